// pree_fp32_div: IEEE-754 binary32 divider, round to nearest even, 4 pipeline stages,
// fully pipelined (one new division every cycle).
//
// y = a / b. Subnormal inputs and outputs in full, signed zeros, overflow to a signed infinity,
// x / 0 -> signed infinity for finite non-zero x. NaN result (x86-64 SSE rule): a NaN -> a
// quieted; else b NaN -> b quieted; else 0 / 0 or inf / inf -> 0xFFC00000.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// Datapath: both significands are normalised (pree_fp32_unpack), so their quotient lies in
// (1/2, 2). A restoring radix-2 array (pree_fp32_div_steps) produces 26 quotient bits of
// weights 2^0 .. 2^-25: 24 significant bits and a guard bit whichever binade the quotient is in;
// the final remainder (non-zero: inexact) and the last bit form the sticky bit.
// Stage 1: unpack, special cases, exponent difference, STEPS1 quotient bits.
// Stage 2: STEPS2 quotient bits.        Stage 3: STEPS3 quotient bits.
// Stage 4: STEPS4 quotient bits, one-bit normalisation, pree_fp32_round (with the shift into
//          the subnormal range), final mux with the special result.
`default_nettype none

module pree_fp32_div (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam LATENCY = 4;
  // Quotient bits per stage (26 in all); the first and last stages also unpack and round.
  localparam STEPS1 = 5;
  localparam STEPS2 = 8;
  localparam STEPS3 = 8;
  localparam STEPS4 = 26 - STEPS1 - STEPS2 - STEPS3;

  // ---------------------------------------------------------------- stage 1: unpack, first bits
  wire        sign_a, sign_b, zero_a, zero_b, inf_a, inf_b, nan_a, nan_b;
  wire [9:0]  exp_a, exp_b;
  wire [23:0] man_a, man_b;

  pree_fp32_unpack u_unpack_a (
    .x_i (a_i), .sign_o (sign_a), .exp_o (exp_a), .man_o (man_a),
    .zero_o (zero_a), .inf_o (inf_a), .nan_o (nan_a)
  );
  pree_fp32_unpack u_unpack_b (
    .x_i (b_i), .sign_o (sign_b), .exp_o (exp_b), .man_o (man_b),
    .zero_o (zero_b), .inf_o (inf_b), .nan_o (nan_b)
  );

  wire       sign_y = sign_a ^ sign_b;
  wire [9:0] exp_d  = exp_a - exp_b + 10'd127;   // biased exponent of quotient bit 2^0

  // Special result: NaN rule first, then invalid operations, infinities and zeros.
  reg        special_d;
  reg [31:0] special_y_d;
  always @* begin
    special_d   = 1'b1;
    special_y_d = {sign_y, 31'd0};
    if (nan_a)                                       special_y_d = a_i | 32'h0040_0000;
    else if (nan_b)                                  special_y_d = b_i | 32'h0040_0000;
    else if ((zero_a && zero_b) || (inf_a && inf_b)) special_y_d = 32'hFFC0_0000;
    else if (inf_a || zero_b)                        special_y_d = {sign_y, 8'hFF, 23'd0};
    else if (zero_a || inf_b)                        special_y_d = {sign_y, 31'd0};
    else                                             special_d   = 1'b0;
  end

  // The dividend significand seeds the partial remainder (man_a < 2^24 <= 2 * man_b).
  wire [24:0] rem0 = {1'b0, man_a};
  wire [24:0] rem1_d;
  wire [25:0] quo1_d;
  pree_fp32_div_steps #(.Steps(STEPS1)) u_steps1 (
    .rem_i (rem0), .den_i (man_b), .quo_i (26'd0), .rem_o (rem1_d), .quo_o (quo1_d)
  );

  // Valid pipeline: valid_q[k] is the valid bit of the stage-(k+1) registers.
  reg [LATENCY-1:0] valid_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {LATENCY{1'b0}};
    else         valid_q <= {valid_q[LATENCY-2:0], valid_i};
  end

  // Stage k registers carry the partial remainder, quotient, divisor, exponent, sign, special.
  reg [24:0] s1_rem_q, s2_rem_q, s3_rem_q;
  reg [25:0] s1_quo_q, s2_quo_q, s3_quo_q;
  reg [23:0] s1_den_q, s2_den_q, s3_den_q;
  reg [9:0]  s1_exp_q, s2_exp_q, s3_exp_q;
  reg        s1_sign_q, s2_sign_q, s3_sign_q;
  reg        s1_special_q, s2_special_q, s3_special_q;
  reg [31:0] s1_special_y_q, s2_special_y_q, s3_special_y_q;

  always @(posedge clk_i) begin
    if (valid_i) begin
      s1_rem_q       <= rem1_d;
      s1_quo_q       <= quo1_d;
      s1_den_q       <= man_b;
      s1_exp_q       <= exp_d;
      s1_sign_q      <= sign_y;
      s1_special_q   <= special_d;
      s1_special_y_q <= special_y_d;
    end
  end

  // ---------------------------------------------------------------- stage 2
  wire [24:0] rem2_d;
  wire [25:0] quo2_d;
  pree_fp32_div_steps #(.Steps(STEPS2)) u_steps2 (
    .rem_i (s1_rem_q), .den_i (s1_den_q), .quo_i (s1_quo_q), .rem_o (rem2_d), .quo_o (quo2_d)
  );

  always @(posedge clk_i) begin
    if (valid_q[0]) begin
      s2_rem_q       <= rem2_d;
      s2_quo_q       <= quo2_d;
      s2_den_q       <= s1_den_q;
      s2_exp_q       <= s1_exp_q;
      s2_sign_q      <= s1_sign_q;
      s2_special_q   <= s1_special_q;
      s2_special_y_q <= s1_special_y_q;
    end
  end

  // ---------------------------------------------------------------- stage 3
  wire [24:0] rem3_d;
  wire [25:0] quo3_d;
  pree_fp32_div_steps #(.Steps(STEPS3)) u_steps3 (
    .rem_i (s2_rem_q), .den_i (s2_den_q), .quo_i (s2_quo_q), .rem_o (rem3_d), .quo_o (quo3_d)
  );

  always @(posedge clk_i) begin
    if (valid_q[1]) begin
      s3_rem_q       <= rem3_d;
      s3_quo_q       <= quo3_d;
      s3_den_q       <= s2_den_q;
      s3_exp_q       <= s2_exp_q;
      s3_sign_q      <= s2_sign_q;
      s3_special_q   <= s2_special_q;
      s3_special_y_q <= s2_special_y_q;
    end
  end

  // ---------------------------------------------------------------- stage 4: last bits, round
  wire [24:0] rem4;
  wire [25:0] quo4;
  pree_fp32_div_steps #(.Steps(STEPS4)) u_steps4 (
    .rem_i (s3_rem_q), .den_i (s3_den_q), .quo_i (s3_quo_q), .rem_o (rem4), .quo_o (quo4)
  );

  // Quotient in [1, 2): bits 25..2 significant, bit 1 guard; in (1/2, 1): bits 24..1, bit 0.
  wire        top      = quo4[25];
  wire [26:0] norm_man = top ? {quo4[25:1], 2'b00} : {quo4[24:0], 2'b00};
  wire        sticky   = (rem4 != 25'd0) | (top & quo4[0]);
  wire [9:0]  norm_exp = s3_exp_q - {9'd0, ~top};
  wire [31:0] rounded;

  pree_fp32_round #(.Denorm(1)) u_round (
    .sign_i   (s3_sign_q),
    .exp_i    (norm_exp),
    .man_i    (norm_man),
    .sticky_i (sticky),
    .y_o      (rounded)
  );

  reg [31:0] s4_y_q;

  always @(posedge clk_i) begin
    if (valid_q[2]) s4_y_q <= s3_special_q ? s3_special_y_q : rounded;
  end

  assign valid_o = valid_q[LATENCY-1];
  assign y_o     = s4_y_q;

endmodule
