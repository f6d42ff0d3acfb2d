// SPDX-License-Identifier: Apache-2.0
// pree_top: the progressive radiance estimation engine (paper 000 Sec. IV, Fig. 5): NumPreu
// PREUs, the AFTSO-HpUOC dispatcher (update mode), the ADISO-REC leaping-address generator
// (radiance mode), the hit-point memory, the index table and the pixel memory, with hazard
// detection so that results never depend on timing. docs/pree_top.md is the user's manual:
// interfaces, host protocol, timing diagrams, memory organisation, hazards, the radiance order,
// the counters.
//
// Modes (mode_i; change it, alpha_i and kappa_i only while idle_o is high): 0 update, photons in
// on ph_* (up to PhotonsPerCycle a cycle; photon k's N^P candidates in the index table from
// p_addr, written through idx_*, up to NumPreu entries a cycle in distinct banks); 1 radiance,
// a pulse on rad_start_i hands every hit point in [0, n_hit_i) to a PREU once, which adds its
// flux to its pixel. Host ports hp_* and px_* only while idle; read data a cycle after the enable.
//
// Pipeline (a lane l of a stage feeds PREU l):
//   A  the controller's offer, read in lane order, one lane per bank a cycle (pree_top_read):
//      update, the index table; radiance, the hit-point memory. PipeFast 0: A reads the
//      controller's outputs when B empties in this cycle. PipeFast 1: A reads a two-offer buffer
//      (pree_top_offer) when R is empty or moves on; the controllers' stall is its full flag.
//   B  the read results (R) issue in lane order, a prefix of the pending lanes, each free of a
//      hazard (its key, the hit point or the pixel, in flight), a same-key earlier lane and a
//      same-bank one (pree_top_issue). Update: issue = the hit-point read; radiance: the PREU.
//      PipeFast 1: R moves into a two-slot queue and B issues from its older slot, whose hazard
//      and lane pairs are precomputed a cycle ahead (pree_top_queue); the hit-point memory is read
//      for each lane first of its bank (the issue's one candidate there) and the counters count a
//      clock later. host/cosim_shadow.c models both flows cycle for cycle.
//   C  update: the hit-point data and the photon into the PREU. Results are written back:
//      update, the state when accepted; radiance, the pixel sum.
// Hazard windows follow the PREU's latencies (rtl/pree_preu_plan.vh): update 1 + its update
// latency (11 / 13 paper / stable, 49 / 53 with PipeFast 1); radiance the add's latency + 1 (3, or
// 9). ADISO-REC's depth is the radiance latency (12, or 64). So, per hit point, updates happen
// in photon order, and per pixel, contributions add in ADISO issue order (model/pree/adiso_order.c).
// Memories (pree_ram_banks of pree_ram_sdp): the index table in NumPreu banks (address mod
// NumPreu); the hit points in 2^HpBankW banks (pree_top_hpmem; bank: rtl/pree_hp_bank.vh); the
// pixel sums in 2^PxBankW banks (the pixel's low bits).
// Counters (cnt_o, pree_counters, while cnt_en_i): update and radiance cycles, haz, dup, bank,
// abank, starve, then the operations into each PREU; photons_done_o counts photons whose last
// index entry has been read (the host may reuse their entries; CountW bits, it wraps: compare
// it with the host's own counts modulo 2^CountW).
`default_nettype none

module pree_top #(
  parameter NumPreu = 4,    // PREUs (a power of two: 1, 2, 4, ...)
  parameter HpAW    = 18,   // hit-point address bits
  parameter HpBankW = 4,    // log2 of the hit-point banks (1 .. HpAW/2)
  parameter IdxAW   = 12,   // index-table address bits (> log2 NumPreu, > 1)
  parameter PxAW    = 17,   // pixel address bits
  parameter PxBankW = 4,    // log2 of the pixel banks (1 .. PxAW-1)
  parameter CntW    = 16,   // bits of a photon's candidate count N^P
  parameter Datapath = 0,   // PREU datapath: 0 paper, 1 stable
  parameter CtrW    = 48,   // bits of each performance counter (cnt_o)
  parameter PipeFast = 0,   // PREU units: 0 the paper's, 1 the deep plans (docs/fpga.md)
  // The PREU units' stages, passed on (pree_preu; 0: the unit's default); the windows follow.
  parameter AddStages  = 0,
  parameter MulStages  = 0, SqrStages = 0, DivStages = 0, U2fStages = 0, WaccStages = 0,
  parameter PhotonsPerCycle = 1, // photons AFTSO-HpUOC takes per cycle (1 .. 8; 1 = the paper)
  parameter CountW  = 32,   // bits of photons_done_o (a running count that wraps)
  parameter StateW  = (Datapath != 0) ? 320 : 160  // do not override: set by Datapath
) (
  input  wire                       clk_i,
  input  wire                       rst_ni,
  // Mode and control.
  input  wire                       mode_i,
  input  wire                       cnt_en_i,
  input  wire [31:0]                ne_i,          // N_emitted as binary32 (radiance)
  input  wire [31:0]                alpha_i,       // alpha as binary32 (update, paper datapath)
  input  wire [31:0]                kappa_i,       // (1 - alpha) / alpha (update, stable datapath)
  input  wire                       rad_start_i,
  input  wire [HpAW-1:0]            n_hit_i,
  output wire                       idle_o,
  // Photon stream (update mode), PhotonsPerCycle slots side by side, one valid/ready for all;
  // a slot's ph_data_i = {phi b, g, r, pos z, y, x}.
  input  wire                       ph_valid_i,
  output wire                       ph_ready_o,
  input  wire [PhotonsPerCycle*192-1:0]   ph_data_i,
  input  wire [PhotonsPerCycle*IdxAW-1:0] ph_paddr_i,
  input  wire [PhotonsPerCycle*CntW-1:0]  ph_n_i,
  output wire [CountW-1:0]          photons_done_o,
  // Index-table load port: entry j in bits [j*W +: W].
  input  wire [NumPreu-1:0]         idx_we_i,
  input  wire [NumPreu*IdxAW-1:0]   idx_addr_i,
  input  wire [NumPreu*HpAW-1:0]    idx_data_i,
  // Host hit-point port: {pixel, f b g r, pos z y x, state} (state: paper {n, r2, tau b g r},
  // stable {k, w, T b g r}).
  input  wire                       hp_we_i,
  input  wire                       hp_re_i,
  input  wire [HpAW-1:0]            hp_addr_i,
  input  wire [PxAW+191+StateW:0]   hp_wdata_i,
  output wire [PxAW+191+StateW:0]   hp_rdata_o,
  // Host pixel port: {b, g, r}.
  input  wire                       px_we_i,
  input  wire                       px_re_i,
  input  wire [PxAW-1:0]            px_addr_i,
  input  wire [95:0]                px_wdata_i,
  output wire [95:0]                px_rdata_o,
  // Counters.
  output wire [(7+NumPreu)*CtrW-1:0] cnt_o
);

`include "pree_preu_lat.vh"
`include "pree_hp_bank.vh"

  localparam LANE_W    = $clog2(NumPreu);
  // The index table's banks: NumPreu, and two for one PREU, so that no bank field is zero bits wide.
  localparam IDX_BANK_W = (LANE_W > 0) ? LANE_W : 1;
  localparam IDX_BANKS  = 1 << IDX_BANK_W;
  localparam IDX_ROW_W  = IdxAW - IDX_BANK_W;
  localparam KEY_W     = HpAW > PxAW ? HpAW : PxAW;          // hazard key: hit point or pixel
  localparam ABANK_W   = IDX_BANK_W > HpBankW ? IDX_BANK_W : HpBankW; // stage-A bank number
  localparam BBANK_W   = HpBankW > PxBankW ? HpBankW : PxBankW; // stage-B bank number
  localparam CONST_W   = PxAW + 192;                          // {pixel, f, pos}
  localparam STATE_W   = StateW;                              // paper {n, r2, tau}, stable {k, w, T}
  // The PREU's latencies (rtl/pree_preu_lat.vh) and the hazard windows they set (public to the
  // co-simulation host): update, issue + C + the update stages (11 paper / 13 stable with
  // PipeFast 0); radiance, from the pixel read (lreq, RAD_LAT - AddStages - 1 after issue) to
  // its write (RAD_LAT after issue): the add's latency + 1 (3 with PipeFast 0). RAD_LAT is also
  // ADISO-REC's depth, which sets the radiance pass's issue order (public, for the host's check).
  localparam RAD_LAT /*verilator public*/ = RAD_LATENCY;
  localparam WIN_UPD /*verilator public*/ = 1 + UPD_LATENCY;
  localparam WIN_RAD /*verilator public*/ = LAT_ADD + 1;
  // PipeFast 1's registered flow control (public to the co-simulation host): A's two-offer buffer
  // (pree_top_offer) and B's two-slot queue (pree_top_queue).
  localparam REG_FLOW /*verilator public*/ = (PipeFast != 0) ? 1 : 0;
  localparam A_REG   = REG_FLOW;
  localparam PH_W      = 192;
  // A lane's record in B: update {index entry, photon} or radiance {f, pos, state} (the pixel is
  // the key), the wider.
  localparam REC_W   = (HpAW + PH_W > 192 + STATE_W) ? HpAW + PH_W : 192 + STATE_W;

  // Parameter checks, whatever the configuration (elaboration fails on a module that does not
  // exist, named after the problem): StateW follows Datapath; NumPreu is a power of two
  // (index-table banks and ADISO groups are cut by bits); Datapath and PipeFast are 0 or 1; each
  // unit's Stages is 0 (its default for PipeFast) or what the unit builds (its header), also for
  // units the datapath leaves out (u2f and wacc are the stable one's); the memories' banks leave
  // rows (HpBankW 1 .. HpAW / 2, PxBankW 1 .. PxAW - 1), and so do the index table's (IdxAW above
  // log2 NumPreu and above 1).
  generate
    if (StateW != ((Datapath != 0) ? 320 : 160)) begin : g_bad_statew
      pree_top_statew_is_set_by_datapath u_fail ();
    end
    if ((1 << LANE_W) != NumPreu) begin : g_bad_numpreu
      pree_top_numpreu_must_be_a_power_of_two u_fail ();
    end
    if (Datapath < 0 || Datapath > 1) begin : g_bad_datapath
      pree_top_datapath_is_0_paper_or_1_stable u_fail ();
    end
    if (PipeFast < 0 || PipeFast > 1) begin : g_bad_pipefast
      pree_top_pipefast_is_0_or_1 u_fail ();
    end
    if (AddStages < 0 || AddStages > 7) begin : g_bad_add
      pree_top_addstages_is_0_or_1_to_7 u_fail ();
    end
    if (MulStages < 0 || MulStages > 8) begin : g_bad_mul
      pree_top_mulstages_is_0_or_1_to_8 u_fail ();
    end
    if (SqrStages < 0 || SqrStages > 6) begin : g_bad_sqr
      pree_top_sqrstages_is_0_or_1_to_6 u_fail ();
    end
    if (DivStages < 0 || DivStages == 1 || DivStages > 31) begin : g_bad_div
      pree_top_divstages_is_0_or_2_to_31 u_fail ();
    end
    if (U2fStages < 0 || U2fStages > 5) begin : g_bad_u2f
      pree_top_u2fstages_is_0_or_1_to_5 u_fail ();
    end
    if (WaccStages < 0 || WaccStages > 5) begin : g_bad_wacc
      pree_top_waccstages_is_0_or_1_to_5 u_fail ();
    end
    if (HpBankW < 1 || 2 * HpBankW > HpAW) begin : g_bad_hpbankw
      pree_top_hpbankw_is_1_to_half_of_hpaw u_fail ();
    end
    if (PxBankW < 1 || PxBankW >= PxAW) begin : g_bad_pxbankw
      pree_top_pxbankw_is_1_to_pxaw_minus_1 u_fail ();
    end
    if (IdxAW <= IDX_BANK_W) begin : g_bad_idxaw
      pree_top_idxaw_is_above_log2_numpreu_and_1 u_fail ();
    end
  endgenerate

  genvar gl, gb;

  // ===============================================================================================
  // Controllers.
  wire                      a_all;      // every lane of the current offer is read by now
  wire                      a_full;     // the controllers' offer is not taken (their stall)
  wire [NumPreu-1:0]        af_valid, af_last;
  wire [NumPreu*IdxAW-1:0]  af_ref;
  wire [NumPreu*PH_W-1:0]   af_data;
  wire [NumPreu-1:0]        af_id_unused;
  wire                      af_ready, af_busy_unused, af_empty;

  // The buffer: 4 entries per photon taken a cycle (the paper's 4 for one photon a cycle).
  pree_aftso_hpuoc #(
    .NumPreu(NumPreu), .BufDepth(4 * PhotonsPerCycle), .DataW(PH_W), .IdW(1), .AddrW(IdxAW),
    .CntW(CntW), .EarlyReady(1), .PhotonsPerCycle(PhotonsPerCycle)
  ) u_aftso (
    .clk_i(clk_i), .rst_ni(rst_ni),
    .in_valid_i(ph_valid_i & ~mode_i), .in_ready_o(af_ready), .in_data_i(ph_data_i),
    .in_id_i({PhotonsPerCycle{1'b0}}), .in_p_addr_i(ph_paddr_i), .in_n_i(ph_n_i),
    .stall_i(mode_i | a_full), .lane_valid_o(af_valid), .lane_ref_addr_o(af_ref),
    .lane_data_o(af_data), .lane_id_o(af_id_unused), .lane_last_o(af_last),
    .busy_o(af_busy_unused), .empty_o(af_empty));

  assign ph_ready_o = af_ready & ~mode_i;

  wire [NumPreu-1:0]       ad_valid;
  wire [NumPreu*HpAW-1:0]  ad_addr;
  wire                     ad_busy;

  pree_adiso_rec #(.NumPreu(NumPreu), .PipeDepth(RAD_LAT), .AddrW(HpAW)) u_adiso (
    .clk_i(clk_i), .rst_ni(rst_ni), .start_i(rad_start_i), .n_hit_i(n_hit_i),
    .stall_i(~mode_i | a_full), .addr_valid_o(ad_valid), .addr_o(ad_addr), .busy_o(ad_busy));

  // ===============================================================================================
  // Stage A: the controller's offer (PipeFast 1: registered, pree_top_offer), read in lane order,
  // one lane per bank a cycle (pree_top_read).
  wire [NumPreu-1:0]         a_valid, a_last;
  wire [NumPreu*ABANK_W-1:0] a_bank;
  wire [NumPreu*IdxAW-1:0]   a_idx;       // update: index-entry addresses
  wire [NumPreu*HpAW-1:0]    a_hp;        // radiance: hit-point addresses
  wire [NumPreu*PH_W-1:0]    a_data;
  wire [NumPreu-1:0]         a_rd;
  wire                       a_short;
  wire                       a_go;        // A may read (PipeFast 0: B empties in this cycle)

  pree_top_offer #(.Reg(A_REG), .NumPreu(NumPreu), .IdxAW(IdxAW), .IdxBankW(IDX_BANK_W), .HpAW(HpAW),
                   .HpBankW(HpBankW), .BankW(ABANK_W), .DataW(PH_W)) u_offer (
    .clk_i(clk_i), .rst_ni(rst_ni), .mode_i(mode_i), .pop_i(a_all), .full_o(a_full), .af_valid_i(af_valid),
    .af_ref_i(af_ref), .af_last_i(af_last), .af_data_i(af_data), .ad_valid_i(ad_valid),
    .ad_addr_i(ad_addr), .valid_o(a_valid), .idx_o(a_idx), .hp_o(a_hp), .bank_o(a_bank),
    .last_o(a_last), .data_o(a_data));

  pree_top_read #(.NumPreu(NumPreu), .BankW(ABANK_W), .CountW(CountW)) u_read (
    .clk_i(clk_i), .rst_ni(rst_ni), .go_i(a_go), .valid_i(a_valid), .bank_i(a_bank),
    .last_i(a_last), .count_last_i(~mode_i), .rd_o(a_rd), .all_o(a_all), .short_o(a_short),
    .photons_done_o(photons_done_o));

  // ===============================================================================================
  // Index table: IDX_BANKS banks (NumPreu; 2 for one PREU); bank = the address's low IDX_BANK_W
  // bits. A's lanes read it (update mode), the load port's lanes write it. The bank outputs are an
  // array, so that a lane's selection is an IDX_BANKS:1 multiplexer on an IDX_BANK_W-bit index.
  wire [HpAW-1:0]           idx_rd [0:IDX_BANKS-1];
  wire [IDX_BANKS*HpAW-1:0] idx_rdata;

  pree_ram_banks #(.BankW(IDX_BANK_W), .RowW(IDX_ROW_W), .Width(HpAW), .Lanes(NumPreu)) u_idx (
    .clk_i(clk_i), .rd_i(a_rd & {NumPreu{~mode_i}}), .rd_addr_i(a_idx), .wr_i(idx_we_i),
    .wr_addr_i(idx_addr_i), .wr_data_i(idx_data_i), .rdata_o(idx_rdata));
  generate
    for (gb = 0; gb < IDX_BANKS; gb = gb + 1) begin : g_idx
      assign idx_rd[gb] = idx_rdata[gb*HpAW +: HpAW];
    end
  endgenerate

  // ===============================================================================================
  // Stage B, R: the lanes read by A (at the RAM outputs). PipeFast 0: B issues from R and A reads
  // when R empties; PipeFast 1: R moves into B's queue (pree_top_queue), which B issues from.
  reg  [NumPreu-1:0]         b_pend_q;
  reg  [NumPreu*ABANK_W-1:0] b_abank_q;  // the bank each lane read (update: the index table's)
  reg  [NumPreu*PH_W-1:0]    b_data_q;
  reg                        b_short_q;
  wire [NumPreu-1:0]         b_iss;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni)            b_pend_q <= {NumPreu{1'b0}};
    else if (a_go)          b_pend_q <= a_rd;
    else if (REG_FLOW == 0) b_pend_q <= b_pend_q & ~b_iss;
  end

  always @(posedge clk_i) begin
    if (a_go) begin
      b_abank_q <= a_bank;
      b_data_q  <= a_data;
      b_short_q <= a_short;
    end
  end

  // Each lane's hit-point read (pree_top_hpmem): update, in B (address from the index table;
  // PipeFast 0 the issue, PipeFast 1 the first pending lane of each bank, the only one that can
  // issue to it); radiance, the read in A (ADISO's address). The lane's data (radiance: in R;
  // update: in C) comes from the bank it read last.
  reg  [NumPreu*HpAW-1:0]    b_hp;     // update: the B lanes' hit-point addresses (index table)
  reg  [NumPreu-1:0]         hr_re;
  reg  [NumPreu*HpAW-1:0]    hr_addr;
  wire [NumPreu*CONST_W-1:0] hm_c;     // each lane's hit-point data
  wire [NumPreu*STATE_W-1:0] hm_s;
  wire [NumPreu-1:0]         bl_pend;  // B's live lanes (below)
  wire [NumPreu*NumPreu-1:0] bl_beq;
  reg  [NumPreu-1:0]         b_first;  // PipeFast 1: no earlier pending lane has the lane's bank

  always @* begin : hp_lane_rd
    integer l, m;
    for (l = 0; l < NumPreu; l = l + 1) begin
      b_first[l] = bl_pend[l];
      for (m = 0; m < l; m = m + 1)
        if (bl_pend[m] && bl_beq[m*NumPreu + l]) b_first[l] = 1'b0;
      hr_re[l]                = mode_i ? a_rd[l] : (REG_FLOW != 0) ? b_first[l] : b_iss[l];
      hr_addr[l*HpAW +: HpAW] = mode_i ? a_hp[l*HpAW +: HpAW] : b_hp[l*HpAW +: HpAW];
    end
  end

  // R's lanes: update, the index entry (from the bank the lane's index address names) and the
  // photon; radiance, the hit-point data. Their keys: update, the hit point; radiance, its pixel.
  reg  [NumPreu*HpAW-1:0]    r_hp;
  reg  [NumPreu*KEY_W-1:0]   r_key;
  reg  [NumPreu*BBANK_W-1:0] r_bank;
  reg  [NumPreu*REC_W-1:0]   r_rec;
  always @* begin : r_lanes
    integer l;
    for (l = 0; l < NumPreu; l = l + 1) begin
      r_hp[l*HpAW +: HpAW]          = idx_rd[b_abank_q[l*ABANK_W +: IDX_BANK_W]];
      r_key[l*KEY_W +: KEY_W]       = {KEY_W{1'b0}};
      r_bank[l*BBANK_W +: BBANK_W]  = {BBANK_W{1'b0}};
      r_rec[l*REC_W +: REC_W]       = {REC_W{1'b0}};
      if (mode_i) begin
        r_key[l*KEY_W +: PxAW]       = hm_c[l*CONST_W + 192 +: PxAW];
        r_bank[l*BBANK_W +: PxBankW] = hm_c[l*CONST_W + 192 +: PxBankW];
        r_rec[l*REC_W +: 192 + STATE_W] = {hm_c[l*CONST_W +: 192], hm_s[l*STATE_W +: STATE_W]};
      end else begin
        r_key[l*KEY_W +: HpAW]       = r_hp[l*HpAW +: HpAW];
        r_bank[l*BBANK_W +: HpBankW] = hp_bank(r_hp[l*HpAW +: 2*HpBankW]);
        r_rec[l*REC_W +: HpAW + PH_W] = {r_hp[l*HpAW +: HpAW], b_data_q[l*PH_W +: PH_W]};
      end
    end
  end

  // B's live lanes: R's (PipeFast 0), or the head slot of B's queue (PipeFast 1), whose hazard
  // and lane pairs come precomputed.
  wire                       bl_short, q_go;
  wire [NumPreu*KEY_W-1:0]   b_key;
  wire [NumPreu*BBANK_W-1:0] b_bank;
  wire [NumPreu*REC_W-1:0]   bl_rec;
  wire [NumPreu-1:0]         q_haz;
  wire [NumPreu*NumPreu-1:0] q_keq;
  wire [WIN_UPD*NumPreu-1:0]       inf_v;
  wire [WIN_UPD*NumPreu*KEY_W-1:0] inf_k;
  pree_top_queue #(.Slots(REG_FLOW), .NumPreu(NumPreu), .KeyW(KEY_W), .BankW(BBANK_W),
                   .RecW(REC_W), .WinUpd(WIN_UPD), .WinRad(WIN_RAD)) u_queue (
    .clk_i(clk_i), .rst_ni(rst_ni), .mode_i(mode_i), .r_pend_i(b_pend_q), .r_short_i(b_short_q),
    .r_key_i(r_key), .r_bank_i(r_bank), .r_rec_i(r_rec), .iss_i(b_iss), .inf_v_i(inf_v),
    .inf_k_i(inf_k), .go_o(q_go), .pend_o(bl_pend), .short_o(bl_short), .key_o(b_key),
    .bank_o(b_bank), .rec_o(bl_rec), .haz_o(q_haz), .keq_o(q_keq), .beq_o(bl_beq));

  reg [NumPreu*PH_W-1:0]    b_ph;      // update: the photons
  reg [NumPreu*192-1:0]     b_hc;      // radiance: the hit-point data {f, pos} and state
  reg [NumPreu*STATE_W-1:0] b_hs;
  always @* begin : b_unpack
    integer l;
    for (l = 0; l < NumPreu; l = l + 1) begin
      if (REG_FLOW != 0) begin   // the head slot's records
        {b_hp[l*HpAW +: HpAW], b_ph[l*PH_W +: PH_W]}      = bl_rec[l*REC_W +: HpAW + PH_W];
        {b_hc[l*192 +: 192], b_hs[l*STATE_W +: STATE_W]} = bl_rec[l*REC_W +: 192 + STATE_W];
      end else begin             // R's, straight from the RAMs and registers (no mode select)
        b_hp[l*HpAW +: HpAW]       = r_hp[l*HpAW +: HpAW];
        b_ph[l*PH_W +: PH_W]       = b_data_q[l*PH_W +: PH_W];
        b_hc[l*192 +: 192]         = hm_c[l*CONST_W +: 192];
        b_hs[l*STATE_W +: STATE_W] = hm_s[l*STATE_W +: STATE_W];
      end
    end
  end

  // Issue: a prefix of the pending lanes, each free of hazards and conflicts (pree_top_issue).
  wire [NumPreu-1:0] b_haz, b_dup;
  pree_top_issue #(.NumPreu(NumPreu), .KeyW(KEY_W), .BankW(BBANK_W), .WinUpd(WIN_UPD),
                   .WinRad(WIN_RAD), .Pre(REG_FLOW)) u_issue (
    .clk_i(clk_i), .rst_ni(rst_ni), .mode_i(mode_i), .pend_i(bl_pend), .key_i(b_key),
    .bank_i(b_bank), .haz_i(q_haz), .keq_i(q_keq), .beq_i(bl_beq), .inf_v_o(inf_v),
    .inf_k_o(inf_k), .iss_o(b_iss), .haz_o(b_haz), .dup_o(b_dup));

  // A reads when B empties in this cycle; PipeFast 1, when R is empty or moves into the queue
  // (from registers).
  assign a_go = (REG_FLOW != 0) ? q_go : &(~b_pend_q | b_iss);

  // ===============================================================================================
  // Stage C (update): the hit-point data arrives; the PREU takes it with the photon.
  reg [NumPreu-1:0]         c_v_q;
  reg [NumPreu*HpAW-1:0]    c_hp_q;
  reg [NumPreu*PH_W-1:0]    c_data_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) c_v_q <= {NumPreu{1'b0}};
    else         c_v_q <= b_iss & {NumPreu{~mode_i}};
  end
  always @(posedge clk_i) begin
    c_hp_q   <= b_hp;
    c_data_q <= b_ph;
  end

  // ===============================================================================================
  // PREUs.
  wire [NumPreu-1:0]       p_valid, p_vout, p_acc, p_lreq, p_busy;
  wire [NumPreu*KEY_W-1:0] p_tag;
  /* verilator lint_off UNUSEDSIGNAL */
  wire [NumPreu*KEY_W-1:0] p_ltag;   // the pixel-sum read's tag: the pixel is its low PxAW bits
  /* verilator lint_on UNUSEDSIGNAL */
  wire [NumPreu*96-1:0]      p_l;
  wire [NumPreu*STATE_W-1:0] p_state;
  wire [NumPreu*96-1:0]      px_l;      // each lane's pixel-sum read (pixel memory)
  // Write-back requests per lane (update: the accepted state at its hit point; radiance: the pixel
  // sum at its pixel), then the host's port as one more lane of the memories below.
  wire [NumPreu-1:0]      wb_hp_en, wb_px_en;
  wire [NumPreu*HpAW-1:0] wb_hp_addr;
  wire [NumPreu*PxAW-1:0] p_lpix, p_wpix; // the pixel read (lreq) and written back
  generate
    for (gl = 0; gl < NumPreu; gl = gl + 1) begin : g_preu
      // The lane's hit-point data {f, pos}: radiance, B's (read in A); update, from the bank the
      // lane read last (in B).
      wire [191:0]       hc   = mode_i ? b_hc[gl*192 +: 192] : hm_c[gl*CONST_W +: 192];
      wire [STATE_W-1:0] hs   = mode_i ? b_hs[gl*STATE_W +: STATE_W] : hm_s[gl*STATE_W +: STATE_W];
      wire [KEY_W-1:0]   tag;
      if (KEY_W > HpAW) begin : g_tag_pad
        assign tag = mode_i ? b_key[gl*KEY_W +: KEY_W] : {{(KEY_W-HpAW){1'b0}}, c_hp_q[gl*HpAW +: HpAW]};
      end else begin : g_tag
        assign tag = mode_i ? b_key[gl*KEY_W +: KEY_W] : c_hp_q[gl*HpAW +: HpAW];
      end
      assign p_valid[gl] = mode_i ? b_iss[gl] : c_v_q[gl];

      pree_preu #(.TagW(KEY_W), .Datapath(Datapath), .PipeFast(PipeFast), .AddStages(AddStages),
                  .MulStages(MulStages), .SqrStages(SqrStages), .DivStages(DivStages),
                  .U2fStages(U2fStages), .WaccStages(WaccStages)) u_preu (
        .clk_i(clk_i), .rst_ni(rst_ni), .mode_i(mode_i), .valid_i(p_valid[gl]), .tag_i(tag),
        .hp_pos_i(hc[0 +: 96]), .hp_f_i(hc[96 +: 96]), .hp_state_i(hs),
        .ph_pos_i(c_data_q[gl*PH_W +: 96]), .ph_phi_i(c_data_q[gl*PH_W + 96 +: 96]),
        .alpha_i(alpha_i), .kappa_i(kappa_i),
        .ne_i(ne_i), .lreq_o(p_lreq[gl]), .lreq_tag_o(p_ltag[gl*KEY_W +: KEY_W]),
        .l_i(px_l[gl*96 +: 96]), .valid_o(p_vout[gl]), .tag_o(p_tag[gl*KEY_W +: KEY_W]),
        .accept_o(p_acc[gl]), .state_o(p_state[gl*STATE_W +: STATE_W]),
        .l_o(p_l[gl*96 +: 96]), .busy_o(p_busy[gl]));

      // Write-back: update, the accepted hit-point state; radiance, the pixel sum.
      assign wb_hp_en[gl]   = !mode_i && p_vout[gl] && p_acc[gl];
      assign wb_hp_addr[gl*HpAW +: HpAW] = p_tag[gl*KEY_W +: HpAW];
      assign wb_px_en[gl]   = mode_i && p_vout[gl];
      assign p_lpix[gl*PxAW +: PxAW] = p_ltag[gl*KEY_W +: PxAW];
      assign p_wpix[gl*PxAW +: PxAW] = p_tag[gl*KEY_W +: PxAW];
    end
  endgenerate

  // ===============================================================================================
  // Hit-point memory (pree_top_hpmem): the PREU lanes' reads (update: B's issue; radiance: A's
  // read) and state writes (update write-back), and the host's port.
  pree_top_hpmem #(.NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(HpBankW), .ConstW(CONST_W),
                   .StateW(STATE_W)) u_hpmem (
    .clk_i(clk_i), .rd_i(hr_re), .rd_addr_i(hr_addr), .wr_i(wb_hp_en), .wr_addr_i(wb_hp_addr),
    .wr_state_i(p_state), .rd_const_o(hm_c), .rd_state_o(hm_s), .hp_we_i(hp_we_i),
    .hp_re_i(hp_re_i), .hp_addr_i(hp_addr_i), .hp_wdata_i(hp_wdata_i), .hp_rdata_o(hp_rdata_o));

  // ===============================================================================================
  // Pixel memory (pree_top_pxmem): the PREU lanes' pixel-sum reads (lreq) and write-backs
  // (radiance), and the host's port.
  pree_top_pxmem #(.NumPreu(NumPreu), .PxAW(PxAW), .PxBankW(PxBankW)) u_pxmem (
    .clk_i(clk_i), .rd_i(p_lreq), .rd_addr_i(p_lpix), .wr_i(wb_px_en), .wr_addr_i(p_wpix),
    .wr_data_i(p_l), .rd_data_o(px_l), .px_we_i(px_we_i), .px_re_i(px_re_i), .px_addr_i(px_addr_i),
    .px_wdata_i(px_wdata_i), .px_rdata_o(px_rdata_o));

  // ===============================================================================================
  // Idle and counters (pree_counters).
  assign idle_o = af_empty && !ad_busy && !(|a_valid) && !(|b_pend_q) && !(|bl_pend) && !(|c_v_q) &&
                  !(|p_busy);

  pree_counters #(.NumPreu(NumPreu), .CtrW(CtrW), .InReg(REG_FLOW)) u_counters (
    .clk_i(clk_i), .rst_ni(rst_ni), .en_i(cnt_en_i), .mode_i(mode_i), .pend_i(bl_pend),
    .iss_i(b_iss), .haz_i(b_haz), .dup_i(b_dup), .short_i(bl_short), .op_i(p_valid), .cnt_o(cnt_o));

`ifdef PREE_ASSERT
  // Protocol checks (simulation only): mode changes and host access only when idle, index
  // writes of one cycle in distinct banks.
  reg mode_q;
  integer a, b;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      mode_q <= 1'b0;
    end else begin
      mode_q <= mode_i;
      if (mode_i != mode_q && !idle_o) $fatal(1, "pree_top: mode_i changed while busy");
      if ((hp_we_i || hp_re_i || px_we_i || px_re_i) && !idle_o)
        $fatal(1, "pree_top: host memory port used while busy");
      for (a = 0; a < NumPreu; a = a + 1)
        for (b = 0; b < a; b = b + 1)
          if (idx_we_i[a] && idx_we_i[b] &&
              idx_addr_i[a*IdxAW +: IDX_BANK_W] == idx_addr_i[b*IdxAW +: IDX_BANK_W])
            $fatal(1, "pree_top: two index writes in bank %0d", idx_addr_i[a*IdxAW +: IDX_BANK_W]);
    end
  end
`endif

endmodule

`default_nettype wire
