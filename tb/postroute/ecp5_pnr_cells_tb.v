// SPDX-License-Identifier: Apache-2.0
// ecp5_pnr_cells_tb: the post-route cell models (tb/postroute/, tb/fpga/MULT18X18D.v) against
// Yosys's ECP5 library on random inputs (tests/checks/postroute_cells.sh extracts LUT4, LUT2,
// PFUMX, L6MUX21, CCU2C and TRELLIS_DPR16X4 from it): TRELLIS_COMB's logic LUT and wide-function
// muxes, two CCU2 halves against one CCU2C (with and without INJECT1), four DPRAM LUTs and a
// TRELLIS_RAMW wired and initialised as nextpnr packs a TRELLIS_DPR16X4, and MULT18X18D with
// nextpnr's tied inputs against the product. Prints "PASS", or "FAIL" with the first difference.
`timescale 1ns / 1ps
`default_nettype none

module ecp5_pnr_cells_tb;
  localparam [15:0]  LutInit = 16'h8e3b, Init0 = 16'h96a5, Init1 = 16'h6a3c;
  localparam [63:0]  DprInit = 64'h0123_4567_89ab_cdef;

  reg [3:0]  lut_in;
  reg        m, f1, fxa, fxb;
  reg [7:0]  cin;                       // A0 B0 C0 D0 A1 B1 C1 D1 of the carry
  reg        ci;
  reg [3:0]  wad, rad, di;
  reg        wre, wck;
  reg [17:0] a, b;
  integer    i, errors;

  // The logic LUT and its muxes.
  wire f_ref, f_dut, f5_ref, f5_dut, f6_ref, f6_dut;
  LUT4 #(.INIT(LutInit)) u_lut (.A(lut_in[0]), .B(lut_in[1]), .C(lut_in[2]), .D(lut_in[3]), .Z(f_ref));
  PFUMX u_f5 (.ALUT(f1), .BLUT(f_ref), .C0(m), .Z(f5_ref));
  L6MUX21 u_f6 (.D0(fxa), .D1(fxb), .SD(m), .Z(f6_ref));
  TRELLIS_COMB #(.INITVAL(LutInit), .OFXMUX("F5")) u_k0 (
    .A(lut_in[0]), .B(lut_in[1]), .C(lut_in[2]), .D(lut_in[3]), .M(m), .F1(f1), .FCI(1'b0),
    .FXA(1'b0), .FXB(1'b0), .DI0(1'b0), .DI1(1'b0), .WD(1'b0), .WAD0(1'b0), .WAD1(1'b0),
    .WAD2(1'b0), .WAD3(1'b0), .WRE(1'b0), .WCK(1'b0), .F(f_dut), .FCO(), .OFX(f5_dut));
  TRELLIS_COMB #(.INITVAL(LutInit), .OFXMUX("F6")) u_k1 (
    .A(lut_in[0]), .B(lut_in[1]), .C(lut_in[2]), .D(lut_in[3]), .M(m), .F1(1'b0), .FCI(1'b0),
    .FXA(fxa), .FXB(fxb), .DI0(1'b0), .DI1(1'b0), .WD(1'b0), .WAD0(1'b0), .WAD1(1'b0),
    .WAD2(1'b0), .WAD3(1'b0), .WRE(1'b0), .WCK(1'b0), .F(), .FCO(), .OFX(f6_dut));

  // A CCU2C against two CCU2 halves, with INJECT1 "NO" and "YES".
  wire [2:0] cc_ref [0:1];
  wire [2:0] cc_dut [0:1];
  genvar g;
  generate
    for (g = 0; g < 2; g = g + 1) begin : g_ccu
      localparam Inj = g ? "YES" : "NO";
      wire carry;
      CCU2C #(.INIT0(Init0), .INIT1(Init1), .INJECT1_0(Inj), .INJECT1_1("NO")) u_ref (
        .CIN(ci), .A0(cin[0]), .B0(cin[1]), .C0(cin[2]), .D0(cin[3]), .A1(cin[4]), .B1(cin[5]),
        .C1(cin[6]), .D1(cin[7]), .S0(cc_ref[g][0]), .S1(cc_ref[g][1]), .COUT(cc_ref[g][2]));
      TRELLIS_COMB #(.MODE("CCU2"), .INITVAL(Init0), .CCU2_INJECT1(Inj)) u_lo (
        .A(cin[0]), .B(cin[1]), .C(cin[2]), .D(cin[3]), .M(1'b0), .F1(1'b0), .FCI(ci),
        .FXA(1'b0), .FXB(1'b0), .DI0(1'b0), .DI1(1'b0), .WD(1'b0), .WAD0(1'b0), .WAD1(1'b0),
        .WAD2(1'b0), .WAD3(1'b0), .WRE(1'b0), .WCK(1'b0), .F(cc_dut[g][0]), .FCO(carry), .OFX());
      TRELLIS_COMB #(.MODE("CCU2"), .INITVAL(Init1), .CCU2_INJECT1("NO")) u_hi (
        .A(cin[4]), .B(cin[5]), .C(cin[6]), .D(cin[7]), .M(1'b0), .F1(1'b0), .FCI(carry),
        .FXA(1'b0), .FXB(1'b0), .DI0(1'b0), .DI1(1'b0), .WD(1'b0), .WAD0(1'b0), .WAD1(1'b0),
        .WAD2(1'b0), .WAD3(1'b0), .WRE(1'b0), .WCK(1'b0), .F(cc_dut[g][1]), .FCO(cc_dut[g][2]), .OFX());
    end
  endgenerate

  // nextpnr's packing of a TRELLIS_DPR16X4: LUT i holds bit i, its INITVAL permuted the way the
  // read address reaches the LUT (RAD 0..3 on D, B, C, A); the RAMW takes WAD and DI.
  function [15:0] dpr_lut_init;
    input [63:0] init;
    input integer bit_i;
    integer k;
    begin
      for (k = 0; k < 16; k = k + 1)
        dpr_lut_init[k] = init[4 * {k[0], k[2], k[1], k[3]} + bit_i];
    end
  endfunction

  wire [3:0] do_ref, do_dut;
  wire [3:0] wado, wdo;
  TRELLIS_DPR16X4 #(.INITVAL(DprInit)) u_dpr (.DI(di), .WAD(wad), .WRE(wre), .WCK(wck), .RAD(rad),
                                              .DO(do_ref));
  TRELLIS_RAMW u_ramw (.A0(wad[3]), .B0(wad[1]), .C0(wad[2]), .D0(wad[0]), .A1(di[1]), .B1(di[3]),
                       .C1(di[0]), .D1(di[2]), .WADO0(wado[0]), .WADO1(wado[1]), .WADO2(wado[2]),
                       .WADO3(wado[3]), .WDO0(wdo[0]), .WDO1(wdo[1]), .WDO2(wdo[2]), .WDO3(wdo[3]));
  generate
    for (g = 0; g < 4; g = g + 1) begin : g_dpr
      TRELLIS_COMB #(.MODE("DPRAM"), .INITVAL(dpr_lut_init(DprInit, g))) u_ram (
        .A(rad[3]), .B(rad[1]), .C(rad[2]), .D(rad[0]), .M(1'b0), .F1(1'b0), .FCI(1'b0),
        .FXA(1'b0), .FXB(1'b0), .DI0(1'b0), .DI1(1'b0), .WD(wdo[g]), .WAD0(wado[0]),
        .WAD1(wado[1]), .WAD2(wado[2]), .WAD3(wado[3]), .WRE(wre), .WCK(wck), .F(do_dut[g]),
        .FCO(), .OFX());
    end
  endgenerate

  // MULT18X18D, unregistered, A16, A17 tied low and B17 tied high by their muxes.
  wire [35:0] p;
  wire [17:0] a_eff = {2'b00, a[15:0]}, b_eff = {1'b1, b[16:0]};
  MULT18X18D #(.A16MUX("0"), .A17MUX("0"), .B17MUX("1"), .C0MUX("0")) u_mul (
    .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]),
    .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]),
    .A15(a[15]), .A16(a[16]), .A17(a[17]), .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]),
    .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]),
    .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(b[16]), .B17(b[17]), .C0(1'b1), .C1(1'b0),
    .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0),
    .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0),
    .C17(1'b0), .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0), .CLK0(1'b0),
    .CLK1(1'b0), .CLK2(1'b0), .CLK3(1'b0), .CE0(1'b0), .CE1(1'b0), .CE2(1'b0), .CE3(1'b0),
    .RST0(1'b0), .RST1(1'b0), .RST2(1'b0), .RST3(1'b0), .P0(p[0]), .P1(p[1]), .P2(p[2]),
    .P3(p[3]), .P4(p[4]), .P5(p[5]), .P6(p[6]), .P7(p[7]), .P8(p[8]), .P9(p[9]), .P10(p[10]),
    .P11(p[11]), .P12(p[12]), .P13(p[13]), .P14(p[14]), .P15(p[15]), .P16(p[16]), .P17(p[17]),
    .P18(p[18]), .P19(p[19]), .P20(p[20]), .P21(p[21]), .P22(p[22]), .P23(p[23]), .P24(p[24]),
    .P25(p[25]), .P26(p[26]), .P27(p[27]), .P28(p[28]), .P29(p[29]), .P30(p[30]), .P31(p[31]),
    .P32(p[32]), .P33(p[33]), .P34(p[34]), .P35(p[35]));

  task check;
    input [8*8-1:0] what;
    input [35:0]    got, want;
    if (got !== want) begin
      if (errors == 0) $display("FAIL %0s at vector %0d: %h, expected %h", what, i, got, want);
      errors = errors + 1;
    end
  endtask

  initial begin
    errors = 0;
    wck = 1'b0;
    wre = 1'b0;
    i = $random(errors);   // a fixed seed (errors is 0)
    errors = 0;
    for (i = 0; i < 4000; i = i + 1) begin
      {lut_in, m, f1, fxa, fxb} = $random;
      {cin, ci} = $random;
      {wad, rad, di, wre} = $random;
      a = $random;
      b = $random;
      #1;
      check("LUT", f_dut, f_ref);
      check("F5", f5_dut, f5_ref);
      check("F6", f6_dut, f6_ref);
      check("CCU2", cc_dut[0], cc_ref[0]);
      check("CCU2INJ", cc_dut[1], cc_ref[1]);
      check("DPRAM", do_dut, do_ref);
      check("MULT", p, a_eff * b_eff);
      wck = 1'b1;        // a write (when wre), then read back at the next vector
      #1;
      check("DPRAMWR", do_dut, do_ref);
      wck = 1'b0;
    end
    if (errors == 0) $display("PASS: 4000 random vectors (LUT, F5, F6, CCU2 x2, DPRAM + RAMW, MULT18X18D)");
    else $display("FAIL: %0d differences", errors);
    $finish;
  end
endmodule
