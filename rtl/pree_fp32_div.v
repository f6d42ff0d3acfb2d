// pree_fp32_div: IEEE-754 binary32 divider, round to nearest even, fully pipelined (one new
// division every cycle), Stages pipeline stages (4 by default, the paper's).
//
// y = a / b. Subnormal inputs and outputs in full, signed zeros, overflow to a signed infinity,
// x / 0 -> signed infinity for finite non-zero x. NaN result (x86-64 SSE rule): a NaN -> a
// quieted; else b NaN -> b quieted; else 0 / 0 or inf / inf -> 0xFFC00000.
//
// Parameter Stages (2 .. 8): the latency. 4 matches the paper; 8 halves the logic depth per
// stage for FPGA clock rates. Every configuration is bit-identical and passes the same benches.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY (= Stages) edges later; one operation may enter
// every cycle. y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// Datapath: both significands are normalised (pree_fp32_unpack), so their quotient lies in
// (1/2, 2). A restoring radix-2 array (pree_fp32_div_steps) produces 26 quotient bits of
// weights 2^0 .. 2^-25: 24 significant bits and a guard bit whichever binade the quotient is in;
// the final remainder (non-zero: inexact) and the last bit form the sticky bit.
// Stage 1 also unpacks and decides special results (carried beside the datapath to the final
// mux); the last stage also normalises by one bit and rounds (pree_fp32_round). The quotient
// bits are spread so that the unpack and the rounding each weigh about three division steps:
// stage k ends with BITS_DONE(k) = round(32 k / Stages) - 3 bits (clamped to 0 .. 26), which
// gives 5 / 8 / 8 / 5 bits for Stages = 4 and 1 / 4 / 4 / 4 / 4 / 4 / 4 / 1 for Stages = 8.
`default_nettype none

module pree_fp32_div #(
  parameter Stages = 4
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam LATENCY = Stages;
  localparam QW      = 26;                      // quotient bits
  // Per-stage pipeline word: remainder, quotient, divisor, exponent, sign, special flag and value.
  localparam W       = 25 + QW + 24 + 10 + 1 + 1 + 32;

  // Quotient bits completed at the end of stage s (s = 0 .. Stages).
  function integer bits_done;
    input integer s;
    begin
      bits_done = (s * 32 + Stages / 2) / Stages - 3;
      if (s == 0 || bits_done < 0) bits_done = 0;
      if (s == Stages || bits_done > QW) bits_done = QW;
    end
  endfunction

  // ---------------------------------------------------------------- stage 1 input: unpack
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

  // Valid pipeline: valid_q[k] is the valid bit of the stage-(k+1) registers.
  reg [LATENCY-1:0] valid_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {LATENCY{1'b0}};
    else         valid_q <= {valid_q[LATENCY-2:0], valid_i};
  end

  // word[k] is what stage k+1 works on: word[0] comes from the inputs (the dividend significand
  // seeds the partial remainder: man_a < 2^24 <= 2 * man_b), word[k] is the stage-k register.
  wire [W-1:0] word [0:Stages-1];
  assign word[0] = {{1'b0, man_a}, {QW{1'b0}}, man_b, exp_d, sign_y, special_d, special_y_d};

  genvar k;
  generate
    for (k = 1; k <= Stages; k = k + 1) begin : g_stage
      // Unpack this stage's input word.
      wire [24:0] rem_in  = word[k-1][W-1 -: 25];
      wire [QW-1:0] quo_in = word[k-1][W-26 -: QW];
      wire [23:0] den     = word[k-1][W-26-QW -: 24];
      wire [9:0]  exp_v   = word[k-1][W-50-QW -: 10];
      wire        sign_v  = word[k-1][33];
      wire        spec_v  = word[k-1][32];
      wire [31:0] spec_y  = word[k-1][31:0];
      wire        load    = (k == 1) ? valid_i : valid_q[(k > 1) ? k - 2 : 0];

      wire [24:0]   rem_out;
      wire [QW-1:0] quo_out;
      pree_fp32_div_steps #(.Steps(bits_done(k) - bits_done(k - 1))) u_steps (
        .rem_i (rem_in), .den_i (den), .quo_i (quo_in), .rem_o (rem_out), .quo_o (quo_out)
      );

      if (k < Stages) begin : g_mid
        reg [W-1:0] word_q;
        always @(posedge clk_i) begin
          if (load) word_q <= {rem_out, quo_out, den, exp_v, sign_v, spec_v, spec_y};
        end
        assign word[k] = word_q;
      end else begin : g_last
        // Quotient in [1, 2): bits 25..2 significant, bit 1 guard; in (1/2, 1): bits 24..1, 0.
        wire        top      = quo_out[QW-1];
        wire [26:0] norm_man = top ? {quo_out[25:1], 2'b00} : {quo_out[24:0], 2'b00};
        wire        sticky   = (rem_out != 25'd0) | (top & quo_out[0]);
        wire [9:0]  norm_exp = exp_v - {9'd0, ~top};
        wire [31:0] rounded;

        pree_fp32_round #(.Denorm(1)) u_round (
          .sign_i   (sign_v),
          .exp_i    (norm_exp),
          .man_i    (norm_man),
          .sticky_i (sticky),
          .y_o      (rounded)
        );

        reg [31:0] y_q;
        always @(posedge clk_i) begin
          if (load) y_q <= spec_v ? spec_y : rounded;
        end
        assign y_o = y_q;
      end
    end
  endgenerate

  assign valid_o = valid_q[LATENCY-1];

endmodule
