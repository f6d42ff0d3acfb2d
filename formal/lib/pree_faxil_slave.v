// SPDX-License-Identifier: Apache-2.0
// pree_faxil_slave: the AXI4-Lite rules (ARM IHI 0022E, Sec. A3.2 and B1) for a slave under
// proof, as a property module for SymbiYosys, instantiated beside the slave's port in a formal
// harness (formal/*/). The master is the environment: its rules are assumed; the slave's are
// asserted.
//
// Master (assumed): AWVALID, WVALID, ARVALID low in reset and in the first cycle after it; each
// held, with its address or data and strobes unchanged, until its handshake; BREADY and RREADY
// free, except that with MaxStall > 0 a response waits at most MaxStall cycles (fair master).
// Slave (asserted): BVALID and RVALID low in reset and the first cycle after; each held, with
// BRESP or RDATA and RRESP unchanged, until its handshake; a response only for an outstanding
// request (a write response once both its address and its data were taken: one response per
// request); no EXOKAY (AXI4-Lite has no exclusive access); at most MaxOut requests of each kind
// outstanding; and, with MaxWait > 0, bounded response: a write whose address and data are both
// offered or taken gets BVALID, and a read ARVALID or taken gets RVALID, within MaxWait cycles
// while no response waits for the master.
// Outputs (for the harness's induction invariants): the requests outstanding of each kind
// (taken, response not yet taken) and the cycles the present write and read have waited.
`default_nettype none

module pree_faxil_slave #(
  parameter AddrW    = 12,
  parameter MaxOut   = 1,
  parameter MaxStall = 0,
  parameter MaxWait  = 0,
  parameter CntW     = 4
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire [AddrW-1:0] awaddr,
  input  wire             awvalid,
  input  wire             awready,
  input  wire [31:0]      wdata,
  input  wire [3:0]       wstrb,
  input  wire             wvalid,
  input  wire             wready,
  input  wire [1:0]       bresp,
  input  wire             bvalid,
  input  wire             bready,
  input  wire [AddrW-1:0] araddr,
  input  wire             arvalid,
  input  wire             arready,
  input  wire [31:0]      rdata,
  input  wire [1:0]       rresp,
  input  wire             rvalid,
  input  wire             rready,
  output reg  [CntW-1:0]  f_aw_out_o,   // write addresses taken, response not yet taken
  output reg  [CntW-1:0]  f_w_out_o,    // write data taken, response not yet taken
  output reg  [CntW-1:0]  f_ar_out_o,   // read addresses taken, response not yet taken
  output reg  [CntW-1:0]  f_wwait_o,    // cycles the present write has waited for BVALID
  output reg  [CntW-1:0]  f_rwait_o     // cycles the present read has waited for RVALID
);

  localparam [1:0] EXOKAY = 2'b01;

  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;
  reg f_rst_past = 1'b0;
  always @(posedge clk_i) f_rst_past <= rst_ni;
  wire f_run = f_past_valid && f_rst_past && rst_ni;     // out of reset for two cycles

  wire aw_hs = awvalid && awready, w_hs = wvalid && wready, b_hs = bvalid && bready;
  wire ar_hs = arvalid && arready, r_hs = rvalid && rready;

  // Reset: no request and no response in reset or in the first cycle after it.
  always @* if (!f_past_valid || !rst_ni) begin
    assume (!awvalid && !wvalid && !arvalid);
    assert (!bvalid && !rvalid);
  end
  always @(posedge clk_i) if (f_past_valid && !$past(rst_ni)) begin
    assume (!awvalid && !wvalid && !arvalid);
    assert (!bvalid && !rvalid);
  end

  // Requests wait unchanged for their handshake (master); responses too (slave).
  always @(posedge clk_i) if (f_run) begin
    if ($past(awvalid && !awready)) assume (awvalid && awaddr == $past(awaddr));
    if ($past(wvalid && !wready))   assume (wvalid && wdata == $past(wdata) && wstrb == $past(wstrb));
    if ($past(arvalid && !arready)) assume (arvalid && araddr == $past(araddr));
    if ($past(bvalid && !bready))   assert (bvalid && bresp == $past(bresp));
    if ($past(rvalid && !rready))   assert (rvalid && rdata == $past(rdata) && rresp == $past(rresp));
  end
  always @* begin
    if (bvalid) assert (bresp != EXOKAY);
    if (rvalid) assert (rresp != EXOKAY);
  end

  // Outstanding requests: a response only for one taken and not yet answered.
  initial begin
    f_aw_out_o = {CntW{1'b0}}; f_w_out_o = {CntW{1'b0}}; f_ar_out_o = {CntW{1'b0}};
  end
  always @(posedge clk_i)
    if (!rst_ni) begin
      f_aw_out_o <= {CntW{1'b0}}; f_w_out_o <= {CntW{1'b0}}; f_ar_out_o <= {CntW{1'b0}};
    end else begin
      f_aw_out_o <= f_aw_out_o + aw_hs - b_hs;
      f_w_out_o  <= f_w_out_o + w_hs - b_hs;
      f_ar_out_o <= f_ar_out_o + ar_hs - r_hs;
    end
  always @* if (rst_ni) begin
    if (bvalid) assert (f_aw_out_o != 0 && f_w_out_o != 0);
    if (rvalid) assert (f_ar_out_o != 0);
    assert (f_aw_out_o <= MaxOut && f_w_out_o <= MaxOut && f_ar_out_o <= MaxOut);
  end

  // Bounded response under a fair master.
  wire w_owed = (awvalid || f_aw_out_o != 0) && (wvalid || f_w_out_o != 0) && !bvalid;
  wire r_owed = (arvalid || f_ar_out_o != 0) && !rvalid;
  initial begin f_wwait_o = {CntW{1'b0}}; f_rwait_o = {CntW{1'b0}}; end
  always @(posedge clk_i) begin
    f_wwait_o <= (!rst_ni || !w_owed) ? {CntW{1'b0}} : f_wwait_o + (f_wwait_o != {CntW{1'b1}});
    f_rwait_o <= (!rst_ni || !r_owed) ? {CntW{1'b0}} : f_rwait_o + (f_rwait_o != {CntW{1'b1}});
  end
  reg [CntW-1:0] f_bstall, f_rstall;
  initial begin f_bstall = {CntW{1'b0}}; f_rstall = {CntW{1'b0}}; end
  always @(posedge clk_i) begin
    f_bstall <= (!rst_ni || !bvalid || bready) ? {CntW{1'b0}} : f_bstall + (f_bstall != {CntW{1'b1}});
    f_rstall <= (!rst_ni || !rvalid || rready) ? {CntW{1'b0}} : f_rstall + (f_rstall != {CntW{1'b1}});
  end
  generate
    if (MaxStall > 0) begin : g_fair_master
      always @* assume (f_bstall < MaxStall && f_rstall < MaxStall);
    end
    if (MaxWait > 0) begin : g_bounded
      always @* if (rst_ni) assert (f_wwait_o < MaxWait && f_rwait_o < MaxWait);
    end
  endgenerate

endmodule

`default_nettype wire
