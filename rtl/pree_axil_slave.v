// SPDX-License-Identifier: Apache-2.0
// pree_axil_slave: AXI4-Lite slave front end that turns the five channels into a simple
// register bus: one write strobe and one read strobe, each a single cycle.
//
// Write: AWREADY and WREADY rise together in the cycle in which both AWVALID and WVALID are high
// and no write response is pending (AXI4 lets a slave wait for both); in that cycle wr_o pulses
// with wr_addr_o, wr_data_o and wr_strb_o, and BVALID (OKAY) follows on the next edge, held until
// BREADY.
// Read: ARREADY is high while no read response is pending; in the cycle of the AR handshake rd_o
// pulses with rd_addr_o and rd_data_i (combinational from rd_addr_o in the parent) is captured
// into RDATA; RVALID (OKAY) follows on the next edge, held until RREADY.
// One transaction of each kind in flight: a new one is taken in the cycle after B/R completes.
// Nothing is taken while rst_ni is low (AWREADY, WREADY and ARREADY low), so that a request made
// while a synchronised reset is still being released is taken, and answered, once it ends.
// Every response is OKAY; addresses are byte addresses, the low two bits ignored.
// Parameters: AddrW address bits.
`default_nettype none

module pree_axil_slave #(
  parameter AddrW = 12
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  // AXI4-Lite.
  input  wire [AddrW-1:0] awaddr_i,
  input  wire             awvalid_i,
  output wire             awready_o,
  input  wire [31:0]      wdata_i,
  input  wire [3:0]       wstrb_i,
  input  wire             wvalid_i,
  output wire             wready_o,
  output wire [1:0]       bresp_o,
  output wire             bvalid_o,
  input  wire             bready_i,
  input  wire [AddrW-1:0] araddr_i,
  input  wire             arvalid_i,
  output wire             arready_o,
  output wire [31:0]      rdata_o,
  output wire [1:0]       rresp_o,
  output wire             rvalid_o,
  input  wire             rready_i,
  // Register bus.
  output wire             wr_o,
  output wire [AddrW-1:0] wr_addr_o,
  output wire [31:0]      wr_data_o,
  output wire [3:0]       wr_strb_o,
  output wire             rd_o,
  output wire [AddrW-1:0] rd_addr_o,
  input  wire [31:0]      rd_data_i
);

  reg        bvalid_q, rvalid_q;
  reg [31:0] rdata_q;

  assign wr_o      = rst_ni && awvalid_i && wvalid_i && !bvalid_q;
  assign awready_o = wr_o;
  assign wready_o  = wr_o;
  assign wr_addr_o = awaddr_i;
  assign wr_data_o = wdata_i;
  assign wr_strb_o = wstrb_i;

  assign rd_o      = arvalid_i && arready_o;
  assign arready_o = rst_ni && !rvalid_q;
  assign rd_addr_o = araddr_i;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      bvalid_q <= 1'b0;
      rvalid_q <= 1'b0;
    end else begin
      bvalid_q <= wr_o || (bvalid_q && !bready_i);
      rvalid_q <= rd_o || (rvalid_q && !rready_i);
    end
  end

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni)   rdata_q <= 32'd0;
    else if (rd_o) rdata_q <= rd_data_i;
  end

  assign bresp_o  = 2'b00;
  assign bvalid_o = bvalid_q;
  assign rresp_o  = 2'b00;
  assign rvalid_o = rvalid_q;
  assign rdata_o  = rdata_q;

endmodule

`default_nettype wire
