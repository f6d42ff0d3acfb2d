// SPDX-License-Identifier: Apache-2.0
// MULT18X18D: a simulation model of the part of the ECP5 MULT18X18D primitive that
// rtl/pree_fp32_dsp_mul.v uses under PREE_ECP5_DSP (Yosys's own model rejects registered modes;
// the file is named for the module, so that -y tb/fpga finds it):
// an unsigned 18 x 18 product with optional input registers (A, B) and an optional output
// register, each clocked by CLK0 when its REG_*_CLK is "CLK0" and enabled by the CE pin its
// REG_*_CE names; no pipeline register, no reset, no cascade. Anything else stops the simulation.
// For tests/checks/fpga_dsp_sim.sh only; never synthesised (the FPGA flow takes the primitive
// from the vendor library).
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

  wire [17:0] a = {A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0};
  wire [17:0] b = {B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0};
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

  always @(posedge CLK0) begin
    if (SIGNEDA !== 1'b0 || SIGNEDB !== 1'b0)
      $fatal(1, "MULT18X18D model: signed products are not modelled");
    if (en(REG_INPUTA_CE, ce)) a_q <= a;
    if (en(REG_INPUTB_CE, ce)) b_q <= b;
    if (en(REG_OUTPUT_CE, ce)) p_q <= p_m;
  end

  assign {P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21, P20, P19,
          P18, P17, P16, P15, P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0} = p;

  initial begin
    if ((REG_INPUTA_CLK != "NONE" && REG_INPUTA_CLK != "CLK0") ||
        (REG_INPUTB_CLK != "NONE" && REG_INPUTB_CLK != "CLK0") ||
        (REG_OUTPUT_CLK != "NONE" && REG_OUTPUT_CLK != "CLK0") || REG_PIPELINE_CLK != "NONE" ||
        GSR != "DISABLED")
      $fatal(1, "MULT18X18D model: only CLK0 input and output registers, GSR disabled");
  end

  wire unused = &{1'b0, C0, C1, C2, C3, C4, C5, C6, C7, C8, C9, C10, C11, C12, C13, C14, C15,
                    C16, C17, SOURCEA, SOURCEB, CLK1, CLK2, CLK3, RST0, RST1, RST2, RST3};
endmodule
