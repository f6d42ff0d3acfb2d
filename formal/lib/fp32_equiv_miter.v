// SPDX-License-Identifier: Apache-2.0
// fp32_equiv_miter: formal miter of one pipelined binary32 unit (pree_fp32_add, _mul, _sqr,
// _div): a deep configuration (Stages = DutStages, InRegs = DutInRegs) against a reference
// configuration (Stages = RefStages, no operand registers; by default the paper's, PipeFast = 0),
// fed the same free operands and valid bit at every cycle. The result of the shorter latency passes
// through as many more registers as the latencies differ, after which, from the second cycle on:
//   - the two valid bits are equal;
//   - whenever they are set, the two results are equal, bit for bit.
// Reset (asynchronous, active low) is held in the first cycle only. Every cycle's operands are
// free, so a proof covers every operand pair and every pattern of valid bits.
`default_nettype none

module fp32_equiv_miter #(
  parameter Unit      = "add",   // add, mul, sqr or div
  parameter DutStages = 7,
  parameter DutInRegs = 0,
  parameter RefStages = (Unit == "div") ? 4 : 2        // the paper's configuration
) (
  input wire        clk_i,
  input wire        valid_i,
  input wire [31:0] a_i,
  input wire [31:0] b_i,
  input wire        sub_i
);

  // The shorter of the two latencies is padded with registers up to the longer.
  localparam DUT_LAT   = DutInRegs + DutStages;
  localparam REF_DELAY = (DUT_LAT > RefStages) ? DUT_LAT - RefStages : 0;
  localparam DUT_DELAY = (RefStages > DUT_LAT) ? RefStages - DUT_LAT : 0;

  reg f_init = 1'b1;
  always @(posedge clk_i) f_init <= 1'b0;
  wire rst_ni = !f_init;

  wire        ref_valid, dut_valid;
  wire [31:0] ref_y, dut_y;

  generate
    if (Unit == "add") begin : g_add
      pree_fp32_add #(.Stages(RefStages)) u_ref (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i), .a_i(a_i), .b_i(b_i), .sub_i(sub_i),
        .valid_o(ref_valid), .y_o(ref_y));
      pree_fp32_add #(.Stages(DutStages), .InRegs(DutInRegs)) u_dut (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i), .a_i(a_i), .b_i(b_i), .sub_i(sub_i),
        .valid_o(dut_valid), .y_o(dut_y));
    end else if (Unit == "mul") begin : g_mul
      pree_fp32_mul #(.Stages(RefStages)) u_ref (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i), .a_i(a_i), .b_i(b_i),
        .valid_o(ref_valid), .y_o(ref_y));
      pree_fp32_mul #(.Stages(DutStages), .InRegs(DutInRegs)) u_dut (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i), .a_i(a_i), .b_i(b_i),
        .valid_o(dut_valid), .y_o(dut_y));
    end else if (Unit == "sqr") begin : g_sqr
      pree_fp32_sqr #(.Stages(RefStages)) u_ref (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i), .a_i(a_i),
        .valid_o(ref_valid), .y_o(ref_y));
      pree_fp32_sqr #(.Stages(DutStages), .InRegs(DutInRegs)) u_dut (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i), .a_i(a_i),
        .valid_o(dut_valid), .y_o(dut_y));
    end else begin : g_div
      pree_fp32_div #(.Stages(RefStages)) u_ref (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i), .a_i(a_i), .b_i(b_i),
        .valid_o(ref_valid), .y_o(ref_y));
      pree_fp32_div #(.Stages(DutStages), .InRegs(DutInRegs)) u_dut (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i), .a_i(a_i), .b_i(b_i),
        .valid_o(dut_valid), .y_o(dut_y));
    end
  endgenerate

  // Both results brought to the longer latency (valid bits reset, data loads on valid).
  wire        ref_valid_d, dut_valid_d;
  wire [31:0] ref_y_d, dut_y_d;
  pree_fp32_pipe #(.Width(32), .Regs(REF_DELAY)) u_ref_delay (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(ref_valid), .d_i(ref_y),
    .valid_o(ref_valid_d), .q_o(ref_y_d));
  pree_fp32_pipe #(.Width(32), .Regs(DUT_DELAY)) u_dut_delay (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(dut_valid), .d_i(dut_y),
    .valid_o(dut_valid_d), .q_o(dut_y_d));

  always @* begin
    if (rst_ni) begin
      assert (dut_valid_d == ref_valid_d);
      if (dut_valid_d) assert (dut_y_d == ref_y_d);
    end
  end

  // Covers: a result of each kind leaves the deep unit (a normal number, a subnormal, an
  // infinity, a NaN), so that the proof is not vacuous.
  always @* begin
    if (rst_ni) begin
      cover (dut_valid_d && dut_y_d[30:23] != 8'h00 && dut_y_d[30:23] != 8'hff);
      cover (dut_valid_d && dut_y_d[30:23] == 8'h00 && dut_y_d[22:0] != 0);
      cover (dut_valid_d && dut_y_d[30:0] == 31'h7f800000);
      cover (dut_valid_d && dut_y_d[30:23] == 8'hff && dut_y_d[22:0] != 0);
    end
  end

endmodule

`default_nettype wire
