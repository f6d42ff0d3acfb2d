// SPDX-License-Identifier: Apache-2.0
// ecp5_pnr_comb: simulation models of nextpnr-ecp5's packed logic cells, as its routed design
// holds them (docs/fpga_board.md, "Post-route simulation"; ports tied and OFXMUX set by
// scripts/postroute_netlist.py):
//   TRELLIS_COMB  one LUT4 of a slice. MODE "LOGIC": F = INITVAL[{D, C, B, A}]. "CCU2": one half of
//                 a CCU2C: F = LUT4 ^ FCI, FCO = LUT4 ? FCI : LUT2 (LUT2 = INITVAL[{B, A}]), with
//                 CCU2_INJECT1 "YES" the carry-in and LUT2 replaced by 0. "DPRAM": a 16 x 1
//                 distributed RAM read as the LUT (F = RAM[{D, C, B, A}], INITVAL its contents),
//                 written at the rising edge of WCK while WRE is high, RAM[{WAD3..WAD0}] = WD.
//                 "RAMW_BLOCK": the LUT that the slice's RAMW occupies, no function. OFX: the
//                 slice's wide-function multiplexer on this LUT, M ? F1 : F on a slice's first LUT
//                 (OFXMUX "F5"), M ? FXB : FXA on its second ("F6").
//   TRELLIS_RAMW  the slice's write-port fan-out to the DPRAM LUTs: WADO0..3 = A0, B0, C0, D0 and
//                 WDO0..3 = C1, A1, D1, B1 (the only wiring under which nextpnr's packing, which
//                 permutes the read address and INITVAL the same way, stores each word where it
//                 is read back).
// Any other mode or mux setting stops the simulation at its start.
`default_nettype none

module TRELLIS_COMB #(
  parameter        MODE         = "LOGIC",
  parameter [15:0] INITVAL      = 16'h0000,
  parameter        CCU2_INJECT1 = "NO",
  parameter        WREMUX       = "WRE",
  parameter        WCKMUX       = "WCK",
  parameter        OFXMUX       = "F5"
) (
  input  wire A, B, C, D, M, F1, FCI, FXA, FXB, DI0, DI1, WD, WAD0, WAD1, WAD2, WAD3, WRE, WCK,
  output wire F, FCO, OFX
);

  localparam IsCcu2 = (MODE == "CCU2"), IsRam = (MODE == "DPRAM");
  localparam Inject = (CCU2_INJECT1 == "YES");

  reg  [15:0] ram_q = INITVAL;
  wire [3:0]  idx   = {D, C, B, A};
  wire        lut4  = IsRam ? ram_q[idx] : INITVAL[idx];
  wire        lut2  = INITVAL[{B, A}];

  always @(posedge WCK)
    if (IsRam && WRE) ram_q[{WAD3, WAD2, WAD1, WAD0}] <= WD;

  assign F   = (MODE == "RAMW_BLOCK") ? 1'b0 : (IsCcu2 && !Inject) ? lut4 ^ FCI : lut4;
  assign FCO = !IsCcu2 ? 1'b0 : lut4 ? FCI : (!Inject && lut2);
  assign OFX = (OFXMUX == "F5") ? (M ? F1 : F) : (M ? FXB : FXA);

  initial begin
    if (MODE != "LOGIC" && MODE != "CCU2" && MODE != "DPRAM" && MODE != "RAMW_BLOCK")
      $fatal(1, "TRELLIS_COMB model: MODE %0s is not modelled", MODE);
    if ((CCU2_INJECT1 != "YES" && CCU2_INJECT1 != "NO") || WREMUX != "WRE" || WCKMUX != "WCK" ||
        (OFXMUX != "F5" && OFXMUX != "F6"))
      $fatal(1, "TRELLIS_COMB model: CCU2_INJECT1, WREMUX, WCKMUX or OFXMUX not modelled");
  end

  // The paths that nextpnr's SDF times (IOPATH), zero until $sdf_annotate sets them.
  specify
    (A => F) = 0; (B => F) = 0; (C => F) = 0; (D => F) = 0; (FCI => F) = 0; (WCK => F) = 0;
    (A => FCO) = 0; (B => FCO) = 0; (C => FCO) = 0; (D => FCO) = 0; (FCI => FCO) = 0;
    (A => OFX) = 0; (B => OFX) = 0; (C => OFX) = 0; (D => OFX) = 0; (M => OFX) = 0;
    (F1 => OFX) = 0; (FXA => OFX) = 0; (FXB => OFX) = 0;
  endspecify

  wire unused = &{1'b0, DI0, DI1};
endmodule

module TRELLIS_RAMW (
  input  wire A0, B0, C0, D0, A1, B1, C1, D1,
  output wire WADO0, WADO1, WADO2, WADO3, WDO0, WDO1, WDO2, WDO3
);
  assign {WADO3, WADO2, WADO1, WADO0} = {D0, C0, B0, A0};
  assign {WDO3, WDO2, WDO1, WDO0}     = {B1, D1, A1, C1};
endmodule
