// SPDX-License-Identifier: Apache-2.0
// fp32_mul_fv: the fp32_mul job's top (docs/formal.md): pree_fp32_mul's split-product plans
// (Stages 5, 6 and 7, PipeFast = 1's; the four partial products in DSP blocks) each against the
// paper's Stages 2, with the significand product cut out (fp32_cut_miter, formal/lib, one per
// plan; taps.ys cuts and taps each). Stages 8 (seam 4 registered too) and the single-`*` plans
// (1, 3, 4) would need another ghost stage and are left to simulation.
`default_nettype none

module fp32_mul_fv (
  input wire        clk_i,
  input wire        valid_i,
  input wire [31:0] a_i,
  input wire [31:0] b_i
);

  fp32_cut_miter #(.Unit("mul"), .DutStages(5), .CutDelay(2)) u_s5 (
    .clk_i(clk_i), .valid_i(valid_i), .a_i(a_i), .b_i(b_i));
  fp32_cut_miter #(.Unit("mul"), .DutStages(6), .CutDelay(2)) u_s6 (
    .clk_i(clk_i), .valid_i(valid_i), .a_i(a_i), .b_i(b_i));
  fp32_cut_miter #(.Unit("mul"), .DutStages(7), .CutDelay(3)) u_s7 (
    .clk_i(clk_i), .valid_i(valid_i), .a_i(a_i), .b_i(b_i));

endmodule

`default_nettype wire
