// SPDX-License-Identifier: Apache-2.0
// pree_axi_fv: the formal harness of pree_axi (job formal/axi; docs/formal.md). The wrapper with
// small parameters around the pree_top stub (pree_top_stub.v), every port checked by the
// interface property modules of formal/lib, the environment's assumptions, and the wrapper's
// own invariants and covers.
//
// Taps: the f_t_* wires have no driver here; taps.ys connects each to a register inside the
// wrapper after flattening (SymbiYosys reads it), so that the RTL stays free of formal code and
// the harness can state invariants on its state.
`default_nettype none

module pree_axi_fv #(
  parameter NumPreu  = 2,
  parameter HpAW     = 4,
  parameter HpBankW  = 1,
  parameter IdxAW    = 3,
  parameter PxAW     = 3,
  parameter PxBankW  = 1,
  parameter CntW     = 3,
  parameter PhFifoAW = 1,
  parameter RingAW   = 2,
  parameter CountW   = 6,   // the wrapper's running counts: narrow, so that they wrap
  parameter PhotonsPerCycle = 1,   // photon slots a beat (formal/axi_wide: 2, with RingAW 3)
  parameter StallMax = 3,   // fair back-pressure: the host takes a waiting result or response
  parameter Acct     = 0,   // 1: the candidate accounting's invariants (job formal/axi_acct)
  parameter CoverWrap = 0,  // 1: cover photons_done_o wrapping (job formal/axi_narrow: CountW 4)
  parameter Live     = 0,   // 1: bounded response under a fair host and engine (job formal/axi_live)
  parameter LiveMax  = 8    // Live: cycles of pending work with no step that fail it
) (
  input wire aclk,
  input wire aresetn,
  input wire [11:0] s_axil_awaddr, input wire s_axil_awvalid,
  input wire [31:0] s_axil_wdata, input wire [3:0] s_axil_wstrb, input wire s_axil_wvalid,
  input wire s_axil_bready,
  input wire [11:0] s_axil_araddr, input wire s_axil_arvalid, input wire s_axil_rready,
  input wire [256*PhotonsPerCycle-1:0] s_axis_ph_tdata, input wire s_axis_ph_tlast, input wire s_axis_ph_tvalid,
  input wire [32*NumPreu-1:0] s_axis_cand_tdata, input wire [4*NumPreu-1:0] s_axis_cand_tkeep,
  input wire s_axis_cand_tvalid,
  input wire [32+192+160-1:0] s_axis_hp_tdata, input wire s_axis_hp_tvalid,
  input wire m_axis_tready
);

  localparam HpRecW = 32 + 192 + 160;
  localparam P = PhotonsPerCycle;
  localparam [31:0] IDX_ROOM = (32'd1 << IdxAW) - NumPreu;

  wire s_axil_awready, s_axil_wready, s_axil_bvalid, s_axil_arready, s_axil_rvalid;
  wire [1:0] s_axil_bresp, s_axil_rresp;
  wire [31:0] s_axil_rdata;
  wire s_axis_ph_tready, s_axis_cand_tready, s_axis_hp_tready;
  wire [HpRecW-1:0] m_axis_tdata;
  wire m_axis_tuser, m_axis_tlast, m_axis_tvalid, irq_o;

  pree_axi #(
    .NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(HpBankW), .IdxAW(IdxAW), .PxAW(PxAW),
    .PxBankW(PxBankW), .CntW(CntW), .PhFifoAW(PhFifoAW), .RingAW(RingAW), .CountW(CountW),
    .PhotonsPerCycle(P)
  ) u_dut (
    .aclk(aclk), .aresetn(aresetn),
    .s_axil_awaddr(s_axil_awaddr), .s_axil_awvalid(s_axil_awvalid), .s_axil_awready(s_axil_awready),
    .s_axil_wdata(s_axil_wdata), .s_axil_wstrb(s_axil_wstrb), .s_axil_wvalid(s_axil_wvalid),
    .s_axil_wready(s_axil_wready), .s_axil_bresp(s_axil_bresp), .s_axil_bvalid(s_axil_bvalid),
    .s_axil_bready(s_axil_bready), .s_axil_araddr(s_axil_araddr), .s_axil_arvalid(s_axil_arvalid),
    .s_axil_arready(s_axil_arready), .s_axil_rdata(s_axil_rdata), .s_axil_rresp(s_axil_rresp),
    .s_axil_rvalid(s_axil_rvalid), .s_axil_rready(s_axil_rready),
    .s_axis_ph_tdata(s_axis_ph_tdata), .s_axis_ph_tlast(s_axis_ph_tlast),
    .s_axis_ph_tvalid(s_axis_ph_tvalid), .s_axis_ph_tready(s_axis_ph_tready),
    .s_axis_cand_tdata(s_axis_cand_tdata), .s_axis_cand_tkeep(s_axis_cand_tkeep),
    .s_axis_cand_tvalid(s_axis_cand_tvalid), .s_axis_cand_tready(s_axis_cand_tready),
    .s_axis_hp_tdata(s_axis_hp_tdata), .s_axis_hp_tvalid(s_axis_hp_tvalid),
    .s_axis_hp_tready(s_axis_hp_tready),
    .m_axis_tdata(m_axis_tdata), .m_axis_tuser(m_axis_tuser), .m_axis_tlast(m_axis_tlast),
    .m_axis_tvalid(m_axis_tvalid), .m_axis_tready(m_axis_tready), .irq_o(irq_o));

  reg f_past_valid = 1'b0;
  always @(posedge aclk) f_past_valid <= 1'b1;
  initial assume (!aresetn);

  // ---------------------------------------------------------------------------------------------
  // Every port's interface rules.
  wire [3:0] f_aw_out, f_w_out, f_ar_out, f_wwait, f_rwait;
  pree_faxil_slave #(.AddrW(12), .MaxOut(1), .MaxStall(StallMax), .MaxWait(4)) f_axil (
    .clk_i(aclk), .rst_ni(aresetn),
    .awaddr(s_axil_awaddr), .awvalid(s_axil_awvalid), .awready(s_axil_awready),
    .wdata(s_axil_wdata), .wstrb(s_axil_wstrb), .wvalid(s_axil_wvalid), .wready(s_axil_wready),
    .bresp(s_axil_bresp), .bvalid(s_axil_bvalid), .bready(s_axil_bready),
    .araddr(s_axil_araddr), .arvalid(s_axil_arvalid), .arready(s_axil_arready),
    .rdata(s_axil_rdata), .rresp(s_axil_rresp), .rvalid(s_axil_rvalid), .rready(s_axil_rready),
    .f_aw_out_o(f_aw_out), .f_w_out_o(f_w_out), .f_ar_out_o(f_ar_out), .f_wwait_o(f_wwait),
    .f_rwait_o(f_rwait));

  pree_faxis #(.DataW(256*P), .SrcIsDut(0)) f_ph (
    .clk_i(aclk), .rst_ni(aresetn), .tvalid(s_axis_ph_tvalid), .tready(s_axis_ph_tready),
    .tdata(s_axis_ph_tdata), .tlast(s_axis_ph_tlast), .tkeep(1'b1), .tuser(1'b1), .f_stall_o());
  pree_faxis #(.DataW(32*NumPreu), .KeepW(4*NumPreu), .SrcIsDut(0)) f_cand (
    .clk_i(aclk), .rst_ni(aresetn), .tvalid(s_axis_cand_tvalid), .tready(s_axis_cand_tready),
    .tdata(s_axis_cand_tdata), .tlast(1'b1), .tkeep(s_axis_cand_tkeep), .tuser(1'b1),
    .f_stall_o());
  pree_faxis #(.DataW(HpRecW), .SrcIsDut(0)) f_hp (
    .clk_i(aclk), .rst_ni(aresetn), .tvalid(s_axis_hp_tvalid), .tready(s_axis_hp_tready),
    .tdata(s_axis_hp_tdata), .tlast(1'b1), .tkeep(1'b1), .tuser(1'b1), .f_stall_o());
  wire [7:0] f_m_stall;
  pree_faxis #(.DataW(HpRecW), .SrcIsDut(1), .MaxStall(StallMax)) f_m (
    .clk_i(aclk), .rst_ni(aresetn), .tvalid(m_axis_tvalid), .tready(m_axis_tready),
    .tdata(m_axis_tdata), .tlast(m_axis_tlast), .tkeep(1'b1), .tuser(m_axis_tuser),
    .f_stall_o(f_m_stall));

  // ---------------------------------------------------------------------------------------------
  // Taps into the wrapper (taps.ys).
  (* keep *) wire [2:0]  f_t_state;
  (* keep *) wire [CountW-1:0] f_t_wr_cnt, f_t_cum_in, f_t_given, f_t_ret, f_t_taken, f_t_done;
  (* keep *) wire        f_t_all_idle, f_t_rst_n;
  (* keep *) wire [PhFifoAW:0] f_t_phf_wp, f_t_phf_rp;
  (* keep *) wire [1:0]  f_t_irq;                  // IRQ_STATUS: {command done, batch done}
  (* keep *) wire        f_t_cmd_done;
  (* keep *) wire [31:0] f_t_ci;                   // Live: a command's items issued
  (* keep *) wire        f_t_head_left;            // Live: the FIFO head has a photon lacking candidates
  (* keep *) wire [P-1:0] f_t_gone;                // the head beat's slots given to the engine
  (* keep *) wire        f_t_core_take;            // photons given to the engine in this cycle
  (* keep *) wire [P*CntW-1:0]   f_t_give_n;       // their N^P, slot by slot (0: not given)
  (* keep *) wire [P*CountW-1:0] f_t_head_end;     // the head beat's candidate ends
  // Acct only (axi_acct/taps_acct.ys, after memory_map): the wrapper's copy of photons_done_o,
  // the ring of in-flight photons' candidate ends and the photon FIFO's ends and N^P (P slots an
  // entry).
  (* keep *) wire [CountW-1:0] f_t_wdone;
  (* keep *) wire [CountW*(1<<RingAW)-1:0]     f_t_ring;
  (* keep *) wire [P*CountW*(1<<PhFifoAW)-1:0] f_t_phf_end;
  (* keep *) wire [P*CntW*(1<<PhFifoAW)-1:0]   f_t_phf_n;

  // ---------------------------------------------------------------------------------------------
  // The environment (the host's contract, docs/integration.md): each slot's N^P fits the index
  // table.
  always @* begin : n_fits
    integer s;
    for (s = 0; s < P; s = s + 1)
      if (aresetn && s_axis_ph_tvalid)
        assume ({{(32-CntW){1'b0}}, s_axis_ph_tdata[256*s + 192 +: CntW]} <= IDX_ROOM);
  end

  // ---------------------------------------------------------------------------------------------
  // Invariants of the wrapper's state (they hold from reset; stated for induction).
  wire [PhFifoAW:0] f_phf_n = f_t_phf_wp - f_t_phf_rp;   // photons in the FIFO
  wire [CountW-1:0] f_fly = f_t_given - f_t_done;          // photons in the engine
  wire [CountW-1:0] f_used = f_t_wr_cnt - f_t_ret;         // index entries not yet retired
  always @* if (aresetn) begin
    assert (f_aw_out == {3'd0, s_axil_bvalid} && f_w_out == {3'd0, s_axil_bvalid});
    assert (f_ar_out == {3'd0, s_axil_rvalid});
    assert (f_t_given == f_t_taken);
    assert (f_t_state <= 3'd5);
    assert (f_phf_n <= (1 << PhFifoAW));
    assert (f_fly < (1 << RingAW));
  end
  // A photon is passed on only after its candidates: every slot given (N^P > 0 to the engine)
  // ends at or before the candidates written (distances modulo 2^CountW).
  always @* begin : given_written
    integer s;
    reg [CountW-1:0] ahead;
    for (s = 0; s < P; s = s + 1) begin
      ahead = f_t_wr_cnt - f_t_head_end[CountW*s +: CountW];
      if (aresetn && f_t_core_take && f_t_give_n[CntW*s +: CntW] != 0) assert (!ahead[CountW-1]);
    end
  end

  // ---------------------------------------------------------------------------------------------
  // Acct: the candidate accounting's invariants through wrap-around (jobs axi_acct and, at
  // PhotonsPerCycle 2, axi_acct_wide). Measured from the candidates retired (ret): the candidate
  // ends of the photons in flight (ring, oldest first), then of the FIFO's photons (oldest first;
  // one a beat at PhotonsPerCycle 1; with several slots, a beat's slots with N^P > 0 in slot
  // order, in the head beat those not yet given), rise, each by at most a table's room, to
  // cum_in, the last photon's; every photon in flight has its candidates written; the written
  // candidates not yet retired fit the table. With several slots besides: the ends rise strictly
  // (N^P > 0), a FIFO photon's end is the one before it plus its own N^P (the end before the
  // first is ret), and the beats' invariants below. (At one slot the first set only: its
  // proof, axi_acct, already takes minutes at k = 6.)
  localparam RING = 1 << RingAW, PHF = 1 << PhFifoAW, NCH = RING + PHF * P;
  localparam [31:0] SPAN = (P == 1) ? IDX_ROOM * (RING + PHF)            // below 2^CountW
                                    : (32'd1 << IdxAW) + IDX_ROOM * PHF * P;
  // The photons whose candidates are not retired: from the wrapper's copy of photons_done_o
  // (w_done, which ret follows a cycle late) to the photons given.
  wire [CountW-1:0] f_unret = f_t_given - f_t_wdone;

  generate
    if (Acct != 0) begin : g_acct
      reg [CountW-1:0] f_end [0:NCH-1];    // the ends in order; f_n of them
      reg [CountW-1:0] f_dist [0:NCH-1];   // each end - ret, modulo 2^CountW
      reg [CntW-1:0]   f_np [0:NCH-1];     // a FIFO photon's N^P (0: a photon in flight)
      reg [CountW-1:0] f_prev [0:NCH-1];   // the distance before each (0 before the first)
      reg [4:0] f_n;
      wire [CountW-1:0] f_d_cum = f_t_cum_in - f_t_ret, f_d_wr = f_t_wr_cnt - f_t_ret;
      wire [CountW-1:0] f_lag = f_t_done - f_t_wdone;
      always @* begin : chain
        integer i, k, e, sl;
        reg [CntW-1:0] np;
        f_n = 5'd0;
        for (i = 0; i < NCH; i = i + 1) begin f_end[i] = 0; f_dist[i] = 0; f_np[i] = 0; end
        for (i = 0; i < RING; i = i + 1)
          if (i < f_unret) begin
            k = (f_t_wdone + i) % RING;
            f_end[f_n] = f_t_ring[CountW*k +: CountW]; f_n = f_n + 5'd1;
          end
        for (e = 0; e < PHF; e = e + 1)
          if (e < f_phf_n) begin
            k = (f_t_phf_rp + e) % PHF;
            for (sl = 0; sl < P; sl = sl + 1) begin
              np = f_t_phf_n[CntW*(k*P + sl) +: CntW];
              if (P == 1 || (np != 0 && !(e == 0 && f_t_gone[sl]))) begin
                f_end[f_n] = f_t_phf_end[CountW*(k*P + sl) +: CountW];
                f_np[f_n] = np; f_n = f_n + 5'd1;
              end
            end
          end
        for (i = 0; i < NCH; i = i + 1) f_dist[i] = f_end[i] - f_t_ret;
        f_prev[0] = {CountW{1'b0}};
        for (i = 1; i < NCH; i = i + 1) f_prev[i] = f_dist[i-1];
      end
      always @* if (aresetn && f_t_rst_n) begin : acct
        integer i;
        assert (f_d_cum <= SPAN);
        assert (f_lag <= P);
        assert (f_d_wr <= (32'd1 << IdxAW));
        for (i = 0; i < NCH; i = i + 1)
          if (i < f_n) begin
            assert (f_dist[i] <= f_d_cum);
            assert ((P == 1 ? f_dist[i] >= f_prev[i] : f_dist[i] > f_prev[i]) &&
                    f_dist[i] - f_prev[i] <= IDX_ROOM);
            if (i == f_n - 1) assert (f_end[i] == f_t_cum_in);
            if (i < f_unret) assert (f_dist[i] <= f_d_wr);
            if (P > 1 && i >= f_unret) assert (f_dist[i] - f_prev[i] == f_np[i]);
          end
        if (f_n == 5'd0) assert (f_d_cum == 0);
      end
      // The FIFO's beats: each holds a photon; the head beat's slots given are photons, a prefix
      // of its photons in slot order, and not all of them (the beat leaves with its last).
      always @* if (P > 1 && aresetn && f_t_rst_n) begin : beats
        integer e, k, a, b;
        reg any, todo;
        if (f_phf_n == 0) assert (f_t_gone == 0);
        for (e = 0; e < PHF; e = e + 1)
          if (e < f_phf_n) begin
            k = (f_t_phf_rp + e) % PHF;
            any = 1'b0; todo = 1'b0;
            for (a = 0; a < P; a = a + 1)
              if (f_t_phf_n[CntW*(k*P + a) +: CntW] != 0) begin
                any = 1'b1;
                if (e == 0 && !f_t_gone[a]) todo = 1'b1;
              end
            assert (any);
            if (e == 0) begin
              assert (todo);
              for (a = 0; a < P; a = a + 1) begin
                if (f_t_gone[a]) assert (f_t_phf_n[CntW*(k*P + a) +: CntW] != 0);
                for (b = a + 1; b < P; b = b + 1)
                  if (f_t_gone[b] && f_t_phf_n[CntW*(k*P + a) +: CntW] != 0) assert (f_t_gone[a]);
              end
            end
          end
      end
    end
  endgenerate

  // ---------------------------------------------------------------------------------------------
  // Covers: the events the proof must reach, so that none of it is vacuous.
  always @* if (aresetn && f_t_rst_n) begin
    cover (s_axis_ph_tvalid && !s_axis_ph_tready);               // a stalled photon stream
    cover (s_axis_cand_tvalid && !s_axis_cand_tready && f_t_state == 3'd0);
    cover (m_axis_tvalid && !m_axis_tready);                     // a stalled result stream
    cover (m_axis_tvalid && m_axis_tready && m_axis_tlast);      // a read command's last beat
    cover (irq_o);                                               // an interrupt raised
    cover (f_phf_n == (1 << PhFifoAW));                          // photon FIFO full
    cover (f_used == (1 << IdxAW));                              // index table full
    cover (s_axil_bvalid && s_axil_rvalid);                      // a write and a read answered
    cover (irq_o && f_t_irq[0]);                                 // a batch-done interrupt
    cover (f_t_state == 3'd5 && f_t_cmd_done);                   // a radiance pass ends
  end
  reg [CountW-1:0] f_done_prev_q = {CountW{1'b0}}, f_given_prev_q = {CountW{1'b0}};
  always @(posedge aclk) begin f_done_prev_q <= f_t_done; f_given_prev_q <= f_t_given; end

  // The wide intake (PhotonsPerCycle 2): two photons given in one cycle; a beat split (slot 0
  // given, slot 1 waiting for its candidates); a beat whose slot 0 is empty and slot 1 not taken.
  generate
    if (P > 1) begin : g_cover_wide
      always @* if (aresetn && f_t_rst_n) begin
        cover (f_t_done - f_done_prev_q == 2);                   // photons_done_o up by 2
        cover (f_t_given - f_given_prev_q == 2);
        cover (f_t_gone[0] && !f_t_gone[1]);
        cover (s_axis_ph_tvalid && s_axis_ph_tready && s_axis_ph_tdata[192 +: CntW] == 0 &&
               s_axis_ph_tdata[256 + 192 +: CntW] != 0);
      end
    end
  endgenerate

  // ---------------------------------------------------------------------------------------------
  // Live: bounded response. While work is pending (a photon offered, a photon in the FIFO or in the
  // engine, a command running, a result beat waiting), some step happens within LiveMax cycles: a
  // beat taken on an input stream or sent on m_axis, a photon given to the engine or done, a
  // candidate entry retired, a command's state or item count moving. Fairness assumed besides the
  // stub's (a waiting photon taken, the oldest photon done, a pass ended, within 3 or 4 cycles)
  // and the fair sinks (results and responses taken within StallMax): the host offers a candidate
  // beat within StallMax cycles whenever the FIFO's head photon still lacks candidates.
  generate
    if (Live != 0) begin : g_live
      reg [CountW-1:0] f_given_q, f_done_q, f_ret_q;
      reg [2:0]  f_state_q;
      reg [31:0] f_ci_q;
      reg [7:0]  f_idle_run, f_owe_run;
      always @(posedge aclk) begin
        f_given_q <= f_t_given; f_done_q <= f_t_done; f_ret_q <= f_t_ret;
        f_state_q <= f_t_state; f_ci_q <= f_t_ci;
      end
      wire f_owed   = f_phf_n != 0 && f_t_head_left;
      wire f_step   = (s_axis_ph_tvalid && s_axis_ph_tready) ||
                      (s_axis_cand_tvalid && s_axis_cand_tready) ||
                      (s_axis_hp_tvalid && s_axis_hp_tready) || (m_axis_tvalid && m_axis_tready) ||
                      f_t_given != f_given_q || f_t_done != f_done_q || f_t_ret != f_ret_q ||
                      f_t_state != f_state_q || f_t_ci != f_ci_q;
      wire f_pend   = s_axis_ph_tvalid || f_phf_n != 0 || f_fly != 0 || f_t_state != 3'd0 ||
                      m_axis_tvalid;
      always @(posedge aclk) begin
        f_idle_run <= (!aresetn || !f_t_rst_n || !f_pend || f_step) ? 8'd0 : f_idle_run + 8'd1;
        f_owe_run  <= (!aresetn || !f_owed || s_axis_cand_tvalid) ? 8'd0 : f_owe_run + 8'd1;
      end
      always @* if (aresetn && f_t_rst_n) begin
        assume (f_owe_run < StallMax);
        assert (f_idle_run < LiveMax);
      end
    end
  endgenerate

  // photons_done_o wraps: from 2^CountW - 1 to 0 (with CountW 4, 16 photons from reset).
  reg f_done_top_q = 1'b0;
  always @(posedge aclk) f_done_top_q <= f_t_done == {CountW{1'b1}};
  generate
    if (CoverWrap != 0) begin : g_cover_wrap
      always @* if (aresetn && f_t_rst_n) cover (f_done_top_q && f_t_done == {CountW{1'b0}});
    end
  endgenerate

endmodule

`default_nettype wire
