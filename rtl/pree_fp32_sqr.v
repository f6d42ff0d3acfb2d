// pree_fp32_sqr: IEEE-754 binary32 squarer, y = a * a, round to nearest even, 2 pipeline stages.
//
// Bit-identical to pree_fp32_mul with both operands equal, but cheaper:
//  - one operand, so one classifier and no subnormal normalisation: the square of any subnormal
//    (< 2^-126) is below 2^-252, far under half the smallest subnormal, so it is +0;
//  - the significand square uses the symmetry of a square. With m = H * 2^17 + L
//    (H = m[23:17], 7 bits; L = m[16:0], 17 bits):  m^2 = H^2 * 2^34 + H*L * 2^18 + L^2.
//    The cross term H*L is needed once (doubled by the shift) instead of twice; L^2 is one
//    17 x 17 product (one DSP48 on a 7-series FPGA), while H^2 and H*L are written as seven
//    shifted partial products each, so they map to LUT adders instead of a second DSP.
// The result is never negative: -x * -x = +x^2, (-0)^2 = +0, (-inf)^2 = +inf.
// NaN result (x86-64 SSE rule): a NaN -> a quieted (sign and payload kept).
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// Stage 1 (input -> s1 registers): classify, square the significand, double the exponent.
// Stage 2 (s1 -> s2 registers): one-bit normalisation, pree_fp32_round (including the shift
//   into the subnormal range), final mux with the special result.
`default_nettype none

module pree_fp32_sqr (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam LATENCY = 2;

  // ---------------------------------------------------------------- stage 1: classify, square
  wire [7:0]  exp_a   = a_i[30:23];
  wire        exp_low = (exp_a == 8'd0);             // zero or subnormal: the square is +0
  wire        inf_a   = (exp_a == 8'hFF) && (a_i[22:0] == 23'd0);
  wire        nan_a   = (exp_a == 8'hFF) && (a_i[22:0] != 23'd0);

  wire [23:0] man     = {1'b1, a_i[22:0]};           // only used for normal operands
  wire [6:0]  man_hi  = man[23:17];
  wire [16:0] man_lo  = man[16:0];
  reg  [13:0] sq_hi;                                 // H^2
  reg  [23:0] sq_mid;                                // H*L
  integer     i;

  // Shift-and-add over the 7 bits of H (small products: LUT logic rather than a DSP).
  always @* begin
    sq_hi  = 14'd0;
    sq_mid = 24'd0;
    for (i = 0; i < 7; i = i + 1) begin
      sq_hi  = sq_hi  + ({7'd0, man_hi & {7{man_hi[i]}}} << i);
      sq_mid = sq_mid + ({7'd0, man_lo & {17{man_hi[i]}}} << i);
    end
  end
  wire [33:0] sq_lo   = man_lo * man_lo;
  wire [47:0] prod_d  = {sq_hi, 34'd0} + {6'd0, sq_mid, 18'd0} + {14'd0, sq_lo};
  wire [9:0]  exp_d   = {1'b0, exp_a, 1'b0} - 10'd127;   // biased exponent of product bit 46

  wire        special_d   = exp_low | inf_a | nan_a;
  wire [31:0] special_y_d = nan_a ? (a_i | 32'h0040_0000)
                          : inf_a ? 32'h7F80_0000
                          :         32'h0000_0000;

  // Valid pipeline: valid_q[k] is the valid bit of the stage-(k+1) registers.
  reg [LATENCY-1:0] valid_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {LATENCY{1'b0}};
    else         valid_q <= {valid_q[LATENCY-2:0], valid_i};
  end

  reg [47:0] s1_prod_q;
  reg [9:0]  s1_exp_q;
  reg        s1_special_q;
  reg [31:0] s1_special_y_q;

  always @(posedge clk_i) begin
    if (valid_i) begin
      s1_prod_q      <= prod_d;
      s1_exp_q       <= exp_d;
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
    .sign_i   (1'b0),
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
