// SPDX-License-Identifier: Apache-2.0
// axi_wrap_drv: one host for the wrapper bench (tb/axi/axi_wrap_tb.v) on one pree_axi: loads
// 2^HpAW hit points, streams NumPhotons photons in batches of Batch (tlast on each batch's last
// photon) and their candidates with random gaps and random lane counts from its own Seed, waits
// for each batch's interrupt (the engine drains there: with Batch = 2^CountW the photon-done
// count rests at a multiple of 2^CountW, where it wraps to 0), checks the
// running counts (PH_IN, PH_DONE, CAND_IN modulo 2^CountW), reads every hit point back, runs the
// radiance pass and reads every pixel; before and after, it checks that a counter's high half
// read first is 0 and that commands reading hit points never loaded or pixels never cleared are
// refused (ERR bit 0, no interrupt). Photons go Ppc slots a beat, some slots left empty at random.
// The stimulus is a function of the photon number only, so
// two drivers with different seeds send the same data under different back-pressure. Fails
// ($fatal) when a stream makes no progress for StallLimit cycles (a deadlock) or on a protocol
// error; results in hp_res / px_res, done_o high at the end.
`default_nettype none

module axi_wrap_drv #(
  parameter NumPreu    = 4,
  parameter HpAW       = 8,
  parameter PxAW       = 6,
  parameter CountW     = 32,
  parameter Ppc        = 1,      // photon slots a beat (the wrapper's PhotonsPerCycle)
  parameter NumPhotons = 600,
  parameter Batch      = 64,
  parameter Seed       = 1,
  parameter StallLimit = 20000,
  parameter HpRecW     = 384     // paper datapath: {pixel, f, pos, state (160)}
) (
  input  wire                    aclk,
  output reg                     aresetn,
  output reg  [11:0]             awaddr,
  output reg                     awvalid,
  input  wire                    awready,
  output reg  [31:0]             wdata,
  output reg                     wvalid,
  input  wire                    wready,
  input  wire                    bvalid,
  output reg                     bready,
  output reg  [11:0]             araddr,
  output reg                     arvalid,
  input  wire                    arready,
  input  wire [31:0]             rdata,
  input  wire                    rvalid,
  output reg                     rready,
  output reg  [256*Ppc-1:0]      ph_tdata,
  output reg                     ph_tlast,
  output reg                     ph_tvalid,
  input  wire                    ph_tready,
  output reg  [32*NumPreu-1:0]   cand_tdata,
  output reg  [4*NumPreu-1:0]    cand_tkeep,
  output reg                     cand_tvalid,
  input  wire                    cand_tready,
  output reg  [HpRecW-1:0]       hp_tdata,
  output reg                     hp_tvalid,
  input  wire                    hp_tready,
  input  wire [HpRecW-1:0]       m_tdata,
  input  wire                    m_tuser,
  input  wire                    m_tlast,
  input  wire                    m_tvalid,
  output reg                     m_tready,
  input  wire                    irq,
  output reg                     done_o
);

  localparam NHP = 1 << HpAW;
  localparam NPX = 1 << PxAW;
  localparam [31:0] ONE = 32'h3f80_0000;
  localparam [63:0] MASK64 = (64'd1 << CountW) - 64'd1;
  localparam [31:0] MASK = MASK64[31:0];   // a running count's bits

  // The stimulus: photon k's candidate count (1 .. 8), its candidates (distinct hit points), its
  // position (each coordinate in +-[0.25, 1)) and flux ([0.5, 1) a channel).
  function [31:0] mix;
    input [31:0] x;
    reg [31:0] y;
    begin
      y = x * 32'h9e37_79b1;
      y = y ^ (y >> 15);
      y = y * 32'h85eb_ca6b;
      mix = y ^ (y >> 13);
    end
  endfunction
  function [31:0] ph_n;
    input integer k;
    ph_n = 32'd1 + (mix(k) % 32'd8);
  endfunction
  function [HpAW-1:0] cand;
    input integer k, i;
    reg [31:0] c;
    begin
      c = mix(k + 32'h1234_0000) + 32'd37 * i;
      cand = c[HpAW-1:0];
    end
  endfunction
  function [31:0] coord;
    input integer k, c;
    reg [31:0] r;
    begin
      r = mix(k * 8 + c + 32'h5555_0000);
      coord = {r[31], 7'h3e, r[24], r[22:0]};
    end
  endfunction
  function [31:0] flux;
    input integer k, c;
    reg [31:0] r;
    begin
      r = mix(k * 8 + c + 32'h7777_0000);
      flux = {9'h07e, r[22:0]};
    end
  endfunction

  integer seed = Seed;
  function gap;   // hold back in this cycle, one time in three
    input dummy;
    gap = ($random(seed) & 3) == 0;
  endfunction

  reg [HpRecW-1:0] hp_res [0:NHP-1];
  reg [95:0]       px_res [0:NPX-1];
  reg              go;           // the photon and candidate streams run
  integer          ph_k, ph_beat, ck, ci, c_sent, c_total, beat_n, rx, rx_n, idle_cnt;
  integer          ph_end, c_end;  // the current batch's photons and candidates end here
  reg              rx_user;

  // ---- AXI4-Lite.
  task lite_write;
    input [11:0] a;
    input [31:0] d;
    begin
      @(posedge aclk);
      awaddr <= a; wdata <= d; awvalid <= 1'b1; wvalid <= 1'b1; bready <= 1'b1;
      @(posedge aclk);
      while (awvalid || wvalid || bready) begin
        if (awvalid && awready) awvalid <= 1'b0;
        if (wvalid && wready)   wvalid  <= 1'b0;
        if (bvalid && bready)   bready  <= 1'b0;
        @(posedge aclk);
      end
    end
  endtask
  task lite_read;
    input  [11:0] a;
    output [31:0] d;
    begin
      @(posedge aclk);
      araddr <= a; arvalid <= 1'b1; rready <= 1'b1;
      @(posedge aclk);
      while (arvalid || rready) begin
        if (arvalid && arready) arvalid <= 1'b0;
        if (rvalid && rready) begin
          rready <= 1'b0;
          d = rdata;
          if (^rdata === 1'bx) $fatal(1, "axi_wrap_drv %0d: register 0x%03x reads X", Seed, a);
        end
        @(posedge aclk);
      end
    end
  endtask
  task wait_irq;   // an interrupt cause, then clear it
    input [1:0] cause;
    reg [31:0] st;
    integer guard;
    begin
      st = 32'd0;
      guard = 0;
      while ((st & cause) == 0) begin
        while (!irq) begin
          @(posedge aclk);
          guard = guard + 1;
          if (guard > StallLimit)
            $fatal(1, "axi_wrap_drv %0d: no interrupt 0x%0x (photons %0d, candidates %0d)", Seed,
                   cause, ph_k, c_sent);
        end
        lite_read(12'h020, st);
      end
      lite_write(12'h020, {30'd0, cause});
    end
  endtask
  task read_cmd;   // a read command of n beats into hp_res / px_res
    input [2:0] c;
    input integer n;
    begin
      rx = 0; rx_n = n; rx_user = c == 3'd4;
      lite_write(12'h014, {29'd0, c});
      wait_irq(2'b10);
      if (rx != n) $fatal(1, "axi_wrap_drv %0d: %0d beats of %0d", Seed, rx, n);
    end
  endtask
  task expect_reg;
    input [11:0] a;
    input [31:0] want;
    input [8*8-1:0] name;
    reg [31:0] v;
    begin
      lite_read(a, v);
      if (v !== want) $fatal(1, "axi_wrap_drv %0d: %0s = %0d, expected %0d", Seed, name, v, want);
    end
  endtask

  task refused;   // a command that must be refused: ERR bit 0, no interrupt, no beat
    input [2:0] c;
    begin
      rx = 0; rx_n = 0;
      lite_write(12'h014, {29'd0, c});
      expect_reg(12'h024, 32'd1, "ERR");
      lite_write(12'h024, 32'd1);
      expect_reg(12'h020, 32'd0, "IRQ_STAT");
    end
  endtask

  // ---- Photons, up to Ppc a beat in photon order; with Ppc > 1 a slot is left empty (N^P 0)
  // at random, and the batch's last photon ends its beat (tlast), the slots after it empty.
  always @(posedge aclk) begin : photons
    integer n, s, b;
    reg fill;
    if (go) begin
      n = ph_k;
      if (ph_tvalid && ph_tready) n = n + ph_beat;
      ph_k <= n;
      if ((!ph_tvalid || ph_tready) && n < ph_end && !gap(0)) begin
        b = 0;
        for (s = 0; s < Ppc; s = s + 1) begin
          fill = n + b < ph_end && !(Ppc > 1 && gap(0));
          if (fill)
            ph_tdata[256*s +: 256] <= {32'd0, ph_n(n + b), flux(n + b, 2), flux(n + b, 1),
                                       flux(n + b, 0), coord(n + b, 2), coord(n + b, 1),
                                       coord(n + b, 0)};
          else
            ph_tdata[256*s +: 256] <= {32'd0, 32'd0, {6{32'h7fc0_0000}}};   // empty: N^P 0
          if (fill) b = b + 1;
        end
        ph_tvalid <= 1'b1;
        ph_tlast  <= n + b == ph_end;
        ph_beat   <= b;
      end else if (ph_tready) begin
        ph_tvalid <= 1'b0;
      end
    end
  end

  // ---- Candidates, in photon order, 1 .. NumPreu a beat in random lanes.
  always @(posedge aclk) begin : candidates
    integer j, k, placed;
    integer nk, ni;
    if (go) begin
      if (cand_tvalid && cand_tready) c_sent = c_sent + beat_n;
      if ((!cand_tvalid || cand_tready) && c_sent < c_end && !gap(0)) begin
        k = 1 + ($random(seed) & 32'h7fff_ffff) % NumPreu;
        if (k > c_end - c_sent) k = c_end - c_sent;
        placed = 0;
        nk = ck; ni = ci;
        for (j = 0; j < NumPreu; j = j + 1) begin
          cand_tkeep[4*j +: 4] <= 4'h0;
          cand_tdata[32*j +: 32] <= 32'hdead_beef;
          if (placed < k && !(NumPreu - j > k - placed && ($random(seed) & 3) == 0)) begin
            cand_tkeep[4*j +: 4] <= 4'hf;
            cand_tdata[32*j +: 32] <= {{(32-HpAW){1'b0}}, cand(nk, ni)};
            placed = placed + 1;
            ni = ni + 1;
            if (ni == ph_n(nk)) begin nk = nk + 1; ni = 0; end
          end
        end
        ck = nk; ci = ni;
        beat_n = k;
        cand_tvalid <= 1'b1;
      end else if (cand_tready) begin
        cand_tvalid <= 1'b0;
      end
    end
  end

  // ---- Results: every m_axis beat, with random back-pressure.
  always @(posedge aclk) begin : results
    if (m_tvalid && m_tready) begin
      if (rx >= rx_n || m_tuser !== rx_user || m_tlast !== (rx + 1 == rx_n))
        $fatal(1, "axi_wrap_drv %0d: m_axis beat %0d out of place", Seed, rx);
      if (rx_user) px_res[rx] = m_tdata[95:0];
      else         hp_res[rx] = m_tdata;
      rx = rx + 1;
    end
    m_tready <= !gap(0);
  end

  // ---- Progress: a stream that stops for StallLimit cycles is a deadlock.
  always @(posedge aclk) begin : watchdog
    if (go && ((ph_tvalid && ph_tready) || (cand_tvalid && cand_tready))) idle_cnt <= 0;
    else if (go && (ph_k < ph_end || c_sent < c_end)) begin
      idle_cnt <= idle_cnt + 1;
      if (idle_cnt > StallLimit)
        $fatal(1, "axi_wrap_drv %0d (CountW %0d): stalled after %0d photons and %0d candidates",
               Seed, CountW, ph_k, c_sent);
    end
  end

  integer i;
  reg [31:0] v;
  initial begin
    aresetn = 1'b0; awvalid = 1'b0; wvalid = 1'b0; bready = 1'b0; arvalid = 1'b0;
    rready = 1'b0; ph_tvalid = 1'b0; ph_tlast = 1'b0; cand_tvalid = 1'b0; hp_tvalid = 1'b0;
    m_tready = 1'b0; go = 1'b0; done_o = 1'b0; awaddr = 12'd0; araddr = 12'd0; wdata = 32'd0;
    ph_tdata = {256*Ppc{1'b0}}; ph_beat = 0; cand_tdata = {32*NumPreu{1'b0}}; cand_tkeep = {4*NumPreu{1'b0}};
    hp_tdata = {HpRecW{1'b0}};
    ph_k = 0; ck = 0; ci = 0; c_sent = 0; beat_n = 0; rx = 0; rx_n = 0; rx_user = 1'b0;
    idle_cnt = 0;
    ph_end = 0; c_end = 0;
    c_total = 0;
    for (i = 0; i < NumPhotons; i = i + 1) c_total = c_total + ph_n(i);
    repeat (4) @(posedge aclk);
    aresetn <= 1'b1;
    repeat (4) @(posedge aclk);
    // After reset: a counter's high half read first is 0; reading a hit point never loaded or a
    // pixel never cleared is refused (ERR bit 0, no beat).
    expect_reg(12'h104, 32'd0, "CNT0 hi");
    lite_write(12'h044, 32'd1);
    refused(3'd2);
    lite_write(12'h04c, 32'd1);
    refused(3'd4);
    // Configuration: alpha 0.7, both interrupts.
    lite_write(12'h034, 32'h3f33_3333);
    lite_write(12'h01c, 32'd3);
    // Hit points 0 .. NHP-1: at the origin, f 1, r2 4, n 0, tau 0, pixel i mod NPX.
    for (i = 0; i < NHP; i = i + 1) begin
      @(posedge aclk);
      hp_tvalid <= 1'b1;
      hp_tdata  <= {i % NPX, ONE, ONE, ONE, 96'd0, 32'd0, 32'h4080_0000, 96'd0};
      @(posedge aclk);
      while (!hp_tready) @(posedge aclk);
      hp_tvalid <= 1'b0;
    end
    expect_reg(12'h040, NHP, "HP_PTR");
    lite_write(12'h010, 32'd1);
    go = 1'b1;
    while (ph_end < NumPhotons) begin
      for (i = ph_end; i < ph_end + Batch && i < NumPhotons; i = i + 1) c_end = c_end + ph_n(i);
      ph_end = i;
      wait_irq(2'b01);
      while (ph_k < ph_end || c_sent < c_end) @(posedge aclk);
    end
    expect_reg(12'h050, NumPhotons & MASK, "PH_IN");
    expect_reg(12'h054, NumPhotons & MASK, "PH_DONE");
    expect_reg(12'h058, c_total & MASK, "CAND_IN");
    expect_reg(12'h024, 32'd0, "ERR");
    // Beyond the hit points loaded: refused.
    lite_write(12'h040, NHP - 1);
    lite_write(12'h044, 32'd2);
    refused(3'd2);
    lite_write(12'h03c, NHP + 1);
    refused(3'd1);
    // Every hit point back.
    lite_write(12'h040, 32'd0);
    lite_write(12'h044, NHP);
    read_cmd(3'd2, NHP);
    // The radiance pass over every pixel.
    lite_write(12'h048, 32'd0);
    lite_write(12'h04c, NPX);
    lite_write(12'h014, 32'd3);
    wait_irq(2'b10);
    lite_write(12'h030, 32'h4b00_0000);
    lite_write(12'h03c, NHP);
    lite_write(12'h014, 32'd1);
    wait_irq(2'b10);
    read_cmd(3'd4, NPX);
    lite_write(12'h048, 32'd1);   // beyond the pixels cleared
    refused(3'd4);
    $display("axi_wrap_drv %0d (CountW %0d): %0d photons, %0d candidates, done", Seed, CountW,
             NumPhotons, c_total);
    done_o = 1'b1;
  end

endmodule

`default_nettype wire
