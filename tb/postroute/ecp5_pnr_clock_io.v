// SPDX-License-Identifier: Apache-2.0
// ecp5_pnr_clock_io: simulation models of the ECP5 clock and pin cells in nextpnr-ecp5's routed
// design (docs/fpga_board.md, "Post-route simulation"):
//   EHXPLLL     CLKOP has an edge for each edge of CLKI, whatever CLKFB_DIV / CLKI_DIV: the
//               simulation counts core clock cycles, so the bench drives the board's clock pin
//               at the core clock (the board top's 25 MHz x PllFbDiv / PllInDiv) and the UART
//               model takes the board top's cycles a bit (its Div); LOCK rises after 16 rising
//               edges. The phase and the VCO are not modelled; feedback other than CLKOP, a
//               disabled CLKOP, PLL reset or standby stop the simulation at its start.
//   DCCA        the global clock buffer: CLKO = CLKI while CE is high.
//   TRELLIS_IO  a pin: DIR "INPUT" drives O from the pad, "OUTPUT" drives the pad from I (IOLOGIC
//               bypassed: DATAMUX "PADDO"); the pad B is one-way, PAD_IN or PAD_OUT
//               (scripts/postroute_netlist.py); a bidirectional pin stops the simulation.
`default_nettype none

module EHXPLLL #(
  parameter CLKI_DIV = 1, parameter CLKFB_DIV = 1, parameter CLKOP_DIV = 8,
  parameter CLKOP_CPHASE = 0, parameter CLKOP_FPHASE = 0, parameter CLKOP_ENABLE = "ENABLED",
  parameter FEEDBK_PATH = "CLKOP", parameter DPHASE_SOURCE = "DISABLED",
  parameter INTFB_WAKE = "DISABLED", parameter PLLRST_ENA = "DISABLED",
  parameter STDBY_ENABLE = "DISABLED", parameter OUTDIVIDER_MUXA = "DIVA",
  parameter OUTDIVIDER_MUXB = "DIVB", parameter OUTDIVIDER_MUXC = "DIVC",
  parameter OUTDIVIDER_MUXD = "DIVD"
) (
  input  wire CLKI, CLKFB, PHASESEL1, PHASESEL0, PHASEDIR, PHASESTEP, PHASELOADREG, STDBY,
              PLLWAKESYNC, RST, ENCLKOP, ENCLKOS, ENCLKOS2, ENCLKOS3,
  output wire CLKOP, CLKOS, CLKOS2, CLKOS3, LOCK, INTLOCK, REFCLK, CLKINTFB
);
  reg [4:0] edges_q = 5'd0;
  always @(posedge CLKI) if (!edges_q[4]) edges_q <= edges_q + 5'd1;

  assign CLKOP    = CLKI;
  assign LOCK     = edges_q[4];
  assign INTLOCK  = edges_q[4];
  assign REFCLK   = CLKI;
  assign {CLKOS, CLKOS2, CLKOS3, CLKINTFB} = 4'd0;

  initial
    if (FEEDBK_PATH != "CLKOP" || CLKOP_ENABLE != "ENABLED" || PLLRST_ENA != "DISABLED" ||
        STDBY_ENABLE != "DISABLED")
      $fatal(1, "EHXPLLL model: only CLKOP with feedback from CLKOP, no reset or standby");

  wire unused = &{1'b0, CLKFB, CLKI_DIV, CLKFB_DIV, PHASESEL1, PHASESEL0, PHASEDIR, PHASESTEP, PHASELOADREG, STDBY,
                  PLLWAKESYNC, RST, ENCLKOP, ENCLKOS, ENCLKOS2, ENCLKOS3, CLKOP_DIV, CLKOP_CPHASE,
                  CLKOP_FPHASE, DPHASE_SOURCE, INTFB_WAKE, OUTDIVIDER_MUXA, OUTDIVIDER_MUXB,
                  OUTDIVIDER_MUXC, OUTDIVIDER_MUXD};
endmodule

module DCCA (
  input  wire CLKI, CE,
  output wire CLKO
);
  assign CLKO = CLKI & CE;
  specify
    (CLKI => CLKO) = 0;
  endspecify
endmodule

module TRELLIS_IO #(
  parameter DIR = "INPUT", parameter DATAMUX_ODDR = "PADDO", parameter DATAMUX_MDDR = "PADDO"
) (
  input  wire PAD_IN, I, T, IOLDO, IOLTO,
  output wire PAD_OUT, O
);
  assign PAD_OUT = I;
  assign O       = (DIR == "INPUT") ? PAD_IN : 1'b0;

  initial
    if ((DIR != "INPUT" && DIR != "OUTPUT") || DATAMUX_ODDR != "PADDO" || DATAMUX_MDDR != "PADDO")
      $fatal(1, "TRELLIS_IO model: only input and output pins without IOLOGIC");

  wire unused = &{1'b0, T, IOLDO, IOLTO};   // PAD_IN: tied low on an output pin
endmodule
