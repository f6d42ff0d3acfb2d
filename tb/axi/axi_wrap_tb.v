// SPDX-License-Identifier: Apache-2.0
// axi_wrap_tb: pree_axi through the wrap-around of its running counts. Two wrappers with the
// real pree_top (by default 2 PREUs, paper datapath, small memories: 64 hit points, a 16-entry
// index table, 16 pixels) get the same photons, candidates and hit points from two hosts
// (tb/axi/axi_wrap_drv.v) under different random back-pressure: one with the wide intake (Ppc
// photon slots a beat, by default 2, some left empty) and CountW narrow (by default 7, the
// narrowest these memories allow: the photon and candidate counts wrap every 128), one with one
// photon a beat and CountW 32 (no wrap in this run). The photons come in batches of 2^CountW, each
// drained before the next (the batch interrupt), so that the narrow wrapper's photon-done count
// rests at 0 after its wrap, where a wrapper that takes a count of 0 for "nothing retired" stops
// taking candidates for good. Both must take every photon and
// candidate (no stall), read the running counts modulo 2^CountW, and give the same hit points
// and pixels bit for bit, the photons must have changed the hit points, and no output of either
// wrapper may be X at any clock edge after aresetn rises (refused reads of unwritten memory,
// reset read data).
// Runs under Icarus (`iverilog -g2005`, `vvp -N`): tests/checks/axi_wrap.sh.
`default_nettype none

module axi_wrap_tb;
  parameter NumPreu    = 2;
  parameter HpAW       = 6;
  parameter PxAW       = 4;
  parameter IdxAW      = 4;
  parameter PhFifoAW   = 1;
  parameter Ppc        = 2;                      // the narrow wrapper's photon slots a beat
  parameter CountW     = IdxAW + PhFifoAW + $clog2(Ppc) + 1;   // the narrowest it takes
  parameter NumPhotons = 200;
  localparam HpRecW = 384;
  localparam NHP = 1 << HpAW;
  localparam NPX = 1 << PxAW;

  reg aclk = 1'b0;
  always #5 aclk = ~aclk;

  wire [1:0] done;

  // Pair 0: the wrapper with CountW narrow and its host (seed 1); pair 1: CountW 32 (seed 2).
  genvar g;
  generate
    for (g = 0; g < 2; g = g + 1) begin : g_pair
      localparam W = (g == 0) ? CountW : 32;
      localparam P = (g == 0) ? Ppc : 1;
      wire rstn, awv, awr, wv, wr, bv, br, arv, arr, rv, rr, pl, pv, pr, cv, cr, hv, hr;
      wire mu, ml, mv, mr, irq;
      wire [11:0] awa, ara;
      wire [31:0] wd, rd;
      wire [1:0] bresp, rresp;
      wire [256*P-1:0] pd;
      wire [32*NumPreu-1:0] cd;
      wire [4*NumPreu-1:0] ck;
      wire [HpRecW-1:0] hd, md;
      pree_axi #(.NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(2), .IdxAW(IdxAW), .PxAW(PxAW),
                 .PxBankW(2), .CntW(8), .PhotonsPerCycle(P), .PhFifoAW(PhFifoAW),
                 .CountW(W)) dut (
        .aclk(aclk), .aresetn(rstn),
        .s_axil_awaddr(awa), .s_axil_awvalid(awv), .s_axil_awready(awr), .s_axil_wdata(wd),
        .s_axil_wstrb(4'hf), .s_axil_wvalid(wv), .s_axil_wready(wr), .s_axil_bresp(bresp),
        .s_axil_bvalid(bv), .s_axil_bready(br), .s_axil_araddr(ara), .s_axil_arvalid(arv),
        .s_axil_arready(arr), .s_axil_rdata(rd), .s_axil_rresp(rresp), .s_axil_rvalid(rv),
        .s_axil_rready(rr), .s_axis_ph_tdata(pd), .s_axis_ph_tlast(pl), .s_axis_ph_tvalid(pv),
        .s_axis_ph_tready(pr), .s_axis_cand_tdata(cd), .s_axis_cand_tkeep(ck),
        .s_axis_cand_tvalid(cv), .s_axis_cand_tready(cr), .s_axis_hp_tdata(hd),
        .s_axis_hp_tvalid(hv), .s_axis_hp_tready(hr), .m_axis_tdata(md), .m_axis_tuser(mu),
        .m_axis_tlast(ml), .m_axis_tvalid(mv), .m_axis_tready(mr), .irq_o(irq));
      axi_wrap_drv #(.NumPreu(NumPreu), .HpAW(HpAW), .PxAW(PxAW), .CountW(W), .Ppc(P),
                     .NumPhotons(NumPhotons), .Batch(1 << CountW), .Seed(g + 1)) drv (
        .aclk(aclk), .aresetn(rstn), .awaddr(awa), .awvalid(awv), .awready(awr), .wdata(wd),
        .wvalid(wv), .wready(wr), .bvalid(bv), .bready(br), .araddr(ara), .arvalid(arv),
        .arready(arr), .rdata(rd), .rvalid(rv), .rready(rr), .ph_tdata(pd), .ph_tlast(pl),
        .ph_tvalid(pv), .ph_tready(pr), .cand_tdata(cd), .cand_tkeep(ck), .cand_tvalid(cv),
        .cand_tready(cr), .hp_tdata(hd), .hp_tvalid(hv), .hp_tready(hr), .m_tdata(md),
        .m_tuser(mu), .m_tlast(ml), .m_tvalid(mv), .m_tready(mr), .irq(irq), .done_o(done[g]));
      // No X on any output of the wrapper once aresetn has risen.
      always @(posedge aclk) begin
        if (rstn && ^{awr, wr, bresp, bv, arr, rd, rresp, rv, pr, cr, hr, md, mu, ml, mv,
                      irq} === 1'bx)
          $fatal(1, "axi_wrap_tb: an output of wrapper %0d is X", g);
      end
    end
  endgenerate

  integer i, diff, moved;
  initial begin
    wait (&done);
    diff = 0;
    moved = 0;
    for (i = 0; i < NHP; i = i + 1) begin
      if (^g_pair[0].drv.hp_res[i] === 1'bx) $fatal(1, "axi_wrap_tb: hit point %0d reads X", i);
      if (g_pair[0].drv.hp_res[i] !== g_pair[1].drv.hp_res[i]) begin
        if (diff < 10) $display("hit point %0d: CountW %0d %h, CountW 32 %h", i, CountW,
                                g_pair[0].drv.hp_res[i], g_pair[1].drv.hp_res[i]);
        diff = diff + 1;
      end
      if (g_pair[0].drv.hp_res[i][95:0] != 96'd0) moved = moved + 1;   // tau: photons arrived
    end
    for (i = 0; i < NPX; i = i + 1) begin
      if (^g_pair[0].drv.px_res[i] === 1'bx) $fatal(1, "axi_wrap_tb: pixel %0d reads X", i);
      if (g_pair[0].drv.px_res[i] !== g_pair[1].drv.px_res[i]) begin
        if (diff < 10) $display("pixel %0d: CountW %0d %h, CountW 32 %h", i, CountW,
                                g_pair[0].drv.px_res[i], g_pair[1].drv.px_res[i]);
        diff = diff + 1;
      end
    end
    if (diff != 0) $fatal(1, "axi_wrap_tb: %0d hit points and pixels differ", diff);
    if (moved < NHP / 2) $fatal(1, "axi_wrap_tb: only %0d hit points took photons", moved);
    $display("axi_wrap_tb: PASS (CountW %0d and 32, %0d photons, %0d hit points with flux, %0d %s",
             CountW, NumPhotons, moved, NPX, "pixels equal)");
    $finish;
  end

  initial begin
    #50_000_000;
    $fatal(1, "axi_wrap_tb: time limit");
  end

endmodule

`default_nettype wire
