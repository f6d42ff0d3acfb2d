// SPDX-License-Identifier: Apache-2.0
// pree_fp32_dsp_mul: an unsigned AW x BW product between two registers, the shape of one DSP
// multiplier with its own input and output registers. The operands load at a rising edge where
// in_en_i is set, the product of the loaded operands at one where out_en_i is set; p_o is that
// register. The split products of pree_fp32_mul and pree_fp32_sqr (PipeFast = 1) use it where the
// seams before and after a product are both registered, with the valid bits entering those seams
// as the enables, so it holds exactly the registers the seams held.
//   Default: two registers and `*`, which synthesis maps to a DSP block and fabric registers
//   (Yosys 0.70 infers no registers inside an ECP5 MULT18X18D).
//   PREE_ECP5_DSP defined (scripts/fpga_timing.sh): one ECP5 MULT18X18D whose own input and output
//   registers hold them (AW, BW at most 17), so that no route between fabric and multiplier lies
//   inside a stage. tb/fpga/MULT18X18D.v models the primitive for simulation
//   (tests/checks/fpga_dsp_sim.sh runs the multiplier benches through it).
`default_nettype none

module pree_fp32_dsp_mul #(
  parameter AW = 17,
  parameter BW = 17
) (
  input  wire             clk_i,
  input  wire             in_en_i,
  input  wire [AW-1:0]    a_i,
  input  wire [BW-1:0]    b_i,
  input  wire             out_en_i,
  output wire [AW+BW-1:0] p_o
);

`ifdef PREE_ECP5_DSP
  wire [17:0] a = {{(18-AW){1'b0}}, a_i};
  wire [17:0] b = {{(18-BW){1'b0}}, b_i};
  /* verilator lint_off UNUSEDSIGNAL */
  wire [35:0] p;                     // the bits above AW + BW are zero
  /* verilator lint_on UNUSEDSIGNAL */

  MULT18X18D #(
    .REG_INPUTA_CLK ("CLK0"), .REG_INPUTA_CE ("CE0"), .REG_INPUTB_CLK ("CLK0"),
    .REG_INPUTB_CE ("CE0"), .REG_OUTPUT_CLK ("CLK0"), .REG_OUTPUT_CE ("CE1"), .GSR ("DISABLED")
  ) u_dsp (
      .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]),
      .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]),
      .A15(a[15]), .A16(a[16]), .A17(a[17]), .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]),
      .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]),
      .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(b[16]), .B17(b[17]), .C0(1'b0), .C1(1'b0),
      .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0),
      .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0),
      .C17(1'b0), .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0), .CLK0(clk_i),
      .CLK1(1'b0), .CLK2(1'b0), .CLK3(1'b0), .CE0(in_en_i), .CE1(out_en_i), .CE2(1'b0), .CE3(1'b0),
      .RST0(1'b0), .RST1(1'b0), .RST2(1'b0), .RST3(1'b0), .P0(p[0]), .P1(p[1]), .P2(p[2]),
      .P3(p[3]), .P4(p[4]), .P5(p[5]), .P6(p[6]), .P7(p[7]), .P8(p[8]), .P9(p[9]), .P10(p[10]),
      .P11(p[11]), .P12(p[12]), .P13(p[13]), .P14(p[14]), .P15(p[15]), .P16(p[16]), .P17(p[17]),
      .P18(p[18]), .P19(p[19]), .P20(p[20]), .P21(p[21]), .P22(p[22]), .P23(p[23]), .P24(p[24]),
      .P25(p[25]), .P26(p[26]), .P27(p[27]), .P28(p[28]), .P29(p[29]), .P30(p[30]), .P31(p[31]),
      .P32(p[32]), .P33(p[33]), .P34(p[34]), .P35(p[35])
  );
  assign p_o = p[AW+BW-1:0];
`else
  reg [AW-1:0]    a_q;
  reg [BW-1:0]    b_q;
  reg [AW+BW-1:0] p_q;

  always @(posedge clk_i) begin
    if (in_en_i)  {a_q, b_q} <= {a_i, b_i};
    if (out_en_i) p_q <= a_q * b_q;
  end
  assign p_o = p_q;
`endif

endmodule
