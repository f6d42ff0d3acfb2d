// SPDX-License-Identifier: Apache-2.0
// pree_fp32_denorm_sel: the denormalising shift amount of a result whose binade is picked by
// one bit, combinational (the normalisation stage of the multiplier, squarer and divider).
//
// The result's exponent is exp_lo_i when top_i is 0 and exp_hi_i = exp_lo_i + 1 when top_i is
// 1; exp_i is that normalised exponent, which the caller forms anyway. tiny_o and sh_o are
// pree_fp32_denorm_amt's for it.
// Parameter Both: 1 forms the amount for either binade beside the normalisation and picks one
// by top_i (a shorter path: the deep plans use it where a register follows); 0 forms it once
// from exp_i (fewer LUTs, measured), and exp_lo_i, exp_hi_i are not used.
`default_nettype none

module pree_fp32_denorm_sel #(
  parameter Both = 0
) (
  input  wire       top_i,
  input  wire [9:0] exp_i,
  input  wire [9:0] exp_lo_i,
  input  wire [9:0] exp_hi_i,
  output wire       tiny_o,
  output wire [4:0] sh_o
);

  generate
    if (Both != 0) begin : g_both
      wire       tiny_lo, tiny_hi;
      wire [4:0] sh_lo, sh_hi;
      pree_fp32_denorm_amt u_amt_lo (.exp_i (exp_lo_i), .tiny_o (tiny_lo), .sh_o (sh_lo));
      pree_fp32_denorm_amt u_amt_hi (.exp_i (exp_hi_i), .tiny_o (tiny_hi), .sh_o (sh_hi));
      assign tiny_o = top_i ? tiny_hi : tiny_lo;
      assign sh_o   = top_i ? sh_hi : sh_lo;
      wire unused_exp = ^exp_i;                // the picked amount needs no normalised exponent
    end else begin : g_one
      pree_fp32_denorm_amt u_amt (.exp_i (exp_i), .tiny_o (tiny_o), .sh_o (sh_o));
      wire unused_bin = ^{top_i, exp_lo_i, exp_hi_i};    // one amount, from exp_i
    end
  endgenerate

endmodule
