// SPDX-License-Identifier: Apache-2.0
// top_tb: self-checking Icarus bench of pree_top over the vector files of tb/cosim/top_vecgen.c.
//
// It plays the host of docs/pree_top.md ("Host protocol"): loads the hit points through hp_*,
// streams the photons in update mode (index entries written through idx_*, up to NumPreu a
// cycle in distinct banks and never before the photons whose entries they overwrite are counted
// by photons_done_o; a photon is offered once its entries are written, with random idle gaps on
// ph_valid_i and random short index writes), waits for idle_o, reads every hit point back and
// compares it with the model's word; then clears the pixels, runs the radiance pass and compares
// every pixel. Also checks that the PREUs' operation counters add up to the operations sent and
// to the hit points, and the stage-A bank-conflict counter (abank) in the update pass: zero for
// the protocol's packed index placement, non-zero for the vecgen's misplaced one. The first 10 mismatches of each memory are printed in hex; any mismatch,
// a protocol assertion (PREE_ASSERT) or a time-out ends the run with $fatal (run as vvp -N).
//
// Plusargs: +vec=PREFIX (PREFIX.meta/.hp/.ph/.idx/.hpx/.px), +seed=N (gaps), +gap=PCT (percent
// of cycles without a photon offer, default 20). Parameters must match the vecgen run (checked
// against PREFIX.meta): NumPreu, HpAW, IdxAW, PxAW; HpBankW and PxBankW are free.
`default_nettype none

module top_tb;
  parameter NumPreu = 4;
  parameter HpAW    = 10;
  parameter HpBankW = 4;
  parameter IdxAW   = 8;
  parameter PxAW    = 9;
  parameter PxBankW = 2;
  parameter CntW    = 16;
  parameter MaxPh   = 4096;     // photons and index entries the bench can hold
  parameter MaxEnt  = 65536;
  localparam HP_W   = PxAW + 352;
  localparam NCNT   = 7 + NumPreu;
  localparam MAXCYC = 4000000;  // time-out of one phase

  // Vectors.
  reg [31:0]  meta   [0:15];
  reg [383:0] hp_in  [0:(1 << HpAW) - 1];
  reg [383:0] hp_exp [0:(1 << HpAW) - 1];
  reg [95:0]  px_exp [0:(1 << PxAW) - 1];
  reg [287:0] ph_vec [0:MaxPh - 1];
  reg [95:0]  idx_vec[0:MaxEnt - 1];
  reg [1023:0] prefix, fname;

  // DUT ports.
  reg                       clk, rst_n, mode, cnt_en, rad_start, ph_valid;
  reg  [31:0]               ne;
  reg  [HpAW-1:0]           n_hit;
  reg  [191:0]              ph_data;
  reg  [IdxAW-1:0]          ph_paddr;
  reg  [CntW-1:0]           ph_n;
  reg  [NumPreu-1:0]        idx_we;
  reg  [NumPreu*IdxAW-1:0]  idx_addr;
  reg  [NumPreu*HpAW-1:0]   idx_data;
  reg                       hp_we, hp_re, px_we, px_re;
  reg  [HpAW-1:0]           hp_addr;
  reg  [HP_W-1:0]           hp_wdata;
  reg  [PxAW-1:0]           px_addr;
  reg  [95:0]               px_wdata;
  wire                      idle, ph_ready;
  wire [31:0]               photons_done;
  wire [HP_W-1:0]           hp_rdata;
  wire [95:0]               px_rdata;
  wire [NCNT*48-1:0]        cnt;

  pree_top #(
    .NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(HpBankW), .IdxAW(IdxAW), .PxAW(PxAW),
    .PxBankW(PxBankW), .CntW(CntW)
  ) dut (
    .clk_i(clk), .rst_ni(rst_n), .mode_i(mode), .cnt_en_i(cnt_en), .ne_i(ne),
    .alpha_i(32'h3F33_3333), .kappa_i(32'h0), // the paper datapath at alpha = (float)0.7
    .rad_start_i(rad_start), .n_hit_i(n_hit), .idle_o(idle),
    .ph_valid_i(ph_valid), .ph_ready_o(ph_ready), .ph_data_i(ph_data), .ph_paddr_i(ph_paddr),
    .ph_n_i(ph_n), .photons_done_o(photons_done),
    .idx_we_i(idx_we), .idx_addr_i(idx_addr), .idx_data_i(idx_data),
    .hp_we_i(hp_we), .hp_re_i(hp_re), .hp_addr_i(hp_addr), .hp_wdata_i(hp_wdata),
    .hp_rdata_o(hp_rdata),
    .px_we_i(px_we), .px_re_i(px_re), .px_addr_i(px_addr), .px_wdata_i(px_wdata),
    .px_rdata_o(px_rdata), .cnt_o(cnt));

  integer nhp, npix, nph, nent, nops, seed, gap, i, j, cyc, errors, hp_err, px_err;
  integer e_head, p_head, e_lim, upd_cycles, held;
  reg     stop, take;
  reg [NumPreu-1:0] used;
  reg [95:0]  ent;
  reg [287:0] phv;
  reg [47:0]  ops_upd, ops_rad;
  reg [NCNT*48-1:0] cnt_upd;     // the counters after the update pass

  // One clock cycle: inputs were set after the last falling edge; rising edge at +5.
  task tick;
    begin
      #5 clk = 1'b1;
      #5 clk = 1'b0;
    end
  endtask

  task wait_idle;
    input [8*16-1:0] what;
    begin
      cyc = 0;
      #1;
      while (!idle) begin
        tick;
        #1;
        cyc = cyc + 1;
        if (cyc > MAXCYC) $fatal(1, "top_tb: %0s: idle_o not reached in %0d cycles", what, MAXCYC);
      end
    end
  endtask

  function [47:0] count;          // counter k now
    input integer k;
    begin
      count = cnt[k*48 +: 48];
    end
  endfunction

  function [47:0] rad_count;      // counter k's radiance-pass share
    input integer k;
    begin
      rad_count = cnt[k*48 +: 48] - cnt_upd[k*48 +: 48];
    end
  endfunction

  initial begin
    if (!$value$plusargs("vec=%s", prefix)) $fatal(1, "top_tb: need +vec=PREFIX");
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    if (!$value$plusargs("gap=%d", gap)) gap = 20;
    $sformat(fname, "%0s.meta", prefix);
    $readmemh(fname, meta);
    nhp = meta[0]; npix = meta[1]; nph = meta[2]; nent = meta[3]; nops = meta[5];
    if (meta[6] != NumPreu || meta[7] != HpAW || meta[8] != IdxAW || meta[9] != PxAW)
      $fatal(1, "top_tb: vectors for NumPreu %0d HpAW %0d IdxAW %0d PxAW %0d, bench built for %0d %0d %0d %0d",
             meta[6], meta[7], meta[8], meta[9], NumPreu, HpAW, IdxAW, PxAW);
    if (nph > MaxPh || nent > MaxEnt || nhp < 1 || nph < 1 || nent < 1)
      $fatal(1, "top_tb: %0d photons / %0d entries out of range", nph, nent);
    $sformat(fname, "%0s.hp", prefix);  $readmemh(fname, hp_in, 0, nhp - 1);
    $sformat(fname, "%0s.hpx", prefix); $readmemh(fname, hp_exp, 0, nhp - 1);
    $sformat(fname, "%0s.px", prefix);  $readmemh(fname, px_exp, 0, npix - 1);
    $sformat(fname, "%0s.ph", prefix);  $readmemh(fname, ph_vec, 0, nph - 1);
    $sformat(fname, "%0s.idx", prefix); $readmemh(fname, idx_vec, 0, nent - 1);

    clk = 1'b0; rst_n = 1'b0; mode = 1'b0; cnt_en = 1'b0; rad_start = 1'b0; ph_valid = 1'b0;
    ne = meta[4]; n_hit = {HpAW{1'b0}}; ph_data = 192'd0; ph_paddr = {IdxAW{1'b0}}; ph_n = {CntW{1'b0}};
    idx_we = {NumPreu{1'b0}}; idx_addr = {NumPreu*IdxAW{1'b0}}; idx_data = {NumPreu*HpAW{1'b0}};
    hp_we = 1'b0; hp_re = 1'b0; hp_addr = {HpAW{1'b0}}; hp_wdata = {HP_W{1'b0}};
    px_we = 1'b0; px_re = 1'b0; px_addr = {PxAW{1'b0}}; px_wdata = 96'd0;
    errors = 0; hp_err = 0; px_err = 0;
    tick; tick;
    rst_n = 1'b1;
    tick;

    // 1. Hit points, one per cycle.
    for (i = 0; i < nhp; i = i + 1) begin
      hp_we = 1'b1;
      hp_addr = i;
      hp_wdata = hp_in[i][HP_W-1:0];
      tick;
    end
    hp_we = 1'b0;
    tick;

    // 2. Update pass: index entries and photons.
    cnt_en = 1'b1;
    e_head = 0; p_head = 0; cyc = 0; held = 0;
    while (p_head < nph) begin
      // Index writes: entries in order, in distinct banks, once their old photons are done;
      // sometimes fewer than NumPreu on purpose.
      idx_we = {NumPreu{1'b0}};
      used = {NumPreu{1'b0}};
      stop = 1'b0;
      e_lim = ($random(seed) & 3) == 0 ? 1 + (($random(seed) & 32'h7fffffff) % NumPreu) : NumPreu;
      for (j = 0; j < NumPreu; j = j + 1) begin
        if (!stop && j < e_lim && e_head < nent) begin
          ent = idx_vec[e_head];
          if (ent[95:64] <= photons_done && !used[ent[32 +: IdxAW] % NumPreu]) begin
            used[ent[32 +: IdxAW] % NumPreu] = 1'b1;
            idx_we[j] = 1'b1;
            idx_addr[j*IdxAW +: IdxAW] = ent[32 +: IdxAW];
            idx_data[j*HpAW +: HpAW] = ent[0 +: HpAW];
            e_head = e_head + 1;
          end else begin
            if (ent[95:64] > photons_done) held = held + 1;
            stop = 1'b1;
          end
        end
      end
      // The head photon once its entries are written (by this edge), unless a gap is drawn.
      phv = ph_vec[p_head];
      ph_valid = phv[287:256] <= e_head && (($random(seed) & 32'h7fffffff) % 100) >= gap;
      ph_paddr = phv[224 +: IdxAW];
      ph_n = phv[192 +: CntW];
      ph_data = phv[191:0];
      #1 take = ph_valid && ph_ready;
      tick;
      if (take) p_head = p_head + 1;
      cyc = cyc + 1;
      if (cyc > MAXCYC) $fatal(1, "top_tb: photon %0d of %0d not taken in %0d cycles", p_head, nph, MAXCYC);
    end
    ph_valid = 1'b0;
    idx_we = {NumPreu{1'b0}};
    if (e_head != nent) $fatal(1, "top_tb: %0d of %0d index entries written", e_head, nent);
    wait_idle("update pass");
    cnt_en = 1'b0;
    tick;
    cnt_upd = cnt;
    upd_cycles = count(0);
    ops_upd = 48'd0;
    for (j = 0; j < NumPreu; j = j + 1) ops_upd = ops_upd + count(7 + j);

    // 3. Read every hit point back.
    for (i = 0; i < nhp; i = i + 1) begin
      hp_re = 1'b1;
      hp_addr = i;
      tick;
      #1;
      if (hp_rdata !== hp_exp[i][HP_W-1:0]) begin
        if (hp_err < 10)
          $display("MISMATCH hit point %0d: rtl %h expected %h", i, hp_rdata, hp_exp[i][HP_W-1:0]);
        hp_err = hp_err + 1;
      end
    end
    hp_re = 1'b0;
    tick;

    // 4. Radiance pass: clear the pixels, start, wait, read them.
    for (i = 0; i < npix; i = i + 1) begin
      px_we = 1'b1;
      px_addr = i;
      px_wdata = 96'd0;
      tick;
    end
    px_we = 1'b0;
    mode = 1'b1;
    tick;
    n_hit = nhp;
    rad_start = 1'b1;
    cnt_en = 1'b1;
    tick;
    rad_start = 1'b0;
    wait_idle("radiance pass");
    cnt_en = 1'b0;
    tick;
    for (i = 0; i < npix; i = i + 1) begin
      px_re = 1'b1;
      px_addr = i;
      tick;
      #1;
      if (px_rdata !== px_exp[i]) begin
        if (px_err < 10) $display("MISMATCH pixel %0d: rtl %h expected %h", i, px_rdata, px_exp[i]);
        px_err = px_err + 1;
      end
    end
    px_re = 1'b0;
    mode = 1'b0;
    tick;

    // Operation counts: every operation sent reached a PREU once, every hit point once.
    ops_rad = 48'd0;
    for (j = 0; j < NumPreu; j = j + 1) ops_rad = ops_rad + rad_count(7 + j);
    if (ops_upd != nops || ops_rad != nhp) begin
      $display("MISMATCH operation counts: update %0d (sent %0d), radiance %0d (hit points %0d)",
               ops_upd, nops, ops_rad, nhp);
      errors = errors + 1;
    end
    if (meta[10] == 0 && cnt_upd[5*48 +: 48] != 48'd0) begin
      $display("MISMATCH abank: %0d stage-A conflict cycles in update mode with packed index entries",
               cnt_upd[5*48 +: 48]);
      errors = errors + 1;
    end
    if (meta[10] != 0 && cnt_upd[5*48 +: 48] == 48'd0) begin
      $display("MISMATCH abank: misplaced index entries caused no stage-A conflict in update mode");
      errors = errors + 1;
    end
    errors = errors + hp_err + px_err;
    $display("top_tb preu=%0d hp=%0d photons=%0d ops=%0d (index writes held for photons_done: %0d cycles): update %0d cycles (util %0d%%; short cycles haz %0d dup %0d bank %0d abank %0d starve %0d), radiance %0d cycles (haz %0d dup %0d bank %0d abank %0d starve %0d); mismatches: hit points %0d, pixels %0d",
             NumPreu, nhp, nph, nops, held, upd_cycles, upd_cycles ? ops_upd * 100 / (NumPreu * upd_cycles) : 0,
             cnt_upd[2*48 +: 48], cnt_upd[3*48 +: 48], cnt_upd[4*48 +: 48], cnt_upd[5*48 +: 48],
             cnt_upd[6*48 +: 48], rad_count(1), rad_count(2), rad_count(3), rad_count(4), rad_count(5),
             rad_count(6), hp_err, px_err);
    if (errors != 0) $fatal(1, "top_tb: FAIL, %0d mismatches", errors);
    $display("top_tb: PASS");
    $finish;
  end
endmodule

`default_nettype wire
