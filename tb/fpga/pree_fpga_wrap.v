// SPDX-License-Identifier: Apache-2.0
// pree_fpga_wrap: one arithmetic unit between input and output registers, for place and route
// (scripts/fpga_timing.sh, make fpga-timing; docs/fpga.md).
//
// Every input of the unit comes from a register loaded from the pins and its outputs go to a
// register that drives the pins, so that every path the timing analyser reports between
// registers is a path of the unit (or the one-net hop into or out of it); the pins' own delays
// are outside the clock domain's figure. Unit selects the unit ("add", "mul", "sqr", "div",
// "wacc", "u2f"); PipeFast and Stages are passed on (Stages = 0: the unit's default for
// PipeFast). The 64-bit a and y fields are used in full by wacc (a, y) and u2f (a); the binary32
// units use their low halves, and the unused register bits are removed by synthesis.
`default_nettype none

module pree_fpga_wrap #(
  parameter Unit     = "add",
  parameter PipeFast = 0,
  parameter Stages   = 0
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [63:0] a_i,
  input  wire [31:0] b_i,
  input  wire        sub_i,
  output wire        valid_o,
  output wire [63:0] y_o
);

  // Input registers (the valid bit reset, as in the units).
  reg        valid_q;
  reg [63:0] a_q;
  reg [31:0] b_q;
  reg        sub_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= 1'b0;
    else         valid_q <= valid_i;
  end

  always @(posedge clk_i) begin
    a_q   <= a_i;
    b_q   <= b_i;
    sub_q <= sub_i;
  end

  wire        unit_valid;
  wire [63:0] unit_y;

  generate
    if (Unit == "add") begin : g_add
      if (Stages == 0) begin : g_def
        pree_fp32_add #(.PipeFast(PipeFast)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q[31:0]), .b_i(b_q),
          .sub_i(sub_q), .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end else begin : g_set
        pree_fp32_add #(.PipeFast(PipeFast), .Stages(Stages)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q[31:0]), .b_i(b_q),
          .sub_i(sub_q), .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end
      assign unit_y[63:32] = 32'd0;
    end else if (Unit == "mul") begin : g_mul
      if (Stages == 0) begin : g_def
        pree_fp32_mul #(.PipeFast(PipeFast)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q[31:0]), .b_i(b_q),
          .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end else begin : g_set
        pree_fp32_mul #(.PipeFast(PipeFast), .Stages(Stages)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q[31:0]), .b_i(b_q),
          .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end
      assign unit_y[63:32] = 32'd0;
    end else if (Unit == "sqr") begin : g_sqr
      if (Stages == 0) begin : g_def
        pree_fp32_sqr #(.PipeFast(PipeFast)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q[31:0]),
          .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end else begin : g_set
        pree_fp32_sqr #(.PipeFast(PipeFast), .Stages(Stages)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q[31:0]),
          .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end
      assign unit_y[63:32] = 32'd0;
    end else if (Unit == "div") begin : g_div
      if (Stages == 0) begin : g_def
        pree_fp32_div #(.PipeFast(PipeFast)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q[31:0]), .b_i(b_q),
          .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end else begin : g_set
        pree_fp32_div #(.PipeFast(PipeFast), .Stages(Stages)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q[31:0]), .b_i(b_q),
          .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end
      assign unit_y[63:32] = 32'd0;
    end else if (Unit == "wacc") begin : g_wacc
      if (Stages == 0) begin : g_def
        pree_wacc #(.PipeFast(PipeFast)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q), .t_i(b_q),
          .valid_o(unit_valid), .y_o(unit_y));
      end else begin : g_set
        pree_wacc #(.PipeFast(PipeFast), .Stages(Stages)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q), .t_i(b_q),
          .valid_o(unit_valid), .y_o(unit_y));
      end
    end else begin : g_u2f
      if (Stages == 0) begin : g_def
        pree_u64_to_f32 #(.PipeFast(PipeFast)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q),
          .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end else begin : g_set
        pree_u64_to_f32 #(.PipeFast(PipeFast), .Stages(Stages)) u_unit (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q), .a_i(a_q),
          .valid_o(unit_valid), .y_o(unit_y[31:0]));
      end
      assign unit_y[63:32] = 32'd0;
    end
  endgenerate

  // Output registers.
  reg        valid_out_q;
  reg [63:0] y_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_out_q <= 1'b0;
    else         valid_out_q <= unit_valid;
  end

  always @(posedge clk_i) begin
    y_q <= unit_y;
  end

  assign valid_o = valid_out_q;
  assign y_o     = y_q;

endmodule
