// SPDX-License-Identifier: Apache-2.0
// pree_fp32_mul_back: the shared back end of the multiplier and the squarer: normalise the
// 48-bit significand product, denormalise, round, select the special result.
//
// Input: prod_i, the exact product of two normalised 24-bit significands (so in
// [2^46, 2^48)), exp_i the biased exponent of its bit 46, and keep_i = {special, special_y,
// sign} carried from the unit's first stage (pree_fp32_special).
//   normalise: the product's top bit selects the binade (a one-bit shift), the sticky bit,
//              the exponent and the denormalising shift amount (pree_fp32_denorm_sel, for
//              both binades when RegsNorm registers follow)            -> RegsNorm registers
//   denormalise, round, final mux (pree_fp32_tail)                     -> RegsDen, RegsOut
// valid_o and y_o follow valid_i RegsNorm + RegsDen + RegsOut rising edges later.
`default_nettype none

module pree_fp32_mul_back #(
  parameter RegsNorm = 0,
  parameter RegsDen  = 0,
  parameter RegsOut  = 1
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [33:0] keep_i,
  input  wire [9:0]  exp_i,
  input  wire [47:0] prod_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  // The amount for both binades, and the mask-formed sticky bit, where registers surround them.
  localparam BOTH = (RegsNorm != 0);

  // ---------------------------------------------------------------- normalise
  wire        top         = prod_i[47];
  wire [26:0] norm_man    = top ? prod_i[47:21] : prod_i[46:20];
  wire        norm_sticky = top ? (prod_i[20:0] != 21'd0) : (prod_i[19:0] != 20'd0);
  wire [9:0]  norm_exp    = exp_i + {9'd0, top};
  wire        norm_tiny;
  wire [4:0]  norm_sh;

  pree_fp32_denorm_sel #(.Both(BOTH)) u_amt (
    .top_i (top), .exp_i (norm_exp), .exp_lo_i (exp_i), .exp_hi_i (exp_i + 10'd1),
    .tiny_o (norm_tiny), .sh_o (norm_sh)
  );

  wire        n_valid;
  wire [33:0] n_keep;
  wire [9:0]  n_exp;
  wire [26:0] n_man;
  wire        n_sticky, n_tiny;
  wire [4:0]  n_sh;

  pree_fp32_pipe #(.Width(34 + 10 + 27 + 1 + 6), .Regs(RegsNorm)) u_seam_norm (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i),
    .d_i   ({keep_i, norm_exp, norm_man, norm_sticky, norm_tiny, norm_sh}),
    .valid_o (n_valid), .q_o ({n_keep, n_exp, n_man, n_sticky, n_tiny, n_sh})
  );

  // ---------------------------------------------------------------- denormalise, round
  pree_fp32_tail #(.MaskSticky(BOTH), .RegsDen(RegsDen), .RegsOut(RegsOut)) u_tail (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (n_valid),
    .keep_i (n_keep), .exp_i (n_exp), .man_i (n_man), .sticky_i (n_sticky),
    .tiny_i (n_tiny), .sh_i (n_sh),
    .valid_o (valid_o), .y_o (y_o)
  );

endmodule
