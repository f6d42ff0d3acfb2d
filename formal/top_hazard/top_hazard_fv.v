// SPDX-License-Identifier: Apache-2.0
// top_hazard_fv: formal harness of pree_top's hazard rule and operation flow, with small
// memories and the PREUs replaced by pree_preu_stub (the PREU's timing, free data).
//
// Environment (assumptions, the host protocol of docs/pree_top.md): reset in the first cycle;
// mode_i changes, rad_start_i pulses (radiance mode) and the host memory ports are used only
// while idle_o is high; one cycle's index-table writes go to distinct banks. Everything else
// (photons, their candidate counts and index addresses, the index table's and the memories'
// contents, n_hit_i, the PREUs' results) is free at every cycle.
//
// Properties, for a watched hit point H and a watched pixel P (any constants):
//   - update: an update of H is in flight from its hit-point read (the cycle before the PREU
//     takes it, stage C) to its write-back (the PREU's valid_o). No update of H is read while
//     another one is in flight (read in the cycle of the write, or before, sees stale data), and
//     no two lanes take H in one cycle;
//   - radiance: a contribution to P is in flight from its pixel-sum read (the PREU's lreq_o) to
//     its write (valid_o); no pixel-sum read of P while another contribution to P is in flight,
//     and no two lanes read P in one cycle;
//   - no operation lost or duplicated: the PREUs never receive more operations than the
//     controllers' lanes handed to stage A (the offer buffer, the read, R and the queue in
//     between), and once idle_o is high they have received exactly as many.
// These are checked against the PREU's latencies (its timing contract), not against the issue
// logic's window parameters, so a window one cycle short is a failure.
`default_nettype none

module top_hazard_fv #(
  parameter PipeFast = 0,
  parameter Mode     = 2    // 0: update mode only, 1: radiance mode only, 2: either (switched while idle)
) (
  input wire                 clk_i,
  input wire                 mode_i,
  input wire                 cnt_en_i,
  input wire                 rad_start_i,
  input wire [HP_AW-1:0]     n_hit_i,
  input wire                 ph_valid_i,
  input wire [191:0]         ph_data_i,
  input wire [IDX_AW-1:0]    ph_paddr_i,
  input wire [CNT_W-1:0]     ph_n_i,
  input wire [NP-1:0]        idx_we_i,
  input wire [NP*IDX_AW-1:0] idx_addr_i,
  input wire [NP*HP_AW-1:0]  idx_data_i,
  input wire                 hp_we_i,
  input wire                 hp_re_i,
  input wire [HP_AW-1:0]     hp_addr_i,
  input wire [PX_AW+351:0]   hp_wdata_i,
  input wire                 px_we_i,
  input wire                 px_re_i,
  input wire [PX_AW-1:0]     px_addr_i,
  input wire [95:0]          px_wdata_i
);

  localparam NP     = 2;
  localparam HP_AW  = 3;
  localparam IDX_AW = 2;
  localparam PX_AW  = 2;
  localparam CNT_W  = 2;
  localparam KEY_W  = (HP_AW > PX_AW) ? HP_AW : PX_AW;
  // PipeFast 1 with each unit at its fewest stages: the registered flow control (offer buffer,
  // queue, precomputed hazards) with windows short enough for a bounded check.
  localparam ST     = (PipeFast != 0) ? 1 : 0;

  reg f_init = 1'b1;
  always @(posedge clk_i) f_init <= 1'b0;
  wire rst_ni = !f_init;

  wire        ph_ready, idle;
  wire [31:0] photons_done;
  wire [PX_AW+351:0] hp_rdata;
  wire [95:0]        px_rdata;

  pree_top #(
    .NumPreu(NP), .HpAW(HP_AW), .HpBankW(1), .IdxAW(IDX_AW), .PxAW(PX_AW), .PxBankW(1),
    .CntW(CNT_W), .Datapath(0), .CtrW(4), .PipeFast(PipeFast), .AddStages(ST),
    .MulStages(ST), .SqrStages(ST), .DivStages(2 * ST)
  ) u_dut (
    .clk_i(clk_i), .rst_ni(rst_ni), .mode_i(mode_i), .cnt_en_i(cnt_en_i), .ne_i(32'd0),
    .alpha_i(32'd0), .kappa_i(32'd0), .rad_start_i(rad_start_i), .n_hit_i(n_hit_i),
    .idle_o(idle), .ph_valid_i(ph_valid_i), .ph_ready_o(ph_ready), .ph_data_i(ph_data_i),
    .ph_paddr_i(ph_paddr_i), .ph_n_i(ph_n_i), .photons_done_o(photons_done),
    .idx_we_i(idx_we_i), .idx_addr_i(idx_addr_i), .idx_data_i(idx_data_i),
    .hp_we_i(hp_we_i), .hp_re_i(hp_re_i), .hp_addr_i(hp_addr_i), .hp_wdata_i(hp_wdata_i),
    .hp_rdata_o(hp_rdata), .px_we_i(px_we_i), .px_re_i(px_re_i), .px_addr_i(px_addr_i),
    .px_wdata_i(px_wdata_i), .px_rdata_o(px_rdata), .cnt_o()
  );

  // Taps (taps.ys connects each to the signal of the flattened pree_top named beside it).
  wire [NP-1:0]       f_t_p_valid;   // p_valid: an operation enters PREU l
  wire [NP*KEY_W-1:0] f_t_tag;       // g_preu[l].tag: its key (hit point or pixel)
  wire [NP-1:0]       f_t_p_vout;    // p_vout: PREU l's result (write-back)
  wire [NP*KEY_W-1:0] f_t_p_tag;     // p_tag
  wire [NP-1:0]       f_t_p_lreq;    // p_lreq: PREU l reads its pixel sum
  wire [NP*KEY_W-1:0] f_t_p_ltag;    // p_ltag
  wire [NP-1:0]       f_t_af_valid;  // af_valid: AFTSO-HpUOC's lanes
  wire [NP-1:0]       f_t_ad_valid;  // ad_valid: ADISO-REC's lanes
  wire                f_t_a_full;    // a_full: the controllers' stall (besides the mode)
  wire [NP-1:0]       f_t_b_haz;     // b_haz: a lane waits on a hazard
  wire                f_t_ad_busy;   // ad_busy: a radiance pass is being issued

  // ---------------------------------------------------------------------------- environment
  reg f_mode_q = 1'b0;
  always @(posedge clk_i) f_mode_q <= mode_i;
  always @* begin
    if (rst_ni) begin
      if (mode_i != f_mode_q) assume (idle);
    end else begin
      assume (!mode_i);
    end
    if (rst_ni && Mode == 0) assume (!mode_i);
    if (rst_ni && Mode == 1) assume (mode_i);
    if (rad_start_i) assume (mode_i && idle && rst_ni);
    if (!idle || !rst_ni) assume (!hp_we_i && !hp_re_i && !px_we_i && !px_re_i);
    if (idx_we_i[0] && idx_we_i[1]) assume (idx_addr_i[0] != idx_addr_i[IDX_AW]);
  end

  // ---------------------------------------------------------------------------- hazards
  (* anyconst *) reg [KEY_W-1:0] f_h;   // the watched key (a hit point, or a pixel)

  integer l;
  reg [1:0] f_pres, f_done, f_lreq;     // per cycle: lanes taking / finishing / reading f_h
  always @* begin
    f_pres = 0;
    f_done = 0;
    f_lreq = 0;
    for (l = 0; l < NP; l = l + 1) begin
      if (f_t_p_valid[l] && f_t_tag[l*KEY_W +: KEY_W] == f_h) f_pres = f_pres + 1;
      if (f_t_p_vout[l] && f_t_p_tag[l*KEY_W +: KEY_W] == f_h) f_done = f_done + 1;
      if (f_t_p_lreq[l] && f_t_p_ltag[l*KEY_W +: KEY_W] == f_h) f_lreq = f_lreq + 1;
    end
  end

  // Update: f_upd = updates of H taken by a PREU in earlier cycles whose write-back was in an
  // earlier cycle or is still to come, minus those written back; f_upd_blk: in the last cycle
  // (the read of an update taken now) some update of H was in flight or was read.
  reg [4:0] f_upd = 0, f_rad = 0;
  reg       f_upd_blk = 1'b0;
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      f_upd     <= 0;
      f_rad     <= 0;
      f_upd_blk <= 1'b0;
    end else if (!mode_i) begin
      f_upd     <= f_upd + f_pres - f_done;
      f_upd_blk <= (f_upd != 0) || (f_pres != 0);
    end else begin
      f_rad     <= f_rad + f_lreq - f_done;
      f_upd_blk <= 1'b0;
    end
  end

  always @* begin
    if (rst_ni && !mode_i && f_pres != 0) begin
      assert (f_pres == 1);
      assert (!f_upd_blk);
    end
    // Radiance: f_rad = contributions to P whose pixel sum was read in an earlier cycle and
    // not yet written in an earlier cycle (one written in this cycle lands at its end).
    if (rst_ni && mode_i && f_lreq != 0) begin
      assert (f_lreq == 1);
      assert (f_rad == 0);
    end
  end

  // ---------------------------------------------------------------------------- no loss
  reg [5:0] f_taken = 0, f_given = 0;
  reg [1:0] f_take_n, f_give_n;
  always @* begin
    f_take_n = 0;
    f_give_n = 0;
    for (l = 0; l < NP; l = l + 1) begin
      if (!f_t_a_full && (mode_i ? f_t_ad_valid[l] : f_t_af_valid[l])) f_take_n = f_take_n + 1;
      if (f_t_p_valid[l]) f_give_n = f_give_n + 1;
    end
  end
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      f_taken <= 0;
      f_given <= 0;
    end else begin
      f_taken <= f_taken + f_take_n;
      f_given <= f_given + f_give_n;
    end
  end
  always @* begin
    if (rst_ni) begin
      assert (f_given <= f_taken);
      if (idle) assert (f_given == f_taken);
    end
  end

  // ---------------------------------------------------------------------------- covers
  reg f_ad_busy_q = 1'b0;
  always @(posedge clk_i) f_ad_busy_q <= f_t_ad_busy;
  always @* begin
    if (rst_ni) begin
      cover (!mode_i && |f_t_b_haz);                     // an update hazard stall
      cover (mode_i && |f_t_b_haz);                      // a radiance hazard stall
      cover (!mode_i && f_t_a_full && |f_t_af_valid);    // a full offer: AFTSO-HpUOC waits
      cover (mode_i && f_t_a_full && |f_t_ad_valid);     // a full offer: ADISO-REC waits
      cover (mode_i && f_ad_busy_q && !f_t_ad_busy);     // a radiance pass's last address
      cover (!mode_i && f_pres != 0 && f_upd == 0 && f_done == 0 && f_given > 2);
      cover (mode_i && idle && f_given > 2);             // a radiance pass done
    end
  end

endmodule

`default_nettype wire
