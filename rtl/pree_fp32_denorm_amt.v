// SPDX-License-Identifier: Apache-2.0
// pree_fp32_denorm_amt: the denormalising shift amount of a result exponent, combinational.
//
// For the biased, two's-complement exponent exp_i (10 bits) of a result in pree_fp32_round's
// format: tiny_o when exp_i <= 0 (below the normal range), and sh_o = 1 - exp_i capped at 31
// (a shift of 27 or more leaves only sticky bits), the right shift of pree_fp32_denorm.
// A separate module so that a deep pipeline can compute it early, for each exponent the
// result may have, and pick one once the significand's binade is known.
`default_nettype none

module pree_fp32_denorm_amt (
  input  wire [9:0] exp_i,
  output wire       tiny_o,
  output wire [4:0] sh_o
);

  wire [10:0] sh_full = 11'd1 - {exp_i[9], exp_i};

  assign tiny_o = exp_i[9] || (exp_i == 10'd0);
  assign sh_o   = (sh_full[10:5] != 6'd0) ? 5'd31 : sh_full[4:0];

endmodule
