// pree_fp32_entry: the entry of a pipelined unit (pree_fp32_add, _mul, _sqr, _div, pree_wacc,
// pree_u64_to_f32): its operand registers (seam 0, InRegs of them, a wire when 0) and the check of
// its parameters.
//
// Seam 0 is a pree_fp32_pipe whose data loads every cycle (Hold = 0, no clock enable): it is
// there so that a caller's operand select and its fan-out (the deep PREU's mode selects) end in a
// register of the unit's own, and so the caller's valid bit drives no enable net of it.
// The check, simulation only: a Stages value outside Min .. Max, or InRegs other than 0 or 1,
// stops the simulation at time 0 with one line that names the unit (Unit).
`default_nettype none

module pree_fp32_entry #(
  parameter Unit     = "unit",
  parameter Stages   = 1,
  parameter InRegs   = 0,
  parameter PipeFast = 0,
  parameter Min      = 1,
  parameter Max      = 1,
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

`ifndef SYNTHESIS
  initial begin
    if (Stages < Min || Stages > Max)
      $fatal(1, "%0s: Stages = %0d (PipeFast = %0d), supported %0d .. %0d", Unit, Stages,
             PipeFast, Min, Max);
    if (InRegs < 0 || InRegs > 1)
      $fatal(1, "%0s: InRegs = %0d, supported 0 .. 1", Unit, InRegs);
  end
`endif

endmodule
