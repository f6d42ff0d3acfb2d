// SPDX-License-Identifier: Apache-2.0
// pree_fp32_unpack: the front end of the multiplier and the divider: classify both binary32
// operands, decide the special result, seam, normalise both significands.
//
//   classify and count (pree_fp32_unpack_lz each; pree_fp32_class inside), the special result
//   (pree_fp32_special) under the operation's rule, the result's sign      -> Regs registers
//   normalise (pree_fp32_unpack_norm each): a subnormal significand shifted left until its
//   leading one sits in man[23], its exponent lowered by as much (combinational, after the seam)
// Parameter Div: the operation whose special cases apply.
//   0, a * b:  invalid 0 * inf and inf * 0; infinite when an operand is; zero when an operand is.
//   1, a / b:  invalid 0 / 0 and inf / inf; infinite for inf / x and x / 0; zero for 0 / x and
//              x / inf.
// Outputs (valid_o and all else Regs rising edges after valid_i): keep_o = {special,
// special_y, sign}, carried by the unit to pree_fp32_final; exp_a_o, man_a_o (and b) with
// value man / 2^23 * 2^(exp - 127) for a finite non-zero operand, exp biased and two's
// complement (down to -22 for a subnormal); man zero for a zero, both don't-cares for inf and
// NaN (the special result covers them).
`default_nettype none

module pree_fp32_unpack #(
  parameter Div  = 0,
  parameter Regs = 0
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        valid_o,
  output wire [33:0] keep_o,
  output wire [9:0]  exp_a_o,
  output wire [23:0] man_a_o,
  output wire [9:0]  exp_b_o,
  output wire [23:0] man_b_o
);

  // ---------------------------------------------------------------- classify, count
  wire       zero_a, zero_b, inf_a, inf_b, nan_a, nan_b;
  wire [4:0] lz_a, lz_b;

  pree_fp32_unpack_lz u_lz_a (
    .x_i (a_i[30:0]), .lz_o (lz_a), .zero_o (zero_a), .inf_o (inf_a), .nan_o (nan_a)
  );
  pree_fp32_unpack_lz u_lz_b (
    .x_i (b_i[30:0]), .lz_o (lz_b), .zero_o (zero_b), .inf_o (inf_b), .nan_o (nan_b)
  );

  wire sign_y = a_i[31] ^ b_i[31];

  // The operation's special cases (header); the NaN rule comes first in pree_fp32_special.
  wire invalid = (Div != 0) ? ((zero_a & zero_b) | (inf_a & inf_b))
                            : ((inf_a & zero_b) | (zero_a & inf_b));
  wire inf_y   = (Div != 0) ? (inf_a | zero_b) : (inf_a | inf_b);
  wire zero_y  = (Div != 0) ? (zero_a | inf_b) : (zero_a | zero_b);

  wire        special_d;
  wire [31:0] special_y_d;

  pree_fp32_special u_special (
    .a_i (a_i), .b_i (b_i), .nan_a_i (nan_a), .nan_b_i (nan_b),
    .invalid_i (invalid), .inf_i (inf_y), .zero_i (zero_y), .sign_i (sign_y),
    .special_o (special_d), .y_o (special_y_d)
  );

  wire [30:0] s1_a, s1_b;                       // the operands' magnitudes
  wire [4:0]  s1_lz_a, s1_lz_b;

  pree_fp32_pipe #(.Width(34 + 62 + 10), .Regs(Regs)) u_seam (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i),
    .d_i   ({special_d, special_y_d, sign_y, a_i[30:0], b_i[30:0], lz_a, lz_b}),
    .valid_o (valid_o), .q_o ({keep_o, s1_a, s1_b, s1_lz_a, s1_lz_b})
  );

  // ---------------------------------------------------------------- normalise
  pree_fp32_unpack_norm u_norm_a (
    .x_i (s1_a), .lz_i (s1_lz_a), .exp_o (exp_a_o), .man_o (man_a_o)
  );
  pree_fp32_unpack_norm u_norm_b (
    .x_i (s1_b), .lz_i (s1_lz_b), .exp_o (exp_b_o), .man_o (man_b_o)
  );

endmodule
