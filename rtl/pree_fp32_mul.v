// pree_fp32_mul: IEEE-754 binary32 multiplier, round to nearest even, 2 pipeline stages.
//
// y = a * b. Subnormal inputs and outputs in full, signed zeros, overflow to a signed infinity.
// NaN result (x86-64 SSE rule): a NaN -> a quieted; else b NaN -> b quieted; else
// 0 * inf or inf * 0 -> 0xFFC00000.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// Stage 1 (input -> s1 registers): unpack both operands (a subnormal significand is normalised
//   by its leading-zero count, pree_fp32_unpack), 24 x 24 -> 48-bit significand product,
//   exponent sum; special results decided here and carried beside the datapath.
// Stage 2 (s1 -> s2 registers): the product of two normalised significands lies in [2^46, 2^48),
//   so normalisation is a one-bit select; pree_fp32_round then shifts a tiny result right
//   into the subnormal range and rounds exactly once; final mux with the special result.
`default_nettype none

module pree_fp32_mul (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam LATENCY = 2;

  // ---------------------------------------------------------------- stage 1: unpack, multiply
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

  wire        sign_y = sign_a ^ sign_b;
  wire [47:0] prod_d = man_a * man_b;
  wire [9:0]  exp_d  = exp_a + exp_b - 10'd127;   // biased exponent of product bit 46

  // Special result: NaN rule first, then infinities and zeros.
  reg        special_d;
  reg [31:0] special_y_d;
  always @* begin
    special_d   = 1'b1;
    special_y_d = {sign_y, 31'd0};
    if (nan_a)                                     special_y_d = a_i | 32'h0040_0000;
    else if (nan_b)                                special_y_d = b_i | 32'h0040_0000;
    else if ((inf_a && zero_b) || (zero_a && inf_b)) special_y_d = 32'hFFC0_0000;
    else if (inf_a || inf_b)                       special_y_d = {sign_y, 8'hFF, 23'd0};
    else if (zero_a || zero_b)                     special_y_d = {sign_y, 31'd0};
    else                                           special_d   = 1'b0;
  end

  // Valid pipeline: valid_q[k] is the valid bit of the stage-(k+1) registers.
  reg [LATENCY-1:0] valid_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {LATENCY{1'b0}};
    else         valid_q <= {valid_q[LATENCY-2:0], valid_i};
  end

  reg [47:0] s1_prod_q;
  reg [9:0]  s1_exp_q;
  reg        s1_sign_q;
  reg        s1_special_q;
  reg [31:0] s1_special_y_q;

  always @(posedge clk_i) begin
    if (valid_i) begin
      s1_prod_q      <= prod_d;
      s1_exp_q       <= exp_d;
      s1_sign_q      <= sign_y;
      s1_special_q   <= special_d;
      s1_special_y_q <= special_y_d;
    end
  end

  // ---------------------------------------------------------------- stage 2: normalise, round
  wire        top      = s1_prod_q[47];
  wire [26:0] norm_man = top ? s1_prod_q[47:21] : s1_prod_q[46:20];
  wire        sticky   = top ? (s1_prod_q[20:0] != 21'd0) : (s1_prod_q[19:0] != 20'd0);
  wire [9:0]  norm_exp = s1_exp_q + {9'd0, top};
  wire [31:0] rounded;

  pree_fp32_round #(.Denorm(1)) u_round (
    .sign_i   (s1_sign_q),
    .exp_i    (norm_exp),
    .man_i    (norm_man),
    .sticky_i (sticky),
    .y_o      (rounded)
  );

  reg [31:0] s2_y_q;

  always @(posedge clk_i) begin
    if (valid_q[0]) s2_y_q <= s1_special_q ? s1_special_y_q : rounded;
  end

  assign valid_o = valid_q[LATENCY-1];
  assign y_o     = s2_y_q;

endmodule
