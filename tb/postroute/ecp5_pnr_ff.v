// SPDX-License-Identifier: Apache-2.0
// ecp5_pnr_ff: a simulation model of nextpnr-ecp5's slice flip-flop, TRELLIS_FF, as its routed
// design holds it (docs/fpga_board.md, "Post-route simulation"): D is DI (the slice's LUT) with
// SD "1", M (general routing) with SD "0"; CEMUX "CE", "INV", "1" or "0"; CLKMUX "CLK" or "INV";
// LSR (LSRMUX "LSR" or "INV") loads the REGSET value ("RESET" 0, "SET" 1), at once with SRMODE
// "ASYNC", at the clock edge and before the clock enable with "LSR_OVER_CE". The power-up value
// is the REGSET value (the configuration's global set/reset). Others stop the simulation.
`default_nettype none

module TRELLIS_FF #(
  parameter GSR    = "DISABLED",
  parameter CEMUX  = "1",
  parameter CLKMUX = "CLK",
  parameter LSRMUX = "LSR",
  parameter SRMODE = "LSR_OVER_CE",
  parameter REGSET = "RESET",
  parameter SD     = "0"
) (
  input  wire CLK, LSR, CE, DI, M,
  output reg  Q
);

  localparam SrVal = (REGSET == "SET");

  wire clk = (CLKMUX == "INV") ? ~CLK : CLK;
  wire lsr = (LSRMUX == "INV") ? ~LSR : LSR;
  wire ce  = (CEMUX == "1") ? 1'b1 : (CEMUX == "0") ? 1'b0 : (CEMUX == "INV") ? ~CE : CE;
  wire d   = (SD == "1") ? DI : M;

  initial Q = SrVal;

  generate
    if (SRMODE == "ASYNC") begin : g_async
      always @(posedge clk or posedge lsr)
        if (lsr)     Q <= SrVal;
        else if (ce) Q <= d;
    end else begin : g_sync
      always @(posedge clk)
        if (lsr)     Q <= SrVal;
        else if (ce) Q <= d;
    end
  endgenerate

  // The clock-to-output time of nextpnr's SDF (IOPATH CLK Q); its setup times reach the
  // timing-annotated run as input delays (scripts/postroute_sdf.py).
  specify
    (CLK => Q) = 0;
    (LSR => Q) = 0;
  endspecify

  initial begin
    if ((CEMUX != "CE" && CEMUX != "INV" && CEMUX != "1" && CEMUX != "0") ||
        (CLKMUX != "CLK" && CLKMUX != "INV") || (LSRMUX != "LSR" && LSRMUX != "INV") ||
        (SRMODE != "ASYNC" && SRMODE != "LSR_OVER_CE") || (REGSET != "RESET" && REGSET != "SET") ||
        (SD != "0" && SD != "1") || (GSR != "DISABLED" && GSR != "ENABLED"))
      $fatal(1, "TRELLIS_FF model: a mux or mode setting that is not modelled");
  end
endmodule
