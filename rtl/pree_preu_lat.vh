// SPDX-License-Identifier: Apache-2.0
// pree_preu_lat.vh: the PREU's latencies from the parameters of the module that includes it
// (Datapath, PipeFast, AddStages .. WaccStages), resolved here once for pree_preu, pree_top and
// the formal PREU stub (formal/top_hazard/pree_preu_stub.v), so that the three agree on every
// unit's latency and on the plan's. Included inside the module, after its parameters; it brings
// the plan's functions (pree_preu_plan.vh) with it.
`include "pree_preu_plan.vh"

// Each unit's latency: its Stages (0: the unit's default for PipeFast) and its operand registers.
localparam LAT_ADD  = preu_unit_lat(PREU_ADD, PipeFast, AddStages);
localparam LAT_MUL  = preu_unit_lat(PREU_MUL, PipeFast, MulStages);
localparam LAT_SQR  = preu_unit_lat(PREU_SQR, PipeFast, SqrStages);
localparam LAT_DIV  = preu_unit_lat(PREU_DIV, PipeFast, DivStages);
localparam LAT_U2F  = preu_unit_lat(PREU_U2F, PipeFast, U2fStages);
localparam LAT_WACC = preu_unit_lat(PREU_WACC, PipeFast, WaccStages);
// The update and radiance latencies (public to the Verilator benches and hosts).
localparam UPD_LATENCY /*verilator public*/ =
  preu_upd_latency(Datapath, LAT_ADD, LAT_MUL, LAT_SQR, LAT_DIV, LAT_U2F, LAT_WACC);
localparam RAD_LATENCY /*verilator public*/ = preu_rad_latency(LAT_ADD, LAT_MUL, LAT_DIV);
