// pree_fp32_stages: the check of a unit's Stages parameter, simulation only (no logic, no ports).
//
// Every pipelined unit (pree_fp32_add, _mul, _sqr, _div, pree_wacc, pree_u64_to_f32) places one
// with its name, Stages, PipeFast and supported range: a Stages value outside Min .. Max stops
// the simulation at time 0 with one line that names the unit. Synthesis sees an empty module.
`default_nettype none

module pree_fp32_stages #(
  parameter Unit     = "unit",
  parameter Stages   = 1,
  parameter PipeFast = 0,
  parameter Min      = 1,
  parameter Max      = 1
) ();

`ifndef SYNTHESIS
  initial begin
    if (Stages < Min || Stages > Max)
      $fatal(1, "%0s: Stages = %0d (PipeFast = %0d), supported %0d .. %0d", Unit, Stages,
             PipeFast, Min, Max);
  end
`endif

endmodule
