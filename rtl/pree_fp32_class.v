// SPDX-License-Identifier: Apache-2.0
// pree_fp32_class: the one classifier of a binary32 operand, combinational.
//
// Every unit that takes a binary32 operand (pree_fp32_add, _mul, _sqr, _div through
// pree_fp32_unpack_lz, _cmp, pree_wacc's t) classifies it here, once, at its first stage; the
// special cases then travel beside the datapath to the final mux (pree_fp32_special decides the
// special result, pree_fp32_final selects it).
//   exp_zero_o  exponent field 0: a zero or a subnormal (no hidden bit, effective exponent 1)
//   zero_o      +0 or -0
//   inf_o       +inf or -inf
//   nan_o       a NaN, quiet or signalling
// The sign is not looked at: x_i is the operand without its sign bit.
`default_nettype none

module pree_fp32_class (
  input  wire [30:0] x_i,
  output wire        exp_zero_o,
  output wire        zero_o,
  output wire        inf_o,
  output wire        nan_o
);

  wire exp_ones  = (x_i[30:23] == 8'hFF);
  wire frac_zero = (x_i[22:0] == 23'd0);

  assign exp_zero_o = (x_i[30:23] == 8'd0);
  assign zero_o     = exp_zero_o & frac_zero;
  assign inf_o      = exp_ones & frac_zero;
  assign nan_o      = exp_ones & ~frac_zero;

endmodule
