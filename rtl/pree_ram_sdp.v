// SPDX-License-Identifier: Apache-2.0
// pree_ram_sdp: simple dual-port synchronous RAM (one write port, one read port, one clock),
// written in the shape FPGA tools map to block RAM (Xilinx RAMB18/36 in simple dual-port mode).
//
// Write: on a rising edge with we_i, mem[waddr_i] <= wdata_i.
// Read:  on a rising edge with re_i, rdata_o <= mem[raddr_i] (one cycle of latency). Without
//        re_i, rdata_o holds its value (the block RAM's output-register enable), which lets a
//        stalled pipeline keep a read result in place.
// Read and write of the same address at the same edge return the OLD word (read-first). The
// users in pree_top never depend on this case: their hazard logic keeps an address that is
// being written away from the read port (see docs/pree_top.md, "Pipeline, memories and hazards").
// No reset; the contents are undefined until written.
//
// Parameters: Width data bits, AddrW address bits (depth 2^AddrW).
`default_nettype none

module pree_ram_sdp #(
  parameter Width = 32,
  parameter AddrW = 10
) (
  input  wire             clk_i,
  input  wire             we_i,
  input  wire [AddrW-1:0] waddr_i,
  input  wire [Width-1:0] wdata_i,
  input  wire             re_i,
  input  wire [AddrW-1:0] raddr_i,
  output reg  [Width-1:0] rdata_o
);

  reg [Width-1:0] mem_q [0:(1 << AddrW) - 1];

  always @(posedge clk_i) begin
    if (we_i) mem_q[waddr_i] <= wdata_i;
  end

  always @(posedge clk_i) begin
    if (re_i) rdata_o <= mem_q[raddr_i];
  end

endmodule

`default_nettype wire
