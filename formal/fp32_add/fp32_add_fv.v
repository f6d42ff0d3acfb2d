// SPDX-License-Identifier: Apache-2.0
// fp32_add_fv: the fp32_add job's top: pree_fp32_add's deep configuration (PipeFast = 1,
// Stages 7) against the paper's (Stages 2) in one fp32_equiv_miter (formal/lib).
`default_nettype none

module fp32_add_fv (
  input wire        clk_i,
  input wire        valid_i,
  input wire [31:0] a_i,
  input wire [31:0] b_i,
  input wire        sub_i
);

  fp32_equiv_miter #(.Unit("add"), .DutStages(7), .DutInRegs(0)) u_fast (
    .clk_i(clk_i), .valid_i(valid_i), .a_i(a_i), .b_i(b_i), .sub_i(sub_i));

endmodule

`default_nettype wire
