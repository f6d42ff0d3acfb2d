// SPDX-License-Identifier: Apache-2.0
// fp32_sqr_fv: the fp32_sqr job's top: pree_fp32_sqr's deep configuration (PipeFast = 1, Stages
// 6: every product in a DSP block with its own registers) against Stages 4 (the same three `*`
// products, H^2, H*L, L^2, with no DSP registers) in one fp32_equiv_miter (formal/lib). Stages 4
// against the paper's Stages 2 (H^2 and H*L by shift and add there) is beyond the solver
// (docs/formal.md).
`default_nettype none

module fp32_sqr_fv (
  input wire        clk_i,
  input wire        valid_i,
  input wire [31:0] a_i,
  input wire [31:0] b_i,
  input wire        sub_i
);

  fp32_equiv_miter #(.Unit("sqr"), .DutStages(6), .DutInRegs(0), .RefStages(4)) u_fast (
    .clk_i(clk_i), .valid_i(valid_i), .a_i(a_i), .b_i(b_i), .sub_i(sub_i));

endmodule

`default_nettype wire
