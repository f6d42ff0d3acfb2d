// SPDX-License-Identifier: Apache-2.0
// pree_fp32_entry: the entry of a pipelined unit (pree_fp32_add, _mul, _sqr, _div, pree_wacc,
// pree_u64_to_f32): its operand registers (seam 0, InRegs of them, a wire when 0). Each unit checks
// its own Stages range at elaboration.
//
// Seam 0 is a pree_fp32_pipe whose data loads every cycle (Hold = 0, no clock enable): it is
// there so that a caller's operand select and its fan-out (the deep PREU's mode selects) end in a
// register of the unit's own, and so the caller's valid bit drives no enable net of it.
// InRegs other than 0 or 1 stops elaboration with a module named after the problem.
`default_nettype none

module pree_fp32_entry #(
  parameter InRegs   = 0,
  parameter Width    = 1
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             valid_i,
  input  wire [Width-1:0] d_i,
  output wire             valid_o,
  output wire [Width-1:0] q_o
);

  pree_fp32_pipe #(.Width(Width), .Regs(InRegs), .Hold(0)) u_seam0 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i), .d_i (d_i), .valid_o (valid_o), .q_o (q_o)
  );

  generate
    if (InRegs < 0 || InRegs > 1) begin : g_bad_inregs
      pree_fp32_unit_inregs_is_0_or_1 u_fail ();
    end
  endgenerate

endmodule
