// SPDX-License-Identifier: Apache-2.0
// pree_uart_axi: pree_axi with pree_uart_bridge in front, its only host link: one UART (rx_i, tx_o,
// Div clock cycles a bit) carries AXI4-Lite register writes and reads, beats for the three input
// streams and every m_axis beat (the protocol is in rtl/board/pree_uart_bridge.v). The board top
// (rtl/board/pree_ulx3s.v) and the bridge's bench (tb/board/uart_bridge_tb.v) both use it.
// Parameters: pree_axi's configuration (its header) and Div.
`default_nettype none

module pree_uart_axi #(
  parameter NumPreu  = 2,
  parameter HpAW     = 12,
  parameter HpBankW  = 3,
  parameter IdxAW    = 12,
  parameter PxAW     = 12,
  parameter PxBankW  = 2,
  parameter CntW     = 16,
  parameter Datapath = 0,
  parameter PipeFast = 1,
  parameter PhFifoAW = 2,
  parameter RingAW   = 4,
  parameter CountW   = 32,
  parameter Div      = 100
) (
  input  wire clk_i,
  input  wire rst_ni,
  input  wire rx_i,
  output wire tx_o,
  output wire overrun_o,
  output wire irq_o
);

  localparam HpRecW = 32 + 192 + ((Datapath != 0) ? 320 : 160);

  wire [11:0]           awaddr, araddr;
  wire [31:0]           wdata, rdata;
  wire [3:0]            wstrb;
  wire [1:0]            bresp, rresp;
  wire                  awvalid, awready, wvalid, wready, bvalid, bready;
  wire                  arvalid, arready, rvalid, rready;
  wire [255:0]          ph_tdata;
  wire                  ph_tlast, ph_tvalid, ph_tready;
  wire [32*NumPreu-1:0] cand_tdata;
  wire [4*NumPreu-1:0]  cand_tkeep;
  wire                  cand_tvalid, cand_tready;
  wire [HpRecW-1:0]     hp_tdata, m_tdata;
  wire                  hp_tvalid, hp_tready, m_tuser, m_tlast, m_tvalid, m_tready;

  pree_uart_bridge #(.NumPreu(NumPreu), .HpRecW(HpRecW), .Div(Div)) u_bridge (
    .clk_i(clk_i), .rst_ni(rst_ni), .rx_i(rx_i), .tx_o(tx_o), .overrun_o(overrun_o),
    .m_axil_awaddr(awaddr), .m_axil_awvalid(awvalid), .m_axil_awready(awready),
    .m_axil_wdata(wdata), .m_axil_wstrb(wstrb), .m_axil_wvalid(wvalid), .m_axil_wready(wready),
    .m_axil_bresp(bresp), .m_axil_bvalid(bvalid), .m_axil_bready(bready),
    .m_axil_araddr(araddr), .m_axil_arvalid(arvalid), .m_axil_arready(arready),
    .m_axil_rdata(rdata), .m_axil_rresp(rresp), .m_axil_rvalid(rvalid), .m_axil_rready(rready),
    .ph_tdata(ph_tdata), .ph_tlast(ph_tlast), .ph_tvalid(ph_tvalid), .ph_tready(ph_tready),
    .cand_tdata(cand_tdata), .cand_tkeep(cand_tkeep), .cand_tvalid(cand_tvalid),
    .cand_tready(cand_tready), .hp_tdata(hp_tdata), .hp_tvalid(hp_tvalid),
    .hp_tready(hp_tready), .m_tdata(m_tdata), .m_tuser(m_tuser), .m_tlast(m_tlast),
    .m_tvalid(m_tvalid), .m_tready(m_tready));

  pree_axi #(
    .NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(HpBankW), .IdxAW(IdxAW), .PxAW(PxAW),
    .PxBankW(PxBankW), .CntW(CntW), .Datapath(Datapath), .PipeFast(PipeFast), .PhFifoAW(PhFifoAW),
    .RingAW(RingAW), .CountW(CountW)
  ) u_pree (
    .aclk(clk_i), .aresetn(rst_ni),
    .s_axil_awaddr(awaddr), .s_axil_awvalid(awvalid), .s_axil_awready(awready),
    .s_axil_wdata(wdata), .s_axil_wstrb(wstrb), .s_axil_wvalid(wvalid), .s_axil_wready(wready),
    .s_axil_bresp(bresp), .s_axil_bvalid(bvalid), .s_axil_bready(bready),
    .s_axil_araddr(araddr), .s_axil_arvalid(arvalid), .s_axil_arready(arready),
    .s_axil_rdata(rdata), .s_axil_rresp(rresp), .s_axil_rvalid(rvalid), .s_axil_rready(rready),
    .s_axis_ph_tdata(ph_tdata), .s_axis_ph_tlast(ph_tlast), .s_axis_ph_tvalid(ph_tvalid),
    .s_axis_ph_tready(ph_tready),
    .s_axis_cand_tdata(cand_tdata), .s_axis_cand_tkeep(cand_tkeep),
    .s_axis_cand_tvalid(cand_tvalid), .s_axis_cand_tready(cand_tready),
    .s_axis_hp_tdata(hp_tdata), .s_axis_hp_tvalid(hp_tvalid), .s_axis_hp_tready(hp_tready),
    .m_axis_tdata(m_tdata), .m_axis_tuser(m_tuser), .m_axis_tlast(m_tlast),
    .m_axis_tvalid(m_tvalid), .m_axis_tready(m_tready), .irq_o(irq_o));

endmodule
