// SPDX-License-Identifier: Apache-2.0
// pree_top (formal stub): the engine as pree_axi sees it, for the formal job formal/axi. The
// same parameters and ports as rtl/pree_top.v; what it does is free within the interface
// contract of docs/pree_top.md, so that a proof of the wrapper covers every engine that keeps
// the contract, at parameters where the proof is quick.
//
// The engine's freedom (free inputs of the proof, constrained by assumptions):
//   ph_ready_o     any value in update mode (0 in radiance mode); a waiting photon is taken
//                  within TAKE_MAX cycles (fairness).
//   photons_done_o counts photons taken (the slots of a handshake with N^P > 0, any of the
//                  PhotonsPerCycle) and finished, in order, up to DONE_STEP a cycle (the engine's
//                  read lanes each may carry a photon's last entry: up to NumPreu; the stub
//                  allows min(NumPreu, PhotonsPerCycle), one at the paper's intake, where a
//                  larger step costs the accounting proof more than it runs); the oldest photon
//                  in flight is finished within DONE_MAX cycles (fairness).
//   idle_o         honest: high exactly when no photon is in flight and no radiance pass runs;
//                  a pass started by rad_start_i ends within RAD_MAX cycles.
//   hp_rdata_o, px_rdata_o, cnt_o  any value.
// The wrapper's obligations (asserted here, where the engine's inputs are seen):
//   mode_i, ne_i, alpha_i, kappa_i and n_hit_i change only while idle; the host ports (hp_*, px_*)
//   are used only while idle; rad_start_i only while idle in radiance mode; photons only in
//   update mode; the enabled lanes of an index-table write
//   lie in distinct banks (address mod NumPreu); the index table (2^IdxAW entries, each free,
//   written or in use) is written only at free entries, a photon is passed on only when all its
//   N^P entries from ph_paddr_i on are written (its candidates are in), and its entries are
//   free again once photons_done_o counts it.
// f_taken_o, f_state_o: the stub's state, for the harness's induction invariants.
`default_nettype none

module pree_top #(
  parameter NumPreu = 4,
  parameter HpAW    = 18,
  parameter HpBankW = 4,
  parameter IdxAW   = 12,
  parameter PxAW    = 17,
  parameter PxBankW = 4,
  parameter CntW    = 16,
  parameter Datapath = 0,
  parameter CtrW    = 48,
  parameter PipeFast = 0,
  parameter AddStages  = 0,
  parameter MulStages  = 0, SqrStages = 0, DivStages = 0, U2fStages = 0, WaccStages = 0,
  parameter PhotonsPerCycle = 1,
  parameter CountW  = 32,
  parameter StateW  = (Datapath != 0) ? 320 : 160
) (
  input  wire                       clk_i,
  input  wire                       rst_ni,
  input  wire                       mode_i,
  input  wire                       cnt_en_i,
  input  wire [31:0]                ne_i,
  input  wire [31:0]                alpha_i,
  input  wire [31:0]                kappa_i,
  input  wire                       rad_start_i,
  input  wire [HpAW-1:0]            n_hit_i,
  output wire                       idle_o,
  input  wire                       ph_valid_i,
  output wire                       ph_ready_o,
  input  wire [PhotonsPerCycle*192-1:0]   ph_data_i,
  input  wire [PhotonsPerCycle*IdxAW-1:0] ph_paddr_i,
  input  wire [PhotonsPerCycle*CntW-1:0]  ph_n_i,
  output wire [CountW-1:0]          photons_done_o,
  input  wire [NumPreu-1:0]         idx_we_i,
  input  wire [NumPreu*IdxAW-1:0]   idx_addr_i,
  input  wire [NumPreu*HpAW-1:0]    idx_data_i,
  input  wire                       hp_we_i,
  input  wire                       hp_re_i,
  input  wire [HpAW-1:0]            hp_addr_i,
  input  wire [PxAW+191+StateW:0]   hp_wdata_i,
  output wire [PxAW+191+StateW:0]   hp_rdata_o,
  input  wire                       px_we_i,
  input  wire                       px_re_i,
  input  wire [PxAW-1:0]            px_addr_i,
  input  wire [95:0]                px_wdata_i,
  output wire [95:0]                px_rdata_o,
  output wire [(7+NumPreu)*CtrW-1:0] cnt_o
);

  localparam TAKE_MAX = 3, DONE_MAX = 4, RAD_MAX = 3;
  localparam DONE_STEP = PhotonsPerCycle < NumPreu ? PhotonsPerCycle : NumPreu;
  localparam IDX_N = 1 << IdxAW;
  localparam FLY_N = 16;                    // photons in flight the stub can hold (above the
                                            // wrapper's ring, which the harness checks)

  // Free choices of the engine.
  (* anyseq *) wire f_ready, f_rad_end;
  (* anyseq *) wire [CountW-1:0] f_done_n;  // photons finished in this cycle
  (* anyseq *) wire [PxAW+191+StateW:0] f_hp_rdata;
  (* anyseq *) wire [95:0] f_px_rdata;
  (* anyseq *) wire [(7+NumPreu)*CtrW-1:0] f_cnt;

  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;

  // Photons taken and done; the radiance pass.
  reg  [CountW-1:0] taken_q, done_q;
  reg         rad_q;
  wire [CountW-1:0] fly = taken_q - done_q;
  wire        take = ph_valid_i && ph_ready_o;
  wire        done = f_done_n != {CountW{1'b0}};
  reg  [CountW-1:0] take_n;                 // photons in the handshake: slots with N^P > 0
  always @* begin : slots
    integer s;
    take_n = {CountW{1'b0}};
    for (s = 0; s < PhotonsPerCycle; s = s + 1)
      if (ph_n_i[s*CntW +: CntW] != {CntW{1'b0}}) take_n = take_n + 1'b1;
  end
  assign ph_ready_o     = f_ready && !mode_i;
  assign photons_done_o = done_q;
  assign idle_o         = fly == {CountW{1'b0}} && !rad_q;
  assign hp_rdata_o     = f_hp_rdata;
  assign px_rdata_o     = f_px_rdata;
  assign cnt_o          = f_cnt;

  always @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) begin
      taken_q <= {CountW{1'b0}}; done_q <= {CountW{1'b0}}; rad_q <= 1'b0;
    end else begin
      taken_q <= take ? taken_q + take_n : taken_q;
      done_q  <= done_q + f_done_n;
      rad_q   <= rad_start_i || (rad_q && !f_rad_end);
    end

  // Fairness: a waiting photon is taken, the oldest photon finishes, a pass ends, in bounded time.
  reg [3:0] take_wait_q, done_wait_q, rad_wait_q;
  always @(posedge clk_i) begin
    take_wait_q <= (!rst_ni || !ph_valid_i || mode_i || take) ? 4'd0 : take_wait_q + 4'd1;
    done_wait_q <= (!rst_ni || fly == {CountW{1'b0}} || done) ? 4'd0 : done_wait_q + 4'd1;
    rad_wait_q  <= (!rst_ni || !rad_q || f_rad_end) ? 4'd0 : rad_wait_q + 4'd1;
  end
  always @* begin
    assume (take_wait_q < TAKE_MAX && done_wait_q < DONE_MAX && rad_wait_q < RAD_MAX);
    assume (fly < FLY_N);
    assume (f_done_n <= DONE_STEP && f_done_n <= fly);
  end

  // The wrapper's obligations on the engine's inputs.
  reg f_rst_past = 1'b0;
  always @(posedge clk_i) f_rst_past <= rst_ni;
  always @(posedge clk_i) if (f_past_valid && rst_ni && f_rst_past && !$past(idle_o)) begin
    assert ($stable(mode_i) && $stable(ne_i) && $stable(alpha_i) && $stable(kappa_i));
    assert ($stable(n_hit_i));
  end
  always @* if (rst_ni) begin
    if (hp_we_i || hp_re_i || px_we_i || px_re_i) assert (idle_o);
    if (rad_start_i) assert (idle_o && mode_i);
    if (ph_valid_i)  assert (!mode_i);
    if (|idx_we_i)   assert (!mode_i);
  end

  // Index-table writes: enabled lanes in distinct banks.
  always @* begin : banks
    integer a, b;
    for (a = 0; a < NumPreu; a = a + 1)
      for (b = a + 1; b < NumPreu; b = b + 1)
        if (rst_ni && idx_we_i[a] && idx_we_i[b])
          assert (idx_addr_i[a*IdxAW +: IdxAW] % NumPreu != idx_addr_i[b*IdxAW +: IdxAW] % NumPreu);
  end

  wire unused_ok = ^{cnt_en_i, idx_data_i, hp_addr_i, hp_wdata_i, px_addr_i, px_wdata_i};

endmodule

`default_nettype wire
