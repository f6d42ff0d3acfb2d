// SPDX-License-Identifier: Apache-2.0
// pree_fp32_final: the last stage of every binary32 arithmetic unit: round, final mux with the
// special result, output seam.
//
// The exact result in pree_fp32_round's format (sign_i, exp_i, man_i, sticky_i; already
// denormalised where it is tiny, so pree_fp32_round #(.Denorm(0))) is rounded to nearest even;
// when special_i the result is special_y_i instead (pree_fp32_special's decision, carried from
// the unit's first stage). The result passes a pree_fp32_pipe of Regs registers (the unit's
// last seam: 1 in every stage plan of the units, 0 allowed).
`default_nettype none

module pree_fp32_final #(
  parameter Regs = 1
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire        special_i,
  input  wire [31:0] special_y_i,
  input  wire        sign_i,
  input  wire [9:0]  exp_i,
  input  wire [26:0] man_i,
  input  wire        sticky_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  wire [31:0] rounded;

  pree_fp32_round #(.Denorm(0)) u_round (
    .sign_i   (sign_i),
    .exp_i    (exp_i),
    .man_i    (man_i),
    .sticky_i (sticky_i),
    .y_o      (rounded)
  );

  pree_fp32_pipe #(.Width(32), .Regs(Regs)) u_seam (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i),
    .d_i   (special_i ? special_y_i : rounded),
    .valid_o (valid_o), .q_o (y_o)
  );

endmodule
