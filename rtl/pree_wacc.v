// pree_wacc: the stable datapath's wide accumulator add, y = A + t, truncating, 2 pipeline stages.
//
// Bit-exact with wide_add() of model/wide_acc.h. A wide word (64 bits) is e = bits 63..56, an
// 8-bit exponent biased as binary32's, and M = bits 55..0, a 56-bit significand with its leading
// bit stored: value M * 2^(max(e, 1) - 182); e = 255 is +infinity (M = 0) or NaN (M != 0).
// t is binary32. A binary32 significand {hidden, fraction} placed in M[55:32] has the same
// exponent scale, so the two operands align by their effective exponents max(e, 1) alone.
//
// Special cases, in the model's priority order:
//   A NaN               -> A
//   t NaN               -> WIDE_NAN (0xFF40000000000000)
//   A +infinity         -> A
//   t negative (not NaN, -0 and -inf included) -> A unchanged (a dropped term)
//   t +infinity         -> WIDE_MAX (0xFEFFFFFFFFFFFFFF)
// Otherwise the operand with the smaller effective exponent is shifted right by the difference
// (bits shifted out are dropped; a shift of 56 or more gives 0), the significands are added, a
// carry out of bit 55 shifts the sum right by one (dropping its low bit) and raises the
// exponent, an exponent reaching 255 saturates to WIDE_MAX, and the exponent field is written
// as 0 when the sum's bit 55 is 0. Every input word is handled as the model handles it,
// including words whose M[55] disagrees with their e field.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// Stage 1 (input -> s1 registers): classify; the special results are carried as two flags
//   (NaN, WIDE_MAX) and a pass flag; for "pass" (the result is A) the datapath carries A itself:
//   the big operand is M_A, the small one forced to 0 and the exponent is A's raw e field, so
//   no 64-bit special word is registered. Otherwise pick the operand with the larger effective
//   exponent and align the other.
// Stage 2 (s1 -> s2 registers): 57-bit add, carry-out normalisation, saturation, exponent field,
//   final mux.
`default_nettype none

module pree_wacc (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [63:0] a_i,
  input  wire [31:0] t_i,
  output wire        valid_o,
  output wire [63:0] y_o
);

  localparam LATENCY = 2;
  localparam [63:0] WIDE_NAN = 64'hFF40_0000_0000_0000;
  localparam [63:0] WIDE_MAX = 64'hFEFF_FFFF_FFFF_FFFF;

  // ---------------------------------------------------------------- stage 1: classify, align
  wire [7:0]  exp_a  = a_i[63:56];
  wire [55:0] man_a  = a_i[55:0];
  wire [7:0]  exp_t  = t_i[30:23];
  wire        sign_t = t_i[31];
  wire        nan_a  = (exp_a == 8'hFF) && (man_a != 56'd0);
  wire        inf_a  = (exp_a == 8'hFF) && (man_a == 56'd0);
  wire        nan_t  = (exp_t == 8'hFF) && (t_i[22:0] != 23'd0);
  wire        inf_t  = (exp_t == 8'hFF) && (t_i[22:0] == 23'd0);

  // Special results (priority as in wide_add): pass = the result is A.
  wire pass_d = nan_a | (~nan_t & (inf_a | sign_t));
  wire nan_d  = ~nan_a & nan_t;
  wire max_d  = ~nan_a & ~nan_t & ~inf_a & ~sign_t & inf_t;

  // Effective exponents and significands; t's significand sits in M[55:32].
  wire [7:0]  exp_a1 = (exp_a == 8'd0) ? 8'd1 : exp_a;
  wire [7:0]  exp_t1 = (exp_t == 8'd0) ? 8'd1 : exp_t;
  wire [55:0] man_t  = {exp_t != 8'd0, t_i[22:0], 32'd0};

  // The operand with the larger effective exponent is "big"; on a tie, A. For pass, A is big.
  wire        swap     = (exp_t1 > exp_a1) & ~pass_d;
  wire [7:0]  diff     = swap ? (exp_t1 - exp_a1) : (exp_a1 - exp_t1);
  wire [55:0] man_big  = swap ? man_t : man_a;
  wire [55:0] man_sml  = swap ? man_a : man_t;
  wire [7:0]  exp_big  = pass_d ? exp_a : (swap ? exp_t1 : exp_a1);

  // Truncating alignment: a shift of 56 or more (or pass) leaves nothing of the small operand.
  wire        sml_gone = pass_d | (diff >= 8'd56);
  wire [55:0] aligned  = sml_gone ? 56'd0 : (man_sml >> diff[5:0]);

  // Valid pipeline: valid_q[k] is the valid bit of the stage-(k+1) registers.
  reg [LATENCY-1:0] valid_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {LATENCY{1'b0}};
    else         valid_q <= {valid_q[LATENCY-2:0], valid_i};
  end

  reg [55:0] s1_big_q;
  reg [55:0] s1_sml_q;
  reg [7:0]  s1_exp_q;
  reg        s1_pass_q;
  reg        s1_nan_q;
  reg        s1_max_q;

  always @(posedge clk_i) begin
    if (valid_i) begin
      s1_big_q  <= man_big;
      s1_sml_q  <= aligned;
      s1_exp_q  <= exp_big;
      s1_pass_q <= pass_d;
      s1_nan_q  <= nan_d;
      s1_max_q  <= max_d;
    end
  end

  // ---------------------------------------------------------------- stage 2: add, normalise
  wire [56:0] sum   = {1'b0, s1_big_q} + {1'b0, s1_sml_q};
  wire        carry = sum[56];
  wire [55:0] man_s = carry ? sum[56:1] : sum[55:0];    // truncating: sum[0] is dropped
  wire [8:0]  exp_s = {1'b0, s1_exp_q} + {8'd0, carry};
  // Without pass the exponent is at most 254, so it reaches 255 only by a carry.
  wire        sat   = (exp_s >= 9'd255);

  wire [63:0] y_d = s1_nan_q           ? WIDE_NAN
                  : s1_pass_q          ? {s1_exp_q, s1_big_q}
                  : (s1_max_q | sat)   ? WIDE_MAX
                  :                      {man_s[55] ? exp_s[7:0] : 8'd0, man_s};

  reg [63:0] s2_y_q;

  always @(posedge clk_i) begin
    if (valid_q[0]) s2_y_q <= y_d;
  end

  assign valid_o = valid_q[LATENCY-1];
  assign y_o     = s2_y_q;

endmodule
