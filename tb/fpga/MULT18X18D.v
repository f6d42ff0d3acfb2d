// SPDX-License-Identifier: Apache-2.0
// MULT18X18D: a simulation model of the part of the ECP5 MULT18X18D primitive that
// rtl/pree_fp32_dsp_mul.v uses under PREE_ECP5_DSP (Yosys's own model rejects registered modes;
// the file is named for the module, so that -y tb/fpga finds it):
// an unsigned 18 x 18 product with optional input registers (A, B) and an optional output
// register, each clocked by CLK0 when its REG_*_CLK is "CLK0" and enabled by the CE pin its
// REG_*_CE names; no pipeline register, no reset, no cascade (SOURCEA, SOURCEB low). The
// post-route netlist (tb/postroute/) also sets <pin>MUX: an A or B input tied to "0" or "1" by
// nextpnr in place of a route (C is not used by the product). Anything else stops the
// simulation. Never synthesised (the FPGA flow takes the primitive from the vendor library).
`default_nettype none

module MULT18X18D (
  input wire A0, A1, A2, A3, A4, A5, A6, A7, A8, A9, A10, A11, A12, A13, A14, A15, A16, A17, B0,
  B1, B2, B3, B4, B5, B6, B7, B8, B9, B10, B11, B12, B13, B14, B15, B16, B17, C0, C1, C2, C3, C4,
  C5, C6, C7, C8, C9, C10, C11, C12, C13, C14, C15, C16, C17, SIGNEDA, SIGNEDB, SOURCEA, SOURCEB,
  CLK0, CLK1, CLK2, CLK3, CE0, CE1, CE2, CE3, RST0, RST1, RST2, RST3,
  output wire P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17, P18,
  P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35
);
  parameter REG_INPUTA_CLK = "NONE";
  parameter REG_INPUTA_CE = "CE0";
  parameter REG_INPUTB_CLK = "NONE";
  parameter REG_INPUTB_CE = "CE0";
  parameter REG_PIPELINE_CLK = "NONE";
  parameter REG_OUTPUT_CLK = "NONE";
  parameter REG_OUTPUT_CE = "CE0";
  parameter GSR = "ENABLED";
  // An input's constant where nextpnr tied it ("0", "1"; else the pin).
  parameter [8*3-1:0] A0MUX = "A0", A1MUX = "A1", A2MUX = "A2", A3MUX = "A3", A4MUX = "A4",
                      A5MUX = "A5", A6MUX = "A6", A7MUX = "A7", A8MUX = "A8", A9MUX = "A9",
                      A10MUX = "A10", A11MUX = "A11", A12MUX = "A12", A13MUX = "A13",
                      A14MUX = "A14", A15MUX = "A15", A16MUX = "A16", A17MUX = "A17";
  parameter [8*3-1:0] B0MUX = "B0", B1MUX = "B1", B2MUX = "B2", B3MUX = "B3", B4MUX = "B4",
                      B5MUX = "B5", B6MUX = "B6", B7MUX = "B7", B8MUX = "B8", B9MUX = "B9",
                      B10MUX = "B10", B11MUX = "B11", B12MUX = "B12", B13MUX = "B13",
                      B14MUX = "B14", B15MUX = "B15", B16MUX = "B16", B17MUX = "B17";
  parameter [8*3-1:0] C0MUX = "C0", C1MUX = "C1", C2MUX = "C2", C3MUX = "C3", C4MUX = "C4",
                      C5MUX = "C5", C6MUX = "C6", C7MUX = "C7", C8MUX = "C8", C9MUX = "C9",
                      C10MUX = "C10", C11MUX = "C11", C12MUX = "C12", C13MUX = "C13",
                      C14MUX = "C14", C15MUX = "C15", C16MUX = "C16", C17MUX = "C17";

  function pin;                         // an input through its <pin>MUX
    input [8*3-1:0] mux;
    input           v;
    pin = (mux == "0") ? 1'b0 : (mux == "1") ? 1'b1 : v;
  endfunction
  function mux_ok;                      // "0", "1" or the pin's own name
    input [8*3-1:0] mux;
    input [8*3-1:0] name;
    mux_ok = (mux == "0") || (mux == "1") || (mux == name);
  endfunction

  wire [17:0] a = {pin(A17MUX, A17), pin(A16MUX, A16), pin(A15MUX, A15), pin(A14MUX, A14),
                   pin(A13MUX, A13), pin(A12MUX, A12), pin(A11MUX, A11), pin(A10MUX, A10),
                   pin(A9MUX, A9), pin(A8MUX, A8), pin(A7MUX, A7), pin(A6MUX, A6), pin(A5MUX, A5),
                   pin(A4MUX, A4), pin(A3MUX, A3), pin(A2MUX, A2), pin(A1MUX, A1), pin(A0MUX, A0)};
  wire [17:0] b = {pin(B17MUX, B17), pin(B16MUX, B16), pin(B15MUX, B15), pin(B14MUX, B14),
                   pin(B13MUX, B13), pin(B12MUX, B12), pin(B11MUX, B11), pin(B10MUX, B10),
                   pin(B9MUX, B9), pin(B8MUX, B8), pin(B7MUX, B7), pin(B6MUX, B6), pin(B5MUX, B5),
                   pin(B4MUX, B4), pin(B3MUX, B3), pin(B2MUX, B2), pin(B1MUX, B1), pin(B0MUX, B0)};
  wire [3:0]  ce = {CE3, CE2, CE1, CE0};

  function en;                          // the CE pin that a register's REG_*_CE names
    input [8*3-1:0] name;
    input [3:0]     pins;
    en = (name == "CE0") ? pins[0] : (name == "CE1") ? pins[1] :
         (name == "CE2") ? pins[2] : pins[3];
  endfunction

  reg  [17:0] a_q, b_q;
  reg  [35:0] p_q;
  wire [17:0] a_m = (REG_INPUTA_CLK == "CLK0") ? a_q : a;
  wire [17:0] b_m = (REG_INPUTB_CLK == "CLK0") ? b_q : b;
  wire [35:0] p_m = a_m * b_m;
  wire [35:0] p   = (REG_OUTPUT_CLK == "CLK0") ? p_q : p_m;

  always @(SIGNEDA or SIGNEDB or SOURCEA or SOURCEB)
    if (SIGNEDA === 1'b1 || SIGNEDB === 1'b1 || SOURCEA === 1'b1 || SOURCEB === 1'b1)
      $fatal(1, "MULT18X18D model: signed products and the shift inputs are not modelled");

  always @(posedge CLK0) begin
    if (en(REG_INPUTA_CE, ce)) a_q <= a;
    if (en(REG_INPUTB_CE, ce)) b_q <= b;
    if (en(REG_OUTPUT_CE, ce)) p_q <= p_m;
  end

  assign {P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21, P20, P19,
          P18, P17, P16, P15, P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0} = p;

  // The product's delays of nextpnr's SDF, zero until $sdf_annotate sets them (the post-route
  // timing-annotated run, docs/fpga_board.md): clock to product (IOPATH CLK0 Pj) where an input
  // or the output is registered, input to product (IOPATH Ai Pj, Bi Pj) where none is. Icarus
  // takes an output's delay from the path of the input that changed last: CLK0 at a registered
  // product's edge, the A or B input of a combinational one.
  specify   // one source a statement: Icarus 11 matches only the first source of a list
    (CLK0 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
             P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A0 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A1 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A2 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A3 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A4 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A5 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A6 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A7 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A8 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A9 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A10 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A11 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A12 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A13 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A14 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A15 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A16 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (A17 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B0 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B1 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B2 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B3 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B4 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B5 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B6 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B7 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B8 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B9 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
           P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B10 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B11 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B12 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B13 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B14 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B15 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B16 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
    (B17 *> P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
            P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35) = 0;
  endspecify

  initial begin
    if ((REG_INPUTA_CLK != "NONE" && REG_INPUTA_CLK != "CLK0") ||
        (REG_INPUTB_CLK != "NONE" && REG_INPUTB_CLK != "CLK0") ||
        (REG_OUTPUT_CLK != "NONE" && REG_OUTPUT_CLK != "CLK0") || REG_PIPELINE_CLK != "NONE" ||
        (GSR != "DISABLED" && (REG_INPUTA_CLK != "NONE" || REG_INPUTB_CLK != "NONE" ||
                               REG_OUTPUT_CLK != "NONE")))
      $fatal(1, "MULT18X18D model: only CLK0 input and output registers, GSR disabled");
    if (!mux_ok(A0MUX, "A0") || !mux_ok(A1MUX, "A1") || !mux_ok(A2MUX, "A2") || !mux_ok(A3MUX, "A3") ||
        !mux_ok(A4MUX, "A4") || !mux_ok(A5MUX, "A5") || !mux_ok(A6MUX, "A6") || !mux_ok(A7MUX, "A7") ||
        !mux_ok(A8MUX, "A8") || !mux_ok(A9MUX, "A9") || !mux_ok(A10MUX, "A10") ||
        !mux_ok(A11MUX, "A11") || !mux_ok(A12MUX, "A12") || !mux_ok(A13MUX, "A13") ||
        !mux_ok(A14MUX, "A14") || !mux_ok(A15MUX, "A15") || !mux_ok(A16MUX, "A16") ||
        !mux_ok(A17MUX, "A17") || !mux_ok(B0MUX, "B0") || !mux_ok(B1MUX, "B1") ||
        !mux_ok(B2MUX, "B2") || !mux_ok(B3MUX, "B3") || !mux_ok(B4MUX, "B4") || !mux_ok(B5MUX, "B5") ||
        !mux_ok(B6MUX, "B6") || !mux_ok(B7MUX, "B7") || !mux_ok(B8MUX, "B8") || !mux_ok(B9MUX, "B9") ||
        !mux_ok(B10MUX, "B10") || !mux_ok(B11MUX, "B11") || !mux_ok(B12MUX, "B12") ||
        !mux_ok(B13MUX, "B13") || !mux_ok(B14MUX, "B14") || !mux_ok(B15MUX, "B15") ||
        !mux_ok(B16MUX, "B16") || !mux_ok(B17MUX, "B17"))
      $fatal(1, "MULT18X18D model: an A or B input mux other than \"0\", \"1\" or the pin");
    if (!mux_ok(C0MUX, "C0") || !mux_ok(C1MUX, "C1") || !mux_ok(C2MUX, "C2") || !mux_ok(C3MUX, "C3")
        || !mux_ok(C4MUX, "C4") || !mux_ok(C5MUX, "C5") || !mux_ok(C6MUX, "C6") ||
        !mux_ok(C7MUX, "C7") || !mux_ok(C8MUX, "C8") || !mux_ok(C9MUX, "C9") ||
        !mux_ok(C10MUX, "C10") || !mux_ok(C11MUX, "C11") || !mux_ok(C12MUX, "C12") ||
        !mux_ok(C13MUX, "C13") || !mux_ok(C14MUX, "C14") || !mux_ok(C15MUX, "C15") ||
        !mux_ok(C16MUX, "C16") || !mux_ok(C17MUX, "C17"))
      $fatal(1, "MULT18X18D model: a C input mux other than \"0\", \"1\" or the pin");
  end

  wire unused = &{1'b0, C0, C1, C2, C3, C4, C5, C6, C7, C8, C9, C10, C11, C12, C13, C14, C15,
                    C16, C17, SOURCEA, SOURCEB, CLK1, CLK2, CLK3, RST0, RST1, RST2, RST3};
endmodule
