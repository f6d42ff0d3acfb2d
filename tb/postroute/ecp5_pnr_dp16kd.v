// SPDX-License-Identifier: Apache-2.0
// ecp5_pnr_dp16kd: a simulation model of the ECP5 block RAM DP16KD in the mode that Yosys's
// synth_ecp5 gives a 36-bit memory (its PDPW16KD mapping) and nextpnr-ecp5 keeps (docs/fpga_board.md,
// "Post-route simulation"): 512 words of 36 bits, {DIB, DIA} written at the rising edge of CLKA
// into word ADA[13:5] while CEA and WEA are high and CSA matches CSDECODE_A, 9-bit byte i where
// ADA[i] is high (i = 0..3); {DOB, DOA} = word ADB[13:5], read at the rising edge of CLKB while
// CEB is high and CSB matches (the word before a write of the same edge), without output
// register (REGMODE "NOREG"), cleared by RSTB (at once with RESETMODE "ASYNC"). Each pin passes
// its <pin>MUX: the pin, "INV" (inverted), "0" or "1" (nextpnr's ties). Initial contents all
// zero. Any other width, mode or mux stops the simulation at its start.
`default_nettype none

module DP16KD (
  input  wire DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9, DIA8, DIA7, DIA6, DIA5,
              DIA4, DIA3, DIA2, DIA1, DIA0,
  input  wire ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4, ADA3, ADA2, ADA1, ADA0,
  input  wire CEA, OCEA, CLKA, WEA, RSTA, CSA2, CSA1, CSA0,
  output wire DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9, DOA8, DOA7, DOA6, DOA5,
              DOA4, DOA3, DOA2, DOA1, DOA0,
  input  wire DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9, DIB8, DIB7, DIB6, DIB5,
              DIB4, DIB3, DIB2, DIB1, DIB0,
  input  wire ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4, ADB3, ADB2, ADB1, ADB0,
  input  wire CEB, OCEB, CLKB, WEB, RSTB, CSB2, CSB1, CSB0,
  output wire DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6, DOB5,
              DOB4, DOB3, DOB2, DOB1, DOB0
);
  parameter DATA_WIDTH_A = 18;
  parameter DATA_WIDTH_B = 18;
  parameter REGMODE_A = "NOREG";
  parameter REGMODE_B = "NOREG";
  parameter RESETMODE = "SYNC";
  parameter ASYNC_RESET_RELEASE = "SYNC";
  parameter CSDECODE_A = "0b000";
  parameter CSDECODE_B = "0b000";
  parameter WRITEMODE_A = "NORMAL";
  parameter WRITEMODE_B = "NORMAL";
  parameter GSR = "ENABLED";
  parameter CLKAMUX = "CLKA", CLKBMUX = "CLKB", CEAMUX = "CEA", CEBMUX = "CEB", OCEAMUX = "OCEA",
  OCEBMUX = "OCEB", WEAMUX = "WEA", WEBMUX = "WEB", RSTAMUX = "RSTA", RSTBMUX = "RSTB",
  CSA0MUX = "CSA0", CSA1MUX = "CSA1", CSA2MUX = "CSA2", CSB0MUX = "CSB0", CSB1MUX = "CSB1",
  CSB2MUX = "CSB2", ADA0MUX = "ADA0", ADA1MUX = "ADA1", ADA2MUX = "ADA2", ADA3MUX = "ADA3",
  ADA4MUX = "ADA4", ADA5MUX = "ADA5", ADA6MUX = "ADA6", ADA7MUX = "ADA7", ADA8MUX = "ADA8",
  ADA9MUX = "ADA9", ADA10MUX = "ADA10", ADA11MUX = "ADA11", ADA12MUX = "ADA12", ADA13MUX = "ADA13",
  ADB0MUX = "ADB0", ADB1MUX = "ADB1", ADB2MUX = "ADB2", ADB3MUX = "ADB3", ADB4MUX = "ADB4",
  ADB5MUX = "ADB5", ADB6MUX = "ADB6", ADB7MUX = "ADB7", ADB8MUX = "ADB8", ADB9MUX = "ADB9",
  ADB10MUX = "ADB10", ADB11MUX = "ADB11", ADB12MUX = "ADB12", ADB13MUX = "ADB13";
  parameter [319:0] INITVAL_00 = 320'h0, INITVAL_01 = 320'h0, INITVAL_02 = 320'h0,
  INITVAL_03 = 320'h0, INITVAL_04 = 320'h0, INITVAL_05 = 320'h0, INITVAL_06 = 320'h0,
  INITVAL_07 = 320'h0, INITVAL_08 = 320'h0, INITVAL_09 = 320'h0, INITVAL_0A = 320'h0,
  INITVAL_0B = 320'h0, INITVAL_0C = 320'h0, INITVAL_0D = 320'h0, INITVAL_0E = 320'h0,
  INITVAL_0F = 320'h0, INITVAL_10 = 320'h0, INITVAL_11 = 320'h0, INITVAL_12 = 320'h0,
  INITVAL_13 = 320'h0, INITVAL_14 = 320'h0, INITVAL_15 = 320'h0, INITVAL_16 = 320'h0,
  INITVAL_17 = 320'h0, INITVAL_18 = 320'h0, INITVAL_19 = 320'h0, INITVAL_1A = 320'h0,
  INITVAL_1B = 320'h0, INITVAL_1C = 320'h0, INITVAL_1D = 320'h0, INITVAL_1E = 320'h0,
  INITVAL_1F = 320'h0, INITVAL_20 = 320'h0, INITVAL_21 = 320'h0, INITVAL_22 = 320'h0,
  INITVAL_23 = 320'h0, INITVAL_24 = 320'h0, INITVAL_25 = 320'h0, INITVAL_26 = 320'h0,
  INITVAL_27 = 320'h0, INITVAL_28 = 320'h0, INITVAL_29 = 320'h0, INITVAL_2A = 320'h0,
  INITVAL_2B = 320'h0, INITVAL_2C = 320'h0, INITVAL_2D = 320'h0, INITVAL_2E = 320'h0,
  INITVAL_2F = 320'h0, INITVAL_30 = 320'h0, INITVAL_31 = 320'h0, INITVAL_32 = 320'h0,
  INITVAL_33 = 320'h0, INITVAL_34 = 320'h0, INITVAL_35 = 320'h0, INITVAL_36 = 320'h0,
  INITVAL_37 = 320'h0, INITVAL_38 = 320'h0, INITVAL_39 = 320'h0, INITVAL_3A = 320'h0,
  INITVAL_3B = 320'h0, INITVAL_3C = 320'h0, INITVAL_3D = 320'h0, INITVAL_3E = 320'h0,
  INITVAL_3F = 320'h0;

  function pin;                         // a pin through its mux
    input [8*5-1:0] mux;
    input           v;
    pin = (mux == "0") ? 1'b0 : (mux == "1") ? 1'b1 : (mux == "INV") ? ~v : v;
  endfunction
  function ok;                          // "0", "1", "INV" or the pin's own name
    input [8*5-1:0] mux;
    input [8*5-1:0] name;
    ok = (mux == "0") || (mux == "1") || (mux == "INV") || (mux == name);
  endfunction

  wire        clka = pin(CLKAMUX, CLKA), clkb = pin(CLKBMUX, CLKB);
  wire        sel_a = ({pin(CSA2MUX, CSA2), pin(CSA1MUX, CSA1), pin(CSA0MUX, CSA0)} == 3'b000);
  wire        sel_b = ({pin(CSB2MUX, CSB2), pin(CSB1MUX, CSB1), pin(CSB0MUX, CSB0)} == 3'b000);
  wire        we    = pin(CEAMUX, CEA) && pin(WEAMUX, WEA) && sel_a;
  wire        re    = pin(CEBMUX, CEB) && sel_b;
  wire        rst   = pin(RSTBMUX, RSTB);
  wire [13:0] ada   = {pin(ADA13MUX, ADA13), pin(ADA12MUX, ADA12), pin(ADA11MUX, ADA11), pin(ADA10MUX, ADA10), pin(ADA9MUX, ADA9), pin(ADA8MUX, ADA8), pin(ADA7MUX, ADA7), pin(ADA6MUX, ADA6), pin(ADA5MUX, ADA5), pin(ADA4MUX, ADA4), pin(ADA3MUX, ADA3), pin(ADA2MUX, ADA2), pin(ADA1MUX, ADA1), pin(ADA0MUX, ADA0)};
  wire [13:0] adb   = {pin(ADB13MUX, ADB13), pin(ADB12MUX, ADB12), pin(ADB11MUX, ADB11), pin(ADB10MUX, ADB10), pin(ADB9MUX, ADB9), pin(ADB8MUX, ADB8), pin(ADB7MUX, ADB7), pin(ADB6MUX, ADB6), pin(ADB5MUX, ADB5), pin(ADB4MUX, ADB4), pin(ADB3MUX, ADB3), pin(ADB2MUX, ADB2), pin(ADB1MUX, ADB1), pin(ADB0MUX, ADB0)};
  wire [35:0] di    = {DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9, DIB8, DIB7, DIB6,
                       DIB5, DIB4, DIB3, DIB2, DIB1, DIB0, DIA17, DIA16, DIA15, DIA14, DIA13, DIA12,
                       DIA11, DIA10, DIA9, DIA8, DIA7, DIA6, DIA5, DIA4, DIA3, DIA2, DIA1, DIA0};

  reg [35:0] mem_q [0:511];
  reg [35:0] do_q;
  integer    w, k;

  initial begin
    for (w = 0; w < 512; w = w + 1) mem_q[w] = 36'd0;
    do_q = 36'd0;
  end

  always @(posedge clka)
    if (we)
      for (k = 0; k < 4; k = k + 1)
        if (ada[k]) mem_q[ada[13:5]][9*k +: 9] <= di[9*k +: 9];

  generate
    if (RESETMODE == "ASYNC") begin : g_arst
      always @(posedge clkb or posedge rst)
        if (rst)     do_q <= 36'd0;
        else if (re) do_q <= mem_q[adb[13:5]];
    end else begin : g_srst
      always @(posedge clkb)
        if (rst)     do_q <= 36'd0;
        else if (re) do_q <= mem_q[adb[13:5]];
    end
  endgenerate

  assign {DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6, DOB5, DOB4,
          DOB3, DOB2, DOB1, DOB0, DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9,
          DOA8, DOA7, DOA6, DOA5, DOA4, DOA3, DOA2, DOA1, DOA0} = do_q;

  // The read's clock-to-output time of nextpnr's SDF (IOPATH CLKB DOx); the inputs' setup times
  // reach the timing-annotated run as input delays (scripts/postroute_sdf.py).
  specify
    (CLKB *> DOA0, DOA1, DOA2, DOA3, DOA4, DOA5, DOA6, DOA7, DOA8, DOA9,
            DOA10, DOA11, DOA12, DOA13, DOA14, DOA15, DOA16, DOA17,
            DOB0, DOB1, DOB2, DOB3, DOB4, DOB5, DOB6, DOB7, DOB8, DOB9, DOB10,
            DOB11, DOB12, DOB13, DOB14, DOB15, DOB16, DOB17) = 0;
  endspecify

  wire [319:0] init_any = INITVAL_00 | INITVAL_01 | INITVAL_02 | INITVAL_03 | INITVAL_04 |
  INITVAL_05 | INITVAL_06 | INITVAL_07 | INITVAL_08 | INITVAL_09 | INITVAL_0A | INITVAL_0B |
  INITVAL_0C | INITVAL_0D | INITVAL_0E | INITVAL_0F | INITVAL_10 | INITVAL_11 | INITVAL_12 |
  INITVAL_13 | INITVAL_14 | INITVAL_15 | INITVAL_16 | INITVAL_17 | INITVAL_18 | INITVAL_19 |
  INITVAL_1A | INITVAL_1B | INITVAL_1C | INITVAL_1D | INITVAL_1E | INITVAL_1F | INITVAL_20 |
  INITVAL_21 | INITVAL_22 | INITVAL_23 | INITVAL_24 | INITVAL_25 | INITVAL_26 | INITVAL_27 |
  INITVAL_28 | INITVAL_29 | INITVAL_2A | INITVAL_2B | INITVAL_2C | INITVAL_2D | INITVAL_2E |
  INITVAL_2F | INITVAL_30 | INITVAL_31 | INITVAL_32 | INITVAL_33 | INITVAL_34 | INITVAL_35 |
  INITVAL_36 | INITVAL_37 | INITVAL_38 | INITVAL_39 | INITVAL_3A | INITVAL_3B | INITVAL_3C |
  INITVAL_3D | INITVAL_3E | INITVAL_3F;
  initial begin
    if (DATA_WIDTH_A != 36 || DATA_WIDTH_B != 36 || REGMODE_A != "NOREG" || REGMODE_B != "NOREG" ||
        CSDECODE_A != "0b000" || CSDECODE_B != "0b000" ||
        (RESETMODE != "ASYNC" && RESETMODE != "SYNC") || init_any != 320'd0)
      $fatal(1, "DP16KD model: only 36-bit words, no output register, CSDECODE 0b000, zero contents");
    if (!ok(CLKAMUX, "CLKA") || !ok(CLKBMUX, "CLKB") || !ok(CEAMUX, "CEA") || !ok(CEBMUX, "CEB") ||
      !ok(OCEAMUX, "OCEA") || !ok(OCEBMUX, "OCEB") || !ok(WEAMUX, "WEA") || !ok(WEBMUX, "WEB") ||
      !ok(RSTAMUX, "RSTA") || !ok(RSTBMUX, "RSTB") || !ok(CSA0MUX, "CSA0") ||
      !ok(CSA1MUX, "CSA1") || !ok(CSA2MUX, "CSA2") || !ok(CSB0MUX, "CSB0") ||
      !ok(CSB1MUX, "CSB1") || !ok(CSB2MUX, "CSB2") || !ok(ADA0MUX, "ADA0") ||
      !ok(ADA1MUX, "ADA1") || !ok(ADA2MUX, "ADA2") || !ok(ADA3MUX, "ADA3") ||
      !ok(ADA4MUX, "ADA4") || !ok(ADA5MUX, "ADA5") || !ok(ADA6MUX, "ADA6") ||
      !ok(ADA7MUX, "ADA7") || !ok(ADA8MUX, "ADA8") || !ok(ADA9MUX, "ADA9") ||
      !ok(ADA10MUX, "ADA10") || !ok(ADA11MUX, "ADA11") || !ok(ADA12MUX, "ADA12") ||
      !ok(ADA13MUX, "ADA13") || !ok(ADB0MUX, "ADB0") || !ok(ADB1MUX, "ADB1") ||
      !ok(ADB2MUX, "ADB2") || !ok(ADB3MUX, "ADB3") || !ok(ADB4MUX, "ADB4") ||
      !ok(ADB5MUX, "ADB5") || !ok(ADB6MUX, "ADB6") || !ok(ADB7MUX, "ADB7") ||
      !ok(ADB8MUX, "ADB8") || !ok(ADB9MUX, "ADB9") || !ok(ADB10MUX, "ADB10") ||
      !ok(ADB11MUX, "ADB11") || !ok(ADB12MUX, "ADB12") || !ok(ADB13MUX, "ADB13"))
      $fatal(1, "DP16KD model: a pin mux other than the pin, \"INV\", \"0\" or \"1\"");
  end

  wire unused = &{1'b0, OCEA, OCEB, RSTA, WEB, pin(OCEAMUX, OCEA), pin(OCEBMUX, OCEB),
                  pin(RSTAMUX, RSTA), pin(WEBMUX, WEB), ada[4], adb[4:0], ASYNC_RESET_RELEASE,
                  WRITEMODE_A, WRITEMODE_B, GSR};
endmodule
