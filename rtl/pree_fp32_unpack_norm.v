// SPDX-License-Identifier: Apache-2.0
// pree_fp32_unpack_norm: the second half of pree_fp32_unpack, combinational: the normalised
// significand and exponent of a binary32 operand, given its leading-zero count lz_i from
// pree_fp32_unpack_lz.
//
// A subnormal operand is shifted left until its leading one sits in man_o[23]; its exponent
// goes down by the same amount, so exp_o (biased, two's complement, 10 bits) may be zero or
// negative (down to -22). The value of a finite non-zero operand is
// (-1)^sign * man_o / 2^23 * 2^(exp_o - 127). For zero, man_o is zero; for inf and NaN,
// exp_o and man_o are don't-cares of the caller.
`default_nettype none

module pree_fp32_unpack_norm (
  input  wire [30:0] x_i,        // the operand without its sign bit
  input  wire [4:0]  lz_i,
  output wire [9:0]  exp_o,
  output wire [23:0] man_o
);

  wire [7:0] exp_field = x_i[30:23];
  wire       exp_zero  = (exp_field == 8'd0);

  assign man_o = {~exp_zero, x_i[22:0]} << lz_i;
  assign exp_o = exp_zero ? (10'd1 - {5'd0, lz_i}) : {2'b00, exp_field};

endmodule
