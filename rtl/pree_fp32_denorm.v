// SPDX-License-Identifier: Apache-2.0
// pree_fp32_denorm: the denormalising right shift in front of rounding, combinational.
//
// The first half of pree_fp32_round #(.Denorm(1)), split out so that a deep pipeline can place
// registers between the shift amount, the shift and the rounding (pree_fp32_round
// #(.Denorm(0)) then finishes the job with the same result). Significand and sticky bit in
// pree_fp32_round's format: the exact result (man_i + sticky) / 2^26 * 2^(exp - 127), man_i[26]
// the leading one. tiny_i and sh_i come from pree_fp32_denorm_amt for the result's exponent:
// when tiny_i (exp <= 0) the result lies below the normal range, and man_o is man_i shifted
// right by sh_i (1 - exp capped at 31, where every bit is sticky) with the bits shifted out
// ORed into sticky_o, so that the later rounding happens once, on the subnormal grid. Otherwise
// man_o and sticky_o are the inputs. The exponent itself passes beside this module unchanged:
// after a shift man_o[26] is 0, which pree_fp32_round packs with exponent field 0 and never
// takes as an overflow.
// Parameter MaskSticky: 0 forms the sticky bit from the low word of a 59-bit shift (fewer LUTs
// after Yosys mapping, measured); 1 from a mask of the low sh_i bits beside the shifter, a
// shorter path on ECP5 (measured), which the deep pipelines use.
`default_nettype none

module pree_fp32_denorm #(
  parameter MaskSticky = 0
) (
  input  wire        tiny_i,
  input  wire [4:0]  sh_i,
  input  wire [26:0] man_i,
  input  wire        sticky_i,
  output wire [26:0] man_o,
  output wire        sticky_o
);

  wire [26:0] shifted;
  wire        lost;

  generate
    if (MaskSticky != 0) begin : g_mask
      wire [26:0] dropped = ~(27'h7FF_FFFF << sh_i);     // the low sh_i bits (all for >= 27)
      assign shifted = man_i >> sh_i;
      assign lost    = ((man_i & dropped) != 27'd0);
    end else begin : g_shift
      wire [58:0] wide = {man_i, 32'd0} >> sh_i;
      assign shifted = wide[58:32];
      assign lost    = (wide[31:0] != 32'd0);
    end
  endgenerate

  assign man_o    = tiny_i ? shifted : man_i;
  assign sticky_o = sticky_i | (tiny_i & lost);

endmodule
