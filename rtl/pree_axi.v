// SPDX-License-Identifier: Apache-2.0
// pree_axi: pree_top behind standard AXI interfaces (docs/integration.md is the manual: register
// map, stream formats, timing diagrams, a worked host sequence).
//
//   s_axil_*      AXI4-Lite slave (pree_axil_slave): control, status, constants, counters.
//   s_axis_ph_*   photons, PhotonsPerCycle 256-bit slots a beat, slot s in tdata[256s +: 256]:
//                 {reserved (32 bits, write 0), N^P (32-bit slot), phi b g r, pos z y x}; slot 0
//                 holds the oldest photon, a slot with N^P = 0 is empty (dropped) and may sit
//                 anywhere. TLAST: the beat's last photon (its last non-empty slot) ends a batch
//                 (interrupt "batch done" once all of it is applied); a beat of empty slots with
//                 TLAST ends the batch at the photons before it.
//   s_axis_cand_* the photons' candidate hit-point addresses, concatenated in photon order, up to
//                 NumPreu a beat (lane j = tdata[32j +: 32], present when tkeep[4j +: 4] is all
//                 ones; photon boundaries need not align with beats).
//   s_axis_hp_*   hit points to load, one a beat at HP_PTR, HP_PTR + 1, ...: {pixel (32-bit
//                 slot), f b g r, pos z y x, state}; taken only while the engine is idle.
//   m_axis_*      results of the read commands: hit-point records (tuser 0, as s_axis_hp) or
//                 pixels (tuser 1, {b, g, r} in the low 96 bits); tlast on a command's last beat.
//   irq_o         level: (IRQ_STATUS & IRQ_EN) != 0.
//
// Defined outputs. Every register software reads is reset, and so is m_axis_tdata. Read commands
// reach only memory the host wrote: hit points [0, n) once s_axis_hp has loaded them from
// address 0 on (loads extend the range when they write at its end) and pixels once CMD 3 has
// cleared them; CMD 2 beyond the hit points loaded, CMD 1 with N_HIT beyond them and CMD 4
// beyond the pixels cleared are refused (ERR bit 0, no interrupt, no beat). The memories'
// contents after reset (or power-up) are never relied on.
//
// Index table. The wrapper owns pree_top's index table: candidate number s (counting every
// candidate since reset) goes to entry ~s mod 2^IdxAW, so that photon k, whose candidates are
// s = S_k .. S_k + N_k - 1, has p_k = -(S_k + N_k) and AFTSO-HpUOC reads its entries in stream
// order; any NumPreu consecutive candidates lie in distinct index banks (no stage-A conflict and
// a conflict-free load port). A photon is offered to pree_top once all its candidates are written
// (registered count): the head beat's photons go, in slot order, in the cycles their candidates
// are written (those not yet given as empty slots), so a beat whose photons' candidates together
// exceed the table never waits for itself. An entry is overwritten only after pree_top has
// counted its photon done (photons_done_o; a ring of the in-flight photons' candidate ends; the candidates retired
// follow each move of photons_done_o, never its value, which wraps to 0). Every running count
// (photons and candidates) is CountW bits and wraps; the wrapper compares them only as
// differences modulo 2^CountW, which its parameter check keeps below 2^(CountW-1). Slots with
// N^P = 0 are dropped here (a beat of them only ends a batch). The mode (update / radiance) is the command engine's: radiance only
// while CMD 1 runs. Streams and commands never overlap: streams move only while no command runs,
// and a command starts only when everything is idle.
//
// Parameters: those of pree_top a user chooses (NumPreu, the memory sizes, CntW, Datapath, PipeFast
// and the PREU units' Stages; CtrW is the register map's 48), which pree_top checks at elaboration
// (a missing module named after the problem, pree_top_*); this wrapper checks its own the same way
// (pree_axi_*: the photon slots, the ring, the running counts, the 32-bit register slots of PxAW,
// HpAW and CntW). Its own: PhotonsPerCycle (photon slots a beat on s_axis_ph, 1 to 8, passed to
// pree_top: its wide intake; NumPreu / 4 lets 8 and 16 PREUs reach pree_top's own utilization),
// PhFifoAW (log2 of the photon FIFO depth, in beats), RingAW (log2 of the in-flight photon ring: a
// give waits while 2^RingAW - PhotonsPerCycle photons are between pree_top's intake and
// photons_done_o; default 4 + log2 PhotonsPerCycle, more than twice PhotonsPerCycle entries),
// CountW (bits of the running counts: photons in, given and done, candidates in and retired; they
// wrap, and every comparison between them is modulo 2^CountW; PH_IN, PH_DONE and CAND_IN read them
// zero-extended; at least IdxAW + PhFifoAW + log2 PhotonsPerCycle + 1 and more than RingAW, so that
// the distances compared stay below 2^(CountW-1); 32 unless a simulation or a proof wants to reach
// the wrap-around in a few hundred photons).
`default_nettype none

module pree_axi #(
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
  parameter CountW   = 32,
  parameter StateW   = (Datapath != 0) ? 320 : 160,   // do not override: set by Datapath
  parameter HpRecW   = 32 + 192 + StateW               // do not override: hit-point record bits
) (
  input  wire                       aclk,
  input  wire                       aresetn,
  // AXI4-Lite slave.
  input  wire [11:0]                s_axil_awaddr,
  input  wire                       s_axil_awvalid,
  output wire                       s_axil_awready,
  input  wire [31:0]                s_axil_wdata,
  input  wire [3:0]                 s_axil_wstrb,
  input  wire                       s_axil_wvalid,
  output wire                       s_axil_wready,
  output wire [1:0]                 s_axil_bresp,
  output wire                       s_axil_bvalid,
  input  wire                       s_axil_bready,
  input  wire [11:0]                s_axil_araddr,
  input  wire                       s_axil_arvalid,
  output wire                       s_axil_arready,
  output wire [31:0]                s_axil_rdata,
  output wire [1:0]                 s_axil_rresp,
  output wire                       s_axil_rvalid,
  input  wire                       s_axil_rready,
  // Photons.
  input  wire [PhotonsPerCycle*256-1:0] s_axis_ph_tdata,
  input  wire                       s_axis_ph_tlast,
  input  wire                       s_axis_ph_tvalid,
  output wire                       s_axis_ph_tready,
  // Candidates.
  input  wire [32*NumPreu-1:0]      s_axis_cand_tdata,
  input  wire [4*NumPreu-1:0]       s_axis_cand_tkeep,
  input  wire                       s_axis_cand_tvalid,
  output wire                       s_axis_cand_tready,
  // Hit points in.
  input  wire [HpRecW-1:0]          s_axis_hp_tdata,
  input  wire                       s_axis_hp_tvalid,
  output wire                       s_axis_hp_tready,
  // Results out.
  output wire [HpRecW-1:0]          m_axis_tdata,
  output wire                       m_axis_tuser,
  output wire                       m_axis_tlast,
  output wire                       m_axis_tvalid,
  input  wire                       m_axis_tready,
  output wire                       irq_o
);

  // RTL version: major.minor.patch in bits 23:16, 15:8, 7:0 (VERSION register, docs).
  localparam [31:0] PREE_VERSION = 32'h0002_0000;
  localparam CtrW     = 48;
  localparam NCNT     = 7 + NumPreu;
  localparam P        = PhotonsPerCycle;
  localparam PH_DEPTH = 1 << PhFifoAW;
  localparam RING     = 1 << RingAW;
  localparam [31:0] IDX_ROOM = (32'd1 << IdxAW) - NumPreu;   // free entries a beat needs
  localparam [CountW-1:0] ROOM = IDX_ROOM[CountW-1:0];
  localparam [31:0] FLY_LIM = RING - P;                      // photons in flight before a give
  localparam [CountW-1:0] FLY = FLY_LIM[CountW-1:0];

  generate
    if (PhotonsPerCycle < 1 || PhotonsPerCycle > 8) begin : g_bad_ppc
      pree_axi_photons_per_cycle_is_1_to_8 u_fail ();
    end
    if ((1 << RingAW) <= 2 * PhotonsPerCycle) begin : g_bad_ringaw
      pree_axi_ring_holds_more_than_twice_photons_per_cycle u_fail ();
    end
    if (PxAW > 31 || HpAW > 31 || CntW > 31) begin : g_bad_widths
      pree_axi_addresses_and_counts_fit_32_bit_slots u_fail ();
    end
    if (CountW > 32 || CountW < IdxAW + PhFifoAW + $clog2(PhotonsPerCycle) + 1 ||
        CountW <= RingAW) begin : g_bad_countw
      pree_axi_countw_is_32_at_most_and_idxaw_plus_phfifoaw_plus_log2_ppc_plus_1_at_least u_fail ();
    end
  endgenerate

  wire rst_n;
  pree_reset_sync #(.Stages(2)) u_rst (.clk_i(aclk), .arst_ni(aresetn), .rst_no(rst_n));

  // ===============================================================================================
  // Registers (AXI4-Lite).
  wire        wr, rd;
  wire [11:0] wr_addr, rd_addr;
  wire [31:0] wr_data;
  wire [3:0]  wr_strb;
  reg  [31:0] rd_data;

  pree_axil_slave #(.AddrW(12)) u_axil (
    .clk_i(aclk), .rst_ni(rst_n),
    .awaddr_i(s_axil_awaddr), .awvalid_i(s_axil_awvalid), .awready_o(s_axil_awready),
    .wdata_i(s_axil_wdata), .wstrb_i(s_axil_wstrb), .wvalid_i(s_axil_wvalid),
    .wready_o(s_axil_wready), .bresp_o(s_axil_bresp), .bvalid_o(s_axil_bvalid),
    .bready_i(s_axil_bready), .araddr_i(s_axil_araddr), .arvalid_i(s_axil_arvalid),
    .arready_o(s_axil_arready), .rdata_o(s_axil_rdata), .rresp_o(s_axil_rresp),
    .rvalid_o(s_axil_rvalid), .rready_i(s_axil_rready),
    .wr_o(wr), .wr_addr_o(wr_addr), .wr_data_o(wr_data), .wr_strb_o(wr_strb),
    .rd_o(rd), .rd_addr_o(rd_addr), .rd_data_i(rd_data));

  // A 32-bit register written under the byte strobes.
  function [31:0] strobe;
    input [31:0] old, new_v;
    input [3:0]  s;
    integer b;
    begin
      for (b = 0; b < 4; b = b + 1) strobe[8*b +: 8] = s[b] ? new_v[8*b +: 8] : old[8*b +: 8];
    end
  endfunction

  // Register numbers (byte address / 4), R_<name>: generated from the register map
  // rtl/regs/pree_axi.rdl (make regs).
  `include "pree_axi_regs.vh"
  // Commands (CMD register).
  localparam [2:0] C_RAD = 3'd1, C_HP_READ = 3'd2, C_PX_CLEAR = 3'd3, C_PX_READ = 3'd4;
  // Command engine states.
  localparam [2:0] S_IDLE = 3'd0,      // streams move; a command may start
                   S_HP_READ = 3'd1,   // hit points [HP_PTR, + HP_COUNT) to m_axis
                   S_PX_READ = 3'd2,   // pixels [PX_BASE, + PX_COUNT) to m_axis
                   S_PX_CLEAR = 3'd3,  // pixels [PX_BASE, + PX_COUNT) to +0
                   S_RAD_START = 3'd4, // radiance mode applied: pulse rad_start_i
                   S_RAD_WAIT = 3'd5;  // the pass runs: wait for idle_o, back to update mode

  reg  [2:0]  state_q, state_d;
  reg         cnt_en_q;
  reg  [1:0]  irq_en_q, irq_q, err_q;
  reg  [31:0] ne_q, alpha_q, kappa_q, n_hit_q, hp_ptr_q, hp_cnt_q, px_base_q, px_cnt_q;
  reg  [31:0] cnt_hi_q;
  reg  [CountW-1:0] ph_in_q;
  reg         mode_q, batch_q;
  wire        all_idle, core_idle, cmd_done, batch_done;
  wire [CountW-1:0] core_done;
  wire [NCNT*CtrW-1:0] cnt;
  reg  [CountW-1:0] cum_in_q, wr_cnt_q;   // candidates announced by photons in; written
  // The running counts as registers read them: zero-extended to 32 bits.
  wire [31+CountW:0] ph_in_x = {32'd0, ph_in_q}, done_x = {32'd0, core_done},
                     cand_in_x = {32'd0, wr_cnt_q};

  wire        idle_wr  = wr && all_idle;   // constants and commands: only while idle
  wire [9:0]  wreg     = wr_addr[11:2];
  wire        range_ok;                    // the command reads only what was written (below)
  wire        cmd_ok   = idle_wr && wreg == R_CMD && wr_data[2:0] >= C_RAD &&
                         wr_data[2:0] <= C_PX_READ && range_ok;
  wire        cmd_bad  = wr && wreg == R_CMD && !cmd_ok;
  wire        const_wr = wr && (wreg == R_NE || wreg == R_ALPHA || wreg == R_KAPPA ||
                                wreg == R_N_HIT || wreg == R_HP_PTR || wreg == R_HP_COUNT ||
                                wreg == R_PX_BASE || wreg == R_PX_COUNT);
  wire        ph_big;                      // a photon with N^P above the index table's room
  wire        hp_take;

  always @(posedge aclk or negedge rst_n) begin
    if (!rst_n) begin
      cnt_en_q <= 1'b0; irq_en_q <= 2'b00; irq_q <= 2'b00; err_q <= 2'b00;
      ne_q <= 32'd0; alpha_q <= 32'd0; kappa_q <= 32'd0; n_hit_q <= 32'd0;
      hp_ptr_q <= 32'd0; hp_cnt_q <= 32'd0; px_base_q <= 32'd0; px_cnt_q <= 32'd0;
    end else begin
      if (wr && wreg == R_CTRL)   cnt_en_q <= wr_strb[0] ? wr_data[0] : cnt_en_q;
      if (wr && wreg == R_IRQ_EN) irq_en_q <= wr_strb[0] ? wr_data[1:0] : irq_en_q;
      irq_q <= (irq_q & ~((wr && wreg == R_IRQ_STATUS && wr_strb[0]) ? wr_data[1:0] : 2'b00))
               | {cmd_done, batch_done};
      err_q <= (err_q & ~((wr && wreg == R_ERR && wr_strb[0]) ? wr_data[1:0] : 2'b00))
               | {ph_big, cmd_bad || (const_wr && !all_idle)};
      if (idle_wr) begin
        if (wreg == R_NE)       ne_q      <= strobe(ne_q, wr_data, wr_strb);
        if (wreg == R_ALPHA)    alpha_q   <= strobe(alpha_q, wr_data, wr_strb);
        if (wreg == R_KAPPA)    kappa_q   <= strobe(kappa_q, wr_data, wr_strb);
        if (wreg == R_N_HIT)    n_hit_q   <= strobe(n_hit_q, wr_data, wr_strb);
        if (wreg == R_HP_COUNT) hp_cnt_q  <= strobe(hp_cnt_q, wr_data, wr_strb);
        if (wreg == R_PX_BASE)  px_base_q <= strobe(px_base_q, wr_data, wr_strb);
        if (wreg == R_PX_COUNT) px_cnt_q  <= strobe(px_cnt_q, wr_data, wr_strb);
      end
      if (idle_wr && wreg == R_HP_PTR) hp_ptr_q <= strobe(hp_ptr_q, wr_data, wr_strb);
      else if (hp_take)                hp_ptr_q <= hp_ptr_q + 32'd1;
    end
  end

  // Read data; a counter's high half is latched when its low half is read.
  wire [9:0] rreg = rd_addr[11:2];
  wire [7:0] rcnt = rreg[8:1] - 8'h20;    // counter number at byte 0x100 + 8k
  reg  [CtrW-1:0] cnt_sel;
  always @* begin : rd_mux
    integer k;
    cnt_sel = {CtrW{1'b0}};
    for (k = 0; k < NCNT; k = k + 1)
      if (rcnt == k[7:0]) cnt_sel = cnt[k*CtrW +: CtrW];
    rd_data = 32'd0;
    if (rreg[9:6] == 4'h1 && {24'd0, rcnt} < NCNT) begin
      rd_data = rreg[0] ? cnt_hi_q : cnt_sel[31:0];
    end else begin
      case (rreg)
        R_VERSION:    rd_data = PREE_VERSION;
        R_CONFIG0:    rd_data = {Datapath != 0, 2'b00, IdxAW[4:0], 3'b000, PxAW[4:0], 3'b000,
                                 HpAW[4:0], NumPreu[7:0]};
        R_CONFIG1:    rd_data = {PhotonsPerCycle[7:0], 3'b000, CntW[4:0], 3'b000, PxBankW[4:0],
                                 3'b000, HpBankW[4:0]};
        R_CTRL:       rd_data = {31'd0, cnt_en_q};
        R_STATUS:     rd_data = {27'd0, batch_q, state_q != S_IDLE, mode_q, core_idle, all_idle};
        R_IRQ_EN:     rd_data = {30'd0, irq_en_q};
        R_IRQ_STATUS: rd_data = {30'd0, irq_q};
        R_ERR:        rd_data = {30'd0, err_q};
        R_NE:         rd_data = ne_q;
        R_ALPHA:      rd_data = alpha_q;
        R_KAPPA:      rd_data = kappa_q;
        R_N_HIT:      rd_data = n_hit_q;
        R_HP_PTR:     rd_data = hp_ptr_q;
        R_HP_COUNT:   rd_data = hp_cnt_q;
        R_PX_BASE:    rd_data = px_base_q;
        R_PX_COUNT:   rd_data = px_cnt_q;
        R_PH_IN:      rd_data = ph_in_x[31:0];
        R_PH_DONE:    rd_data = done_x[31:0];
        R_CAND_IN:    rd_data = cand_in_x[31:0];
        default:      rd_data = 32'd0;
      endcase
    end
  end

  always @(posedge aclk or negedge rst_n) begin
    if (!rst_n) cnt_hi_q <= 32'd0;
    else if (rd && rreg[9:6] == 4'h1 && !rreg[0])
      cnt_hi_q <= {{(64-CtrW){1'b0}}, cnt_sel[CtrW-1:32]};
  end

  assign irq_o = |(irq_q & irq_en_q);

  // ===============================================================================================
  // Photon FIFO, one entry a beat with a non-empty slot: {data, N^P, candidate end S_k + N_k}
  // per slot (an empty slot keeps the end before it). The head beat's photons are given to
  // pree_top, in slot order, as soon as their candidates are written (gone_q: those given), so a
  // beat whose photons' candidates together exceed the index table never waits for itself.
  reg  [P*192-1:0]     phf_data_q [0:PH_DEPTH-1];
  reg  [P*CntW-1:0]    phf_n_q    [0:PH_DEPTH-1];
  reg  [P*CountW-1:0]  phf_end_q  [0:PH_DEPTH-1];
  reg  [PhFifoAW:0]    phf_wp_q, phf_rp_q;
  reg  [P-1:0]         gone_q;             // the head beat's slots given to pree_top
  reg  [CountW-1:0] ring_q [0:RING-1];     // candidate end of photon g mod RING, given to pree_top
  reg  [CountW-1:0] given_q, ret_q;        // photons given; candidates retired
  reg  [CountW-1:0] done_q;                // photons_done_o as ret_q last followed it
  wire [PhFifoAW-1:0] rp = phf_rp_q[PhFifoAW-1:0];
  wire [PhFifoAW-1:0] wp = phf_wp_q[PhFifoAW-1:0];
  wire phf_empty = phf_wp_q == phf_rp_q;
  wire phf_full  = phf_wp_q == {~phf_rp_q[PhFifoAW], phf_rp_q[PhFifoAW-1:0]};
  wire ph_take = s_axis_ph_tvalid && s_axis_ph_tready;
  assign s_axis_ph_tready = rst_n && !phf_full && state_q == S_IDLE;

  // The beat on s_axis_ph: its slots' N^P, which are photons (N^P > 0), their ends.
  reg  [P*192-1:0]    in_data;
  reg  [P*CntW-1:0]   in_n;
  reg  [P*CountW-1:0] in_end;
  reg  [P-1:0]        in_full;              // the slot holds a photon
  reg  [CountW-1:0]   in_sum;               // the beat's candidates
  reg  [CountW-1:0]   in_cnt;               // the beat's photons
  reg                 in_big;               // a slot's N^P above the index table's room
  reg  [CntW-1:0]     in_nx_top;            // the zero extension's top (unused)
  always @* begin : ph_slots
    integer s;
    reg [CntW+CountW-1:0] nx;
    in_sum = {CountW{1'b0}}; in_cnt = {CountW{1'b0}}; in_big = 1'b0; in_nx_top = {CntW{1'b0}};
    for (s = 0; s < P; s = s + 1) begin
      in_data[s*192 +: 192] = s_axis_ph_tdata[256*s +: 192];
      in_n[s*CntW +: CntW] = s_axis_ph_tdata[256*s + 192 +: CntW];
      nx = {{CountW{1'b0}}, s_axis_ph_tdata[256*s + 192 +: CntW]};
      in_full[s] = s_axis_ph_tdata[256*s + 192 +: CntW] != {CntW{1'b0}};
      in_big = in_big || {{(32-CntW){1'b0}}, s_axis_ph_tdata[256*s + 192 +: CntW]} > IDX_ROOM;
      in_sum = in_sum + nx[CountW-1:0];      // N^P as a count (at most ROOM unless ph_big)
      in_nx_top = in_nx_top | nx[CntW+CountW-1:CountW];
      in_end[s*CountW +: CountW] = cum_in_q + in_sum;
      in_cnt = in_cnt + {{(CountW-1){1'b0}}, in_full[s]};
    end
  end
  wire ph_push = ph_take && |in_full;
  assign ph_big = ph_take && in_big;

  // The head beat: the slots still to give, those whose candidates are all written (an end not
  // ahead of the candidates written; distances modulo 2^CountW, kept below 2^(CountW-1) by the
  // parameter check) and, in slot order, where each given one goes in the ring.
  wire [P*CountW-1:0] head_end = phf_end_q[rp];
  wire [P*CntW-1:0]   head_n   = phf_n_q[rp];
  reg  [P-1:0]        todo, give, left;      // to give; given in this offer; left after it
  reg  [P*CntW-1:0]   give_n;                // N^P to pree_top: 0 in the slots not given
  reg  [P*IdxAW-1:0]  give_p;                // p_k = -(S_k + N_k)
  reg  [P*RingAW-1:0] ring_wa;
  reg  [CountW-1:0]   give_cnt;
  always @* begin : head_slots
    integer s;
    reg [CountW-1:0] ahead;
    give_cnt = {CountW{1'b0}};
    for (s = 0; s < P; s = s + 1) begin
      ahead = wr_cnt_q - head_end[s*CountW +: CountW];
      todo[s] = head_n[s*CntW +: CntW] != {CntW{1'b0}} && !gone_q[s];
      give[s] = todo[s] && !ahead[CountW-1];
      left[s] = todo[s] && ahead[CountW-1];
      give_n[s*CntW +: CntW] = give[s] ? head_n[s*CntW +: CntW] : {CntW{1'b0}};
      give_p[s*IdxAW +: IdxAW] = -head_end[s*CountW +: IdxAW];
      ring_wa[s*RingAW +: RingAW] = given_q[RingAW-1:0] + give_cnt[RingAW-1:0];
      give_cnt = give_cnt + {{(CountW-1){1'b0}}, give[s]};
    end
  end

  wire [CountW-1:0] in_flight = given_q - core_done;
  wire        core_ready;
  wire        core_valid = !phf_empty && |give && in_flight < FLY && state_q == S_IDLE;
  wire        core_take = core_valid && core_ready;
  wire        head_pop = core_take && !(|left);
  wire [RingAW-1:0] last_done = core_done[RingAW-1:0] - {{(RingAW-1){1'b0}}, 1'b1};

  always @(posedge aclk or negedge rst_n) begin
    if (!rst_n) begin
      phf_wp_q <= {(PhFifoAW+1){1'b0}}; phf_rp_q <= {(PhFifoAW+1){1'b0}}; gone_q <= {P{1'b0}};
      cum_in_q <= {CountW{1'b0}}; ph_in_q <= {CountW{1'b0}}; given_q <= {CountW{1'b0}};
      ret_q <= {CountW{1'b0}}; done_q <= {CountW{1'b0}}; batch_q <= 1'b0;
    end else begin
      if (ph_push) phf_wp_q <= phf_wp_q + 1'b1;
      if (ph_push) cum_in_q <= cum_in_q + in_sum;
      if (ph_take) ph_in_q <= ph_in_q + in_cnt;
      if (head_pop) phf_rp_q <= phf_rp_q + 1'b1;
      if (core_take) gone_q <= head_pop ? {P{1'b0}} : gone_q | give;
      if (core_take) given_q <= given_q + give_cnt;
      // Candidates retired: the end of the last photon done, followed whenever photons_done_o
      // moves, by one photon or several (never from its value: it returns to 0 when it wraps).
      done_q <= core_done;
      if (core_done != done_q) ret_q <= ring_q[last_done];
      batch_q <= (batch_q && !batch_done) || (ph_take && s_axis_ph_tlast);
    end
  end

  always @(posedge aclk) begin : ph_store
    integer s;
    if (ph_push) begin
      phf_data_q[wp] <= in_data;
      phf_n_q[wp]   <= in_n;
      phf_end_q[wp] <= in_end;
    end
    for (s = 0; s < P; s = s + 1)
      if (core_take && give[s]) ring_q[ring_wa[s*RingAW +: RingAW]] <= head_end[s*CountW +: CountW];
  end

  // ===============================================================================================
  // Candidates into the index table: candidate s at entry ~s.
  reg  [NumPreu-1:0]       idx_we;
  reg  [NumPreu*IdxAW-1:0] idx_addr;
  reg  [NumPreu*HpAW-1:0]  idx_data;
  reg  [CountW-1:0]        cand_n;
  wire [CountW-1:0] used = wr_cnt_q - ret_q;
  assign s_axis_cand_tready = rst_n && state_q == S_IDLE && used <= ROOM;
  wire cand_take = s_axis_cand_tvalid && s_axis_cand_tready;

  always @* begin : cand_lanes
    integer j;
    reg [IdxAW-1:0] s;
    cand_n = {CountW{1'b0}};
    for (j = 0; j < NumPreu; j = j + 1) begin
      s = wr_cnt_q[IdxAW-1:0] + cand_n[IdxAW-1:0];
      idx_we[j] = cand_take && (&s_axis_cand_tkeep[4*j +: 4]);
      idx_addr[j*IdxAW +: IdxAW] = ~s;
      idx_data[j*HpAW +: HpAW] = s_axis_cand_tdata[32*j +: HpAW];
      if (&s_axis_cand_tkeep[4*j +: 4]) cand_n = cand_n + 1'b1;
    end
  end

  always @(posedge aclk or negedge rst_n) begin
    if (!rst_n)         wr_cnt_q <= {CountW{1'b0}};
    else if (cand_take) wr_cnt_q <= wr_cnt_q + cand_n;
  end

  // ===============================================================================================
  // Command engine: reads to m_axis (one beat a cycle: the RAM's held output is the first stage,
  // the m_axis register the second), pixel clears, the radiance pass.
  reg  [31:0] ci_q;                   // items issued
  reg         rd_pend_q, rd_last_q;   // a read result waits in the RAM output
  reg         m_valid_q, m_last_q, m_user_q;
  reg  [HpRecW-1:0] m_data_q;
  wire [PxAW+191+StateW:0] hp_rdata;
  wire [95:0] px_rdata;
  wire        rd_state = state_q == S_HP_READ || state_q == S_PX_READ;
  wire [31:0] cmd_n    = state_q == S_HP_READ ? hp_cnt_q : px_cnt_q;
  wire        more     = ci_q != cmd_n;
  wire        move     = rd_pend_q && (!m_valid_q || m_axis_tready);
  wire        issue    = rd_state && more && (!rd_pend_q || move);
  wire        px_clr   = state_q == S_PX_CLEAR && more;
  assign hp_take  = s_axis_hp_tvalid && s_axis_hp_tready;
  assign s_axis_hp_tready = rst_n && all_idle;
  assign cmd_done = (rd_state && !more && !rd_pend_q && !m_valid_q) ||
                    (state_q == S_PX_CLEAR && !more) || (state_q == S_RAD_WAIT && core_idle);

  always @* begin
    state_d = state_q;
    case (state_q)
      S_IDLE:      if (cmd_ok) state_d = wr_data[2:0] == C_RAD     ? S_RAD_START :
                                         wr_data[2:0] == C_HP_READ ? S_HP_READ :
                                         wr_data[2:0] == C_PX_READ ? S_PX_READ :
                                         wr_data[2:0] == C_PX_CLEAR ? S_PX_CLEAR : S_IDLE;
      S_RAD_START: state_d = S_RAD_WAIT;
      default:     if (cmd_done) state_d = S_IDLE;
    endcase
  end

  always @(posedge aclk or negedge rst_n) begin
    if (!rst_n) begin
      state_q <= S_IDLE; mode_q <= 1'b0; ci_q <= 32'd0;
      rd_pend_q <= 1'b0; rd_last_q <= 1'b0; m_valid_q <= 1'b0; m_last_q <= 1'b0; m_user_q <= 1'b0;
    end else begin
      state_q <= state_d;
      mode_q  <= state_d == S_RAD_START || state_d == S_RAD_WAIT;
      if (state_q == S_IDLE) ci_q <= 32'd0;
      else if (issue || px_clr) ci_q <= ci_q + 32'd1;
      if (issue) rd_last_q <= ci_q + 32'd1 == cmd_n;
      rd_pend_q <= issue || (rd_pend_q && !move);
      m_valid_q <= move || (m_valid_q && !m_axis_tready);
      if (move) begin
        m_last_q <= rd_last_q;
        m_user_q <= state_q == S_PX_READ;
      end
    end
  end

  always @(posedge aclk or negedge rst_n) begin
    if (!rst_n)    m_data_q <= {HpRecW{1'b0}};
    else if (move) m_data_q <= state_q == S_PX_READ ? {{(HpRecW-96){1'b0}}, px_rdata}
                                                    : {{(32-PxAW){1'b0}}, hp_rdata};
  end

  assign m_axis_tdata  = m_data_q;
  assign m_axis_tuser  = m_user_q;
  assign m_axis_tlast  = m_last_q;
  assign m_axis_tvalid = m_valid_q;

  // ===============================================================================================
  // Written ranges: hit points [0, hp_wr_q) have been loaded since reset (s_axis_hp extends the
  // range when it writes at its end), pixels [0, px_wr_q) cleared (CMD 3 extends the range when
  // it starts inside it or at its end). A command that would read beyond them (CMD 2 over
  // [HP_PTR, + HP_COUNT), CMD 1 over [0, N_HIT), CMD 4 over [PX_BASE, + PX_COUNT)) is refused as
  // an unknown one is (ERR bit 0), so no memory word the host never wrote leaves the wrapper and
  // nothing relies on what the RAMs hold after reset.
  reg  [HpAW:0] hp_wr_q;
  reg  [PxAW:0] px_wr_q;
  wire [32:0] hp_wr_x = {{(32-HpAW){1'b0}}, hp_wr_q};
  wire [32:0] px_wr_x = {{(32-PxAW){1'b0}}, px_wr_q};
  wire [32:0] hp_end  = {1'b0, hp_ptr_q} + {1'b0, hp_cnt_q};
  wire [32:0] px_end  = {1'b0, px_base_q} + {1'b0, px_cnt_q};
  wire [32:0] px_cap  = 33'd1 << PxAW;
  wire [32:0] px_new  = px_end > px_cap ? px_cap : px_end;   // a clear's end, within the memory
  wire        hp_grow = hp_take && !hp_wr_q[HpAW] && {1'b0, hp_ptr_q} == hp_wr_x;
  wire        px_grow = cmd_ok && wr_data[2:0] == C_PX_CLEAR && {1'b0, px_base_q} <= px_wr_x &&
                        px_new > px_wr_x;
  assign range_ok = wr_data[2:0] == C_HP_READ ? hp_end <= hp_wr_x :
                    wr_data[2:0] == C_RAD     ? {1'b0, n_hit_q} <= hp_wr_x :
                    wr_data[2:0] == C_PX_READ ? px_end <= px_wr_x : 1'b1;

  always @(posedge aclk or negedge rst_n) begin
    if (!rst_n) begin
      hp_wr_q <= {(HpAW+1){1'b0}};
      px_wr_q <= {(PxAW+1){1'b0}};
    end else begin
      if (hp_grow) hp_wr_q <= hp_wr_q + 1'b1;
      if (px_grow) px_wr_q <= px_new[PxAW:0];
    end
  end

  assign all_idle   = core_idle && phf_empty && state_q == S_IDLE && wr_cnt_q == cum_in_q &&
                      !m_valid_q;
  assign batch_done = batch_q && all_idle;

  // ===============================================================================================
  // The engine.
  wire [31:0] hp_a = hp_ptr_q + (state_q == S_HP_READ ? ci_q : 32'd0);
  wire [31:0] px_a = px_base_q + ci_q;
  wire [HpAW-1:0] n_hit = n_hit_q[HpAW-1:0];

  pree_top #(
    .NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(HpBankW), .IdxAW(IdxAW), .PxAW(PxAW),
    .PxBankW(PxBankW), .CntW(CntW), .Datapath(Datapath), .CtrW(CtrW), .PipeFast(PipeFast),
    .AddStages(AddStages), .MulStages(MulStages), .SqrStages(SqrStages), .DivStages(DivStages),
    .U2fStages(U2fStages), .WaccStages(WaccStages), .PhotonsPerCycle(P), .CountW(CountW)
  ) u_top (
    .clk_i(aclk), .rst_ni(rst_n),
    .mode_i(mode_q), .cnt_en_i(cnt_en_q), .ne_i(ne_q), .alpha_i(alpha_q), .kappa_i(kappa_q),
    .rad_start_i(state_q == S_RAD_START), .n_hit_i(n_hit), .idle_o(core_idle),
    .ph_valid_i(core_valid), .ph_ready_o(core_ready), .ph_data_i(phf_data_q[rp]),
    .ph_paddr_i(give_p), .ph_n_i(give_n), .photons_done_o(core_done),
    .idx_we_i(idx_we), .idx_addr_i(idx_addr), .idx_data_i(idx_data),
    .hp_we_i(hp_take), .hp_re_i(issue && state_q == S_HP_READ), .hp_addr_i(hp_a[HpAW-1:0]),
    .hp_wdata_i(s_axis_hp_tdata[PxAW+191+StateW:0]), .hp_rdata_o(hp_rdata),
    .px_we_i(px_clr), .px_re_i(issue && state_q == S_PX_READ), .px_addr_i(px_a[PxAW-1:0]),
    .px_wdata_i(96'd0), .px_rdata_o(px_rdata), .cnt_o(cnt));

  // Bits the engine does not use: the slots' upper bits, the byte offsets, the counts' tops.
  wire unused_bits = ^{ph_unused, in_nx_top, s_axis_hp_tdata[HpRecW-1:PxAW+192+StateW],
                       wr_addr[1:0], rd_addr[1:0], n_hit_q[31:HpAW], hp_a[31:HpAW], px_a[31:PxAW],
                       cand_unused, ph_in_x[31+CountW:32], done_x[31+CountW:32],
                       cand_in_x[31+CountW:32], px_new[32:PxAW+1]};
  reg [NumPreu*(32-HpAW)-1:0] cand_unused;
  reg [P*(64-CntW)-1:0]       ph_unused;   // each slot's N^P top and reserved word
  always @* begin : cand_tops
    integer j;
    for (j = 0; j < NumPreu; j = j + 1)
      cand_unused[j*(32-HpAW) +: 32-HpAW] = s_axis_cand_tdata[32*j+HpAW +: 32-HpAW];
    for (j = 0; j < P; j = j + 1)
      ph_unused[j*(64-CntW) +: 64-CntW] = s_axis_ph_tdata[256*j+192+CntW +: 64-CntW];
  end

endmodule

`default_nettype wire
