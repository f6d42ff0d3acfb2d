// SPDX-License-Identifier: Apache-2.0
// axi_reset_tb: pree_axi (with the real pree_top, small memories) at the end of a reset. A host
// may start a transfer at the first rising edge after ARESETn rises (AXI4, A3.1.2), while the
// wrapper's synchronised reset is still low for two more edges. Here every channel starts then:
// an AXI4-Lite write (IRQ_EN = 3) and read (VERSION), a photon beat (N^P = 1: counted, held for its candidate)
// and a hit-point beat. Each must be taken and answered once: one write response, one read
// response with the version, then IRQ_EN reads 3, PH_IN 1 and HP_PTR 1. A lost transfer ends
// the run with $fatal (a response that never comes, or a count short); run with vvp -N.
`default_nettype none

module axi_reset_tb;
  localparam NumPreu = 2, HpAW = 6, IdxAW = 4, PxAW = 4;
  localparam HpRecW = 32 + 192 + 160;

  reg         aclk = 1'b0, aresetn = 1'b0;
  reg  [11:0] awaddr = 12'd0, araddr = 12'd0;
  reg         awvalid = 1'b0, wvalid = 1'b0, arvalid = 1'b0, bready = 1'b0, rready = 1'b0;
  reg  [31:0] wdata = 32'd0;
  wire        awready, wready, bvalid, arready, rvalid;
  wire [1:0]  bresp, rresp;
  wire [31:0] rdata;
  reg         ph_valid = 1'b0, hp_valid = 1'b0;
  wire        ph_ready, cand_ready, hp_ready, m_valid, m_last, m_user, irq;
  wire [HpRecW-1:0] m_data;

  pree_axi #(.NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(1), .IdxAW(IdxAW), .PxAW(PxAW),
             .PxBankW(1)) u_dut (
    .aclk(aclk), .aresetn(aresetn),
    .s_axil_awaddr(awaddr), .s_axil_awvalid(awvalid), .s_axil_awready(awready),
    .s_axil_wdata(wdata), .s_axil_wstrb(4'hf), .s_axil_wvalid(wvalid), .s_axil_wready(wready),
    .s_axil_bresp(bresp), .s_axil_bvalid(bvalid), .s_axil_bready(bready),
    .s_axil_araddr(araddr), .s_axil_arvalid(arvalid), .s_axil_arready(arready),
    .s_axil_rdata(rdata), .s_axil_rresp(rresp), .s_axil_rvalid(rvalid), .s_axil_rready(rready),
    .s_axis_ph_tdata({64'd1, 192'd0}), .s_axis_ph_tlast(1'b0), .s_axis_ph_tvalid(ph_valid),
    .s_axis_ph_tready(ph_ready),
    .s_axis_cand_tdata({(32*NumPreu){1'b0}}), .s_axis_cand_tkeep({(4*NumPreu){1'b0}}),
    .s_axis_cand_tvalid(1'b0), .s_axis_cand_tready(cand_ready),
    .s_axis_hp_tdata({HpRecW{1'b0}}), .s_axis_hp_tvalid(hp_valid), .s_axis_hp_tready(hp_ready),
    .m_axis_tdata(m_data), .m_axis_tuser(m_user), .m_axis_tlast(m_last), .m_axis_tvalid(m_valid),
    .m_axis_tready(1'b1), .irq_o(irq));

  always #5 aclk = ~aclk;

  // Every handshake and response, counted at the rising edge.
  integer aw_n = 0, w_n = 0, b_n = 0, ar_n = 0, r_n = 0, ph_n = 0, hp_n = 0;
  reg [31:0] r_last;
  always @(posedge aclk) begin
    aw_n <= aw_n + (awvalid && awready);
    w_n  <= w_n + (wvalid && wready);
    b_n  <= b_n + (bvalid && bready);
    ar_n <= ar_n + (arvalid && arready);
    r_n  <= r_n + (rvalid && rready);
    ph_n <= ph_n + (ph_valid && ph_ready);
    hp_n <= hp_n + (hp_valid && hp_ready);
    if (rvalid && rready) r_last <= rdata;
  end

  // Drop each valid after its handshake (changes just after the edge).
  always @(posedge aclk) begin
    #1;
    if (aw_n > 0) awvalid = 1'b0;
    if (w_n > 0)  wvalid  = 1'b0;
    if (ar_n > 0) arvalid = 1'b0;
    if (ph_n > 0) ph_valid = 1'b0;
    if (hp_n > 0) hp_valid = 1'b0;
  end

  task wait_for;   // wait until the count reaches n, at most 20 cycles
    input integer which, n;
    integer t;
    begin
      t = 0;
      while ((which == 0 ? b_n : which == 1 ? r_n : which == 2 ? ph_n : hp_n) < n && t < 20) begin
        @(posedge aclk); t = t + 1;
      end
      if (t == 20)
        $fatal(1, "axi_reset_tb: %s not answered (%0d of %0d): taken during the reset release and lost",
               which == 0 ? "write" : which == 1 ? "read" : which == 2 ? "photon" : "hit point",
               which == 0 ? b_n : which == 1 ? r_n : which == 2 ? ph_n : hp_n, n);
    end
  endtask

  task read_reg;
    input [11:0] a;
    input [31:0] want;
    input [8*10-1:0] name;
    integer n;
    begin
      n = r_n;
      @(negedge aclk); araddr = a; arvalid = 1'b1;
      wait_for(1, n + 1);
      if (r_last !== want) $fatal(1, "axi_reset_tb: %0s reads %h, expected %h", name, r_last, want);
      $display("ok: %0s = %h", name, r_last);
    end
  endtask

  initial begin
    repeat (3) @(negedge aclk);
    aresetn = 1'b1;
    // The first rising edge after ARESETn rose; the transfers start just after it.
    @(posedge aclk); #1;
    awaddr = 12'h01C; wdata = 32'd3; awvalid = 1'b1; wvalid = 1'b1; bready = 1'b1;
    araddr = 12'h000; arvalid = 1'b1; rready = 1'b1;
    ph_valid = 1'b1; hp_valid = 1'b1;
    wait_for(0, 1); wait_for(1, 1); wait_for(2, 1); wait_for(3, 1);
    if (r_last !== 32'h0002_0000) $fatal(1, "axi_reset_tb: VERSION read %h", r_last);
    repeat (4) @(posedge aclk);
    if (aw_n != 1 || w_n != 1 || b_n != 1 || ar_n != 1 || r_n != 1)
      $fatal(1, "axi_reset_tb: handshakes aw %0d w %0d b %0d ar %0d r %0d, expected one each",
             aw_n, w_n, b_n, ar_n, r_n);
    $display("ok: the write and the read made at the reset release answered once each");
    read_reg(12'h01C, 32'd3, "IRQ_EN");
    read_reg(12'h050, 32'd1, "PH_IN");
    read_reg(12'h040, 32'd1, "HP_PTR");
    $display("PASS");
    $finish;
  end

endmodule

`default_nettype wire
