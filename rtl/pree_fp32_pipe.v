// SPDX-License-Identifier: Apache-2.0
// pree_fp32_pipe: one seam of an arithmetic unit's pipeline: Regs registers in a row, or a wire.
//
// The units (pree_fp32_add, _mul, _sqr, _div, pree_wacc, pree_u64_to_f32) cut their datapath at
// natural seams (unpack, align, add or multiply, normalise, round) and place one of these at
// each seam; the unit's Stages parameter decides, through its stage plan, how many registers
// each seam gets. Regs = 0 is a wire (no clock, no latency); Regs = 1 is a pipeline register;
// Regs > 1 adds retiming registers at the same seam (each one cycle more, same logic).
//
// Each register has a valid bit, always reset (rst_ni, asynchronous, active low), and a data
// word that loads only when the valid bit entering it is set (Hold = 1), so idle cycles do not
// toggle the datapath and the data of an invalid stage is a don't-care that holds its last
// value; with Hold = 0 the data word loads every cycle (no clock enable: for a seam whose valid
// bit would otherwise be a high-fan-out enable, the units' operand registers in the deep PREU).
// valid_o and q_o follow valid_i and d_i exactly Regs rising edges later.
`default_nettype none

module pree_fp32_pipe #(
  parameter Width = 1,
  parameter Regs  = 1,
  parameter Hold  = 1
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             valid_i,
  input  wire [Width-1:0] d_i,
  output wire             valid_o,
  output wire [Width-1:0] q_o
);

  generate
    if (Regs == 0) begin : g_wire
      assign valid_o = valid_i;
      assign q_o     = d_i;
      wire unused_clk = clk_i ^ rst_ni;    // no register at this seam
    end else begin : g_reg
      // valid[r] / data[r] enter register r (r = 0 .. Regs-1); register r drives index r + 1.
      wire             valid [0:Regs] /* verilator split_var */;
      wire [Width-1:0] data  [0:Regs] /* verilator split_var */;
      assign valid[0] = valid_i;
      assign data[0]  = d_i;

      genvar r;
      for (r = 0; r < Regs; r = r + 1) begin : g_stage
        reg             valid_q;
        reg [Width-1:0] data_q;

        always @(posedge clk_i or negedge rst_ni) begin
          if (!rst_ni) valid_q <= 1'b0;
          else         valid_q <= valid[r];
        end

        always @(posedge clk_i) begin
          if (valid[r] || Hold == 0) data_q <= data[r];
        end

        assign valid[r+1] = valid_q;
        assign data[r+1]  = data_q;
      end

      assign valid_o = valid[Regs];
      assign q_o     = data[Regs];
    end
  endgenerate

endmodule
