// SPDX-License-Identifier: Apache-2.0
// pree_fp32_unpack_lz: the first half of pree_fp32_unpack, combinational: classify a binary32
// operand (pree_fp32_class) and count the leading zeros that normalise its significand.
//
// lz_o is the leading-zero count of {hidden bit, fraction} (0 for a normal operand, 1 .. 23
// for a subnormal, 24 for zero). pree_fp32_unpack_norm finishes the unpacking from x_i and
// lz_o; the two are separate modules so that a deep pipeline can put a register between them.
`default_nettype none

module pree_fp32_unpack_lz (
  input  wire [30:0] x_i,        // the operand without its sign bit
  output wire [4:0]  lz_o,
  output wire        zero_o,
  output wire        inf_o,
  output wire        nan_o
);

  wire exp_zero;

  pree_fp32_class u_class (
    .x_i (x_i), .exp_zero_o (exp_zero), .zero_o (zero_o), .inf_o (inf_o), .nan_o (nan_o)
  );

  pree_fp32_lzc #(.Width(24), .CntWidth(5)) u_lzc (
    .x_i   ({~exp_zero, x_i[22:0]}),
    .cnt_o (lz_o)
  );

endmodule
