// SPDX-License-Identifier: Apache-2.0
// pree_fpga_axi_wrap: the whole pree_axi between registers on a few pins, for place and route on a
// package whose pins cannot carry its buses (pree.core's pnr target; docs/integration.md). Every
// multi-bit input of pree_axi (AXI4-Lite addresses, data and strobes, the streams' tdata and
// tkeep) comes from one register that a serial pin shifts (scan_i); the one-bit handshakes
// (valid, ready, last) from a register of their own pins (hs_i); every output goes to a register,
// folded into one pin (pree_fpga_fold). So every path is a path of pree_axi, or the one-net hop
// into or out of it, and synthesis can remove nothing. Parameters: pree_axi's (passed through).
`default_nettype none

module pree_fpga_axi_wrap #(
  parameter NumPreu  = 4,
  parameter HpAW     = 18,
  parameter HpBankW  = 4,
  parameter IdxAW    = 12,
  parameter PxAW     = 17,
  parameter PxBankW  = 4,
  parameter CntW     = 16,
  parameter Datapath = 0,
  parameter PipeFast = 0,
  parameter AddStages  = 0,
  parameter MulStages  = 0,
  parameter SqrStages  = 0,
  parameter DivStages  = 0,
  parameter U2fStages  = 0,
  parameter WaccStages = 0,
  parameter PhotonsPerCycle = 1,
  parameter PhFifoAW = 2,
  parameter RingAW   = 4 + $clog2(PhotonsPerCycle),
  parameter CountW   = 32
) (
  input  wire       clk_i,
  input  wire       rst_ni,
  input  wire       scan_i,
  // {m_axis_tready, s_axis_hp_tvalid, s_axis_cand_tvalid, s_axis_ph_tlast, s_axis_ph_tvalid,
  //  s_axil_rready, s_axil_arvalid, s_axil_bready, s_axil_wvalid, s_axil_awvalid}
  input  wire [9:0] hs_i,
  output wire       fold_o
);

  localparam HpRecW = 32 + 192 + ((Datapath != 0) ? 320 : 160);
  localparam PhW    = PhotonsPerCycle * 256;
  localparam ScanW  = 12 + 32 + 4 + 12 + PhW + 36 * NumPreu + HpRecW;
  localparam OutW   = 41 + 3 + HpRecW + 4;

  reg [ScanW-1:0] scan_q;
  reg [9:0]       hs_q;
  always @(posedge clk_i) begin
    scan_q <= {scan_q[ScanW-2:0], scan_i};
    hs_q   <= hs_i;
  end

  wire [11:0]            awaddr  = scan_q[0 +: 12];
  wire [31:0]            wdata   = scan_q[12 +: 32];
  wire [3:0]             wstrb   = scan_q[44 +: 4];
  wire [11:0]            araddr  = scan_q[48 +: 12];
  wire [PhW-1:0]         ph      = scan_q[60 +: PhW];
  wire [32*NumPreu-1:0]  cand    = scan_q[60 + PhW +: 32 * NumPreu];
  wire [4*NumPreu-1:0]   keep    = scan_q[60 + PhW + 32 * NumPreu +: 4 * NumPreu];
  wire [HpRecW-1:0]      hp      = scan_q[60 + PhW + 36 * NumPreu +: HpRecW];

  wire        awready, wready, bvalid, arready, rvalid, ph_ready, cand_ready, hp_ready;
  wire [1:0]  bresp, rresp;
  wire [31:0] rdata;
  wire [HpRecW-1:0] m_data;
  wire        m_user, m_last, m_valid, irq;

  pree_axi #(
    .NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(HpBankW), .IdxAW(IdxAW), .PxAW(PxAW),
    .PxBankW(PxBankW), .CntW(CntW), .Datapath(Datapath), .PipeFast(PipeFast),
    .AddStages(AddStages), .MulStages(MulStages), .SqrStages(SqrStages), .DivStages(DivStages),
    .U2fStages(U2fStages), .WaccStages(WaccStages), .PhotonsPerCycle(PhotonsPerCycle),
    .PhFifoAW(PhFifoAW), .RingAW(RingAW), .CountW(CountW)
  ) u_axi (
    .aclk(clk_i), .aresetn(rst_ni),
    .s_axil_awaddr(awaddr), .s_axil_awvalid(hs_q[0]), .s_axil_awready(awready),
    .s_axil_wdata(wdata), .s_axil_wstrb(wstrb), .s_axil_wvalid(hs_q[1]), .s_axil_wready(wready),
    .s_axil_bresp(bresp), .s_axil_bvalid(bvalid), .s_axil_bready(hs_q[2]),
    .s_axil_araddr(araddr), .s_axil_arvalid(hs_q[3]), .s_axil_arready(arready),
    .s_axil_rdata(rdata), .s_axil_rresp(rresp), .s_axil_rvalid(rvalid), .s_axil_rready(hs_q[4]),
    .s_axis_ph_tdata(ph), .s_axis_ph_tlast(hs_q[6]), .s_axis_ph_tvalid(hs_q[5]),
    .s_axis_ph_tready(ph_ready),
    .s_axis_cand_tdata(cand), .s_axis_cand_tkeep(keep), .s_axis_cand_tvalid(hs_q[7]),
    .s_axis_cand_tready(cand_ready),
    .s_axis_hp_tdata(hp), .s_axis_hp_tvalid(hs_q[8]), .s_axis_hp_tready(hp_ready),
    .m_axis_tdata(m_data), .m_axis_tuser(m_user), .m_axis_tlast(m_last),
    .m_axis_tvalid(m_valid), .m_axis_tready(hs_q[9]), .irq_o(irq));

  reg [OutW-1:0] out_q;
  always @(posedge clk_i)
    out_q <= {awready, wready, bresp, bvalid, arready, rdata, rresp, rvalid, ph_ready, cand_ready,
              hp_ready, m_data, m_user, m_last, m_valid, irq};

  pree_fpga_fold #(.W(OutW)) u_fold (.clk_i(clk_i), .d_i(out_q), .fold_o(fold_o));

endmodule

`default_nettype wire
