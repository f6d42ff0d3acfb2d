// SPDX-License-Identifier: Apache-2.0
// pree_fp32_tail: the last two seams of the multiplier, squarer and divider: denormalise, then
// round and select the special result.
//
// Input: a normalised result in pree_fp32_round's format (exp_i, man_i with its leading one in
// man_i[26], sticky_i) and its denormalising shift amount (tiny_i, sh_i from
// pree_fp32_denorm_amt or pree_fp32_denorm_sel), beside it keep_i = {special, special_y, sign}
// carried from the unit's first stage.
//   denormalise: a tiny result shifted right into the subnormal range (pree_fp32_denorm,
//                MaskSticky as the unit's plan chooses)                  -> RegsDen registers
//   round, final mux (pree_fp32_final)                                   -> RegsOut registers
// valid_o and y_o follow valid_i RegsDen + RegsOut rising edges later.
`default_nettype none

module pree_fp32_tail #(
  parameter MaskSticky = 0,
  parameter RegsDen    = 0,
  parameter RegsOut    = 1
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [33:0] keep_i,
  input  wire [9:0]  exp_i,
  input  wire [26:0] man_i,
  input  wire        sticky_i,
  input  wire        tiny_i,
  input  wire [4:0]  sh_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  // ---------------------------------------------------------------- denormalise
  wire [26:0] den_man;
  wire        den_sticky;

  pree_fp32_denorm #(.MaskSticky(MaskSticky)) u_denorm (
    .tiny_i (tiny_i), .sh_i (sh_i), .man_i (man_i), .sticky_i (sticky_i),
    .man_o (den_man), .sticky_o (den_sticky)
  );

  wire        d_valid;
  wire [33:0] d_keep;
  wire [9:0]  d_exp;
  wire [26:0] d_man;
  wire        d_sticky;

  pree_fp32_pipe #(.Width(34 + 10 + 27 + 1), .Regs(RegsDen)) u_seam_den (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i),
    .d_i   ({keep_i, exp_i, den_man, den_sticky}),
    .valid_o (d_valid), .q_o ({d_keep, d_exp, d_man, d_sticky})
  );

  // ---------------------------------------------------------------- round, final mux
  pree_fp32_final #(.Regs(RegsOut)) u_final (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (d_valid),
    .special_i (d_keep[33]), .special_y_i (d_keep[32:1]), .sign_i (d_keep[0]),
    .exp_i (d_exp), .man_i (d_man), .sticky_i (d_sticky),
    .valid_o (valid_o), .y_o (y_o)
  );

endmodule
