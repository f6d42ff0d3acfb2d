// SPDX-License-Identifier: Apache-2.0
// pree_fp32_cmp: IEEE-754 binary32 comparator, combinational (latency 0).
//
// lt_o = a < b, le_o = a <= b, eq_o = a == b, with IEEE ordering: -0 == +0, subnormals ordered
// by value, infinities at the ends. When either operand is a NaN (quiet or signalling) the pair
// is unordered: unordered_o = 1 and lt_o, le_o, eq_o are all 0. No exceptions are signalled.
// Method: binary32 magnitudes order like unsigned integers of bits [30:0], so the comparison is
// one 31-bit magnitude compare plus sign logic.
`default_nettype none

module pree_fp32_cmp (
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        lt_o,
  output wire        le_o,
  output wire        eq_o,
  output wire        unordered_o
);

  wire expz_a_unused, expz_b_unused, inf_a_unused, inf_b_unused;
  wire zero_a, zero_b, nan_a, nan_b;

  pree_fp32_class u_class_a (
    .x_i (a_i[30:0]), .exp_zero_o (expz_a_unused), .zero_o (zero_a), .inf_o (inf_a_unused),
    .nan_o (nan_a)
  );
  pree_fp32_class u_class_b (
    .x_i (b_i[30:0]), .exp_zero_o (expz_b_unused), .zero_o (zero_b), .inf_o (inf_b_unused),
    .nan_o (nan_b)
  );

  wire both_zero = zero_a & zero_b;
  wire mag_lt    = (a_i[30:0] < b_i[30:0]);
  wire mag_eq    = (a_i[30:0] == b_i[30:0]);
  wire sign_a    = a_i[31];
  wire sign_b    = b_i[31];

  // Ordered comparison of two non-NaN values.
  wire same_sign = (sign_a == sign_b);
  wire eq_num    = both_zero | (same_sign & mag_eq);
  wire lt_num    = same_sign ? (sign_a ? (~mag_lt & ~mag_eq) : mag_lt)   // both negative: larger
                             : (sign_a & ~both_zero);                    // magnitude is smaller
  wire ordered   = ~(nan_a | nan_b);

  assign unordered_o = ~ordered;
  assign eq_o        = ordered & eq_num;
  assign lt_o        = ordered & lt_num;
  assign le_o        = ordered & (lt_num | eq_num);

endmodule
