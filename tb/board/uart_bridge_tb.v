// SPDX-License-Identifier: Apache-2.0
// uart_bridge_tb: pree_uart_axi (pree_uart_bridge in front of the real pree_axi, narrow memories,
// NumPreu PREUs: a parameter, 1 or 2), driven over its UART by a host written here (its own
// transmitter and receiver, Div clock cycles a bit). Checks: register reads (VERSION, CONFIG0) and
// their 'r' replies; an unknown command byte's '?'; register writes ('b'); two hit points pushed on
// s_axis_hp ('a' each, HP_PTR then reads 2); CMD 2 reading them back, which must arrive as two
// m_axis beats (header 0x80, then 0x82 with TLAST) equal to what was pushed; an update batch the
// way pree_be_uart.c sends one (each photon's candidates as 'C' beats of up to NumPreu lanes in
// whole bytes, then its photon beat, 'L' on the last): every candidate beat reaching pree_axi's
// s_axis_cand equals the one sent, TKEEP and TDATA lane for lane; after the batch-done interrupt
// ERR is 0, PH_IN and CAND_IN count the photons and candidates, and CMD 2 reads hit point 0 (a
// candidate within its radius) updated to the exact words of the paper datapath and hit point 1
// (a candidate of both photons, out of their reach) unchanged; then photon beats ('a' each)
// until the wrapper's photon FIFO is full (no candidates), and a byte sent while the bridge
// waits on the next one sets the overrun flag. Prints "uart_bridge_tb: PASS" or the first
// difference and "FAIL".
`timescale 1ns / 1ps
`default_nettype none

module uart_bridge_tb;

  parameter NumPreu = 2;

  localparam Div = 4, HpRecW = 384, NB = HpRecW / 8;
  localparam CandW = 36 * NumPreu, CB = (CandW + 7) / 8;     // a 'C' payload: whole bytes

  reg clk = 1'b0, rst_n = 1'b0, host_tx = 1'b1;
  always #5 clk = ~clk;

  wire dev_tx, overrun, irq;
  pree_uart_axi #(.NumPreu(NumPreu), .HpAW(6), .HpBankW(2), .IdxAW(4), .PxAW(4), .PxBankW(2),
                  .CntW(8), .PipeFast(0), .PhFifoAW(1), .CountW(6), .Div(Div)) u_dut (
    .clk_i(clk), .rst_ni(rst_n), .rx_i(host_tx), .tx_o(dev_tx), .overrun_o(overrun),
    .irq_o(irq));

  // The host's receiver: every byte the bridge sends, in order, into rx_buf.
  reg [7:0] rx_buf [0:1023];
  integer   rx_n = 0, rd = 0, k;
  reg [7:0] rb;
  always begin
    @(negedge dev_tx);
    repeat (Div / 2) @(posedge clk);
    if (dev_tx == 1'b0) begin
      for (k = 0; k < 8; k = k + 1) begin
        repeat (Div) @(posedge clk);
        rb[k] = dev_tx;
      end
      repeat (Div) @(posedge clk);
      if (dev_tx !== 1'b1) begin
        $display("uart_bridge_tb: stop bit low after byte %0d", rx_n);
        $display("FAIL");
        $finish;
      end
      rx_buf[rx_n] = rb;
      rx_n = rx_n + 1;
    end
  end

  task send_byte;
    input [7:0] b;
    integer i;
    begin
      host_tx = 1'b0;
      repeat (Div) @(posedge clk);
      for (i = 0; i < 8; i = i + 1) begin
        host_tx = b[i];
        repeat (Div) @(posedge clk);
      end
      host_tx = 1'b1;
      repeat (Div) @(posedge clk);
    end
  endtask

  task next_byte;
    output [7:0] b;
    begin
      while (rx_n <= rd) @(posedge clk);
      b  = rx_buf[rd];
      rd = rd + 1;
    end
  endtask

  task fail;
    input [8*48-1:0] what;
    begin
      $display("uart_bridge_tb: %0s", what);
      $display("FAIL");
      $finish;
    end
  endtask

  task expect_byte;
    input [7:0] want;
    reg [7:0] got;
    begin
      next_byte(got);
      if (got !== want) begin
        $display("uart_bridge_tb: byte %0d is %h, expected %h", rd - 1, got, want);
        fail("unexpected reply");
      end
    end
  endtask

  task reg_write;
    input [15:0] addr;
    input [31:0] data;
    integer i;
    begin
      send_byte(8'h57);
      for (i = 5; i >= 0; i = i - 1) send_byte({addr, data} >> (8 * i));
    end
  endtask

  task reg_write_ok;
    input [15:0] addr;
    input [31:0] data;
    begin
      reg_write(addr, data);
      expect_byte(8'h62);
    end
  endtask

  task reg_read;
    input  [15:0] addr;
    output [31:0] data;
    begin
      send_byte(8'h52);
      send_byte(addr[15:8]);
      send_byte(addr[7:0]);
      expect_byte(8'h72);
      next_byte(data[31:24]);
      next_byte(data[23:16]);
      next_byte(data[15:8]);
      next_byte(data[7:0]);
    end
  endtask

  task reg_read_expect;
    input [15:0] addr;
    input [31:0] want;
    reg   [31:0] got;
    begin
      reg_read(addr, got);
      if (got !== want) begin
        $display("uart_bridge_tb: register 0x%h reads %h, expected %h", addr, got, want);
        fail("a register reads a wrong value");
      end
    end
  endtask

  // The hit points pushed (hp) and those CMD 2 must read back (want).
  reg [HpRecW-1:0] hp [0:1], want [0:1];
  reg [HpRecW-1:0] got_beat;
  reg [7:0]        h;
  integer          i, j, k2, beats, writes, blocked;

  // CMD 2 over hit points 0 and 1: two m_axis beats equal to want, and the write's reply, in
  // either order.
  task read_back;
    begin
      reg_write_ok(16'h040, 32'd0);                          // HP_PTR = 0
      reg_write_ok(16'h044, 32'd2);                          // HP_COUNT = 2
      reg_write(16'h014, 32'd2);                             // CMD 2: read the hit points
      beats  = 0;
      writes = 0;
      while (beats < 2 || writes < 1) begin
        next_byte(h);
        if (h == 8'h62) begin
          writes = writes + 1;
        end else if (h == (beats == 1 ? 8'h82 : 8'h80)) begin
          for (j = NB - 1; j >= 0; j = j - 1) begin
            next_byte(rb);
            got_beat[8 * j +: 8] = rb;
          end
          if (got_beat !== want[beats]) begin
            $display("uart_bridge_tb: beat %0d is %h", beats, got_beat);
            $display("uart_bridge_tb: expected   %h", want[beats]);
            fail("a hit point read back differs");
          end
          beats = beats + 1;
        end else begin
          $display("uart_bridge_tb: byte %h after CMD 2", h);
          fail("unexpected byte");
        end
      end
    end
  endtask

  // Candidate beats: each one sent is recorded in cand_sent; every beat s_axis_cand takes must
  // be the next of them, bit for bit.
  reg [CandW-1:0] cand_sent [0:15];
  integer         cand_n = 0, cand_got = 0;

  always @(posedge clk)
    if (u_dut.u_pree.s_axis_cand_tvalid && u_dut.u_pree.s_axis_cand_tready) begin
      if (cand_got >= cand_n) fail("s_axis_cand took a beat never sent");
      if ({u_dut.u_pree.s_axis_cand_tkeep, u_dut.u_pree.s_axis_cand_tdata} !==
          cand_sent[cand_got]) begin
        $display("uart_bridge_tb: candidate beat %0d is {tkeep %h, tdata %h}, sent %h", cand_got,
                 u_dut.u_pree.s_axis_cand_tkeep, u_dut.u_pree.s_axis_cand_tdata,
                 cand_sent[cand_got]);
        fail("a candidate beat differs from the one sent");
      end
      cand_got = cand_got + 1;
    end

  // 'C': {tkeep, tdata} zero-padded to CB bytes, most significant first; reply 'a'.
  task send_cand;
    input [CandW-1:0] beat;
    reg   [8*CB-1:0]  pad;
    integer b;
    begin
      cand_sent[cand_n] = beat;
      cand_n = cand_n + 1;
      pad = beat;
      send_byte(8'h43);
      for (b = CB - 1; b >= 0; b = b - 1) send_byte(pad[8 * b +: 8]);
      expect_byte(8'h61);
    end
  endtask

  // A photon as pree_be_uart.c sends it: its candidates (cands[32c +: 32], N^P of them, ph's
  // slot 6) in beats of up to NumPreu lanes, then the photon beat, 'L' (TLAST) when last.
  task send_photon;
    input         last;
    input [255:0] ph;
    input [63:0]  cands;
    reg   [CandW-1:0] beat;
    integer n, c, l, b;
    begin
      n = ph[192 +: 32];
      for (c = 0; c < n; c = c + NumPreu) begin
        beat = {CandW{1'b0}};
        for (l = 0; l < NumPreu && c + l < n; l = l + 1) begin
          beat[32 * l +: 32] = cands[32 * (c + l) +: 32];
          beat[32 * NumPreu + 4 * l +: 4] = 4'hf;
        end
        send_cand(beat);
      end
      send_byte(last ? 8'h4c : 8'h50);
      for (b = 31; b >= 0; b = b - 1) send_byte(ph[8 * b +: 8]);
      expect_byte(8'h61);
    end
  endtask

  // binary32 words of the update batch.
  localparam [31:0] F0 = 32'h0000_0000, F_HALF = 32'h3f00_0000, F1 = 32'h3f80_0000,
                    F2 = 32'h4000_0000, F3 = 32'h4040_0000, F3_5 = 32'h4060_0000,
                    F4 = 32'h4080_0000, F_M8 = 32'hc100_0000, INV_PI = 32'h3ea2_f983;
  reg [31:0] st;
  reg [31:0] poll;

  initial begin
    #2_000_000;
    fail("timeout");
  end

  initial begin
    // Hit points {pixel, f b g r, pos z y x, n, r2, tau b g r}: 0 at (1, 2, 3), 1 at (-8, 0, 0),
    // both radius 2 (r2 = 4), N = 0, f = 1; 1 with tau 0.5 (so that an update would show).
    hp[0] = {32'd5, F1, F1, F1, F3, F2, F1, F0, F4, F0, F0, F0};
    hp[1] = {32'd6, F1, F1, F1, F0, F0, F_M8, F0, F4, F_HALF, F_HALF, F_HALF};
    repeat (10) @(posedge clk);
    rst_n = 1'b1;
    repeat (10) @(posedge clk);
    reg_read_expect(16'h000, 32'h0002_0000);                 // VERSION
    reg_read_expect(16'h004, {3'd0, 5'd4, 3'd0, 5'd4, 3'd0, 5'd6, NumPreu[7:0]});
                                                             // CONFIG0: IdxAW, PxAW, HpAW, NumPreu
    send_byte(8'h5a);                                        // unknown
    expect_byte(8'h3f);
    reg_write_ok(16'h034, F_HALF);                           // ALPHA = 0.5
    reg_write_ok(16'h040, 32'd0);                            // HP_PTR = 0
    for (i = 0; i < 2; i = i + 1) begin
      send_byte(8'h48);
      for (j = NB - 1; j >= 0; j = j - 1) send_byte(hp[i] >> (8 * j));
      expect_byte(8'h61);
    end
    reg_read_expect(16'h040, 32'd2);                         // HP_PTR counted the beats
    want[0] = hp[0];
    want[1] = hp[1];
    read_back;
    if (overrun !== 1'b0) fail("overrun set by a well-behaved host");
    // The update batch: photon A at (1, 2, 3.5), phi (1, 2, 4), candidates 1 and 0; photon B,
    // the same, candidate 1 only, TLAST. Hit point 0 accepts A (d2 0.25 <= 4) and is no
    // candidate of B; hit point 1 (d2 97.25) accepts neither. With alpha 0.5 every value is
    // exact: g = (0 + 0.5) / (0 + 1) = 0.5, N' = 0.5, r2' = 2, tau' = (f phi INV_PI) g.
    send_photon(1'b0, {F0, 32'd2, F4, F2, F1, F3_5, F2, F1}, {32'd0, 32'd1});
    send_photon(1'b1, {F0, 32'd1, F4, F2, F1, F3_5, F2, F1}, {32'd0, 32'd1});
    poll = 0;
    st   = 0;
    while (!st[0]) begin                                     // IRQ_STATUS: batch done
      reg_read(16'h020, st);
      poll = poll + 1;
      if (poll > 50) fail("no batch-done interrupt");
    end
    if (cand_got !== cand_n) fail("a candidate beat sent never reached s_axis_cand");
    reg_read_expect(16'h024, 32'd0);                         // ERR
    reg_read_expect(16'h050, 32'd2);                         // PH_IN
    reg_read_expect(16'h058, 32'd3);                         // CAND_IN
    want[0] = {32'd5, F1, F1, F1, F3, F2, F1, F_HALF, F2,
               INV_PI + 32'h0080_0000, INV_PI, INV_PI - 32'h0080_0000};
    want[1] = hp[1];
    read_back;
    if (overrun !== 1'b0) fail("overrun set by a well-behaved host");
    // Photons without candidates stay in the wrapper's photon FIFO, so one is finally not taken;
    // a byte sent while the bridge waits on it is an overrun.
    i = 0;
    blocked = 0;
    while (!blocked && i < 8) begin
      send_byte(8'h50);
      for (j = 31; j >= 0; j = j - 1) send_byte(j == 24 ? 8'h01 : 8'h00);   // N^P = 1
      k2 = 0;
      while (rx_n <= rd && k2 < 500) begin
        @(posedge clk);
        k2 = k2 + 1;
      end
      if (rx_n <= rd) blocked = 1;
      else expect_byte(8'h61);
      i = i + 1;
    end
    if (!blocked) fail("eight photons without candidates all taken");
    send_byte(8'h52);
    repeat (Div) @(posedge clk);                             // the receiver's synchroniser
    if (overrun !== 1'b1) fail("no overrun for a byte sent while a beat waits");
    $display("uart_bridge_tb: PASS (NumPreu %0d: %0d candidate beats, %0d bytes received, photon %0d not taken)",
             NumPreu, cand_n, rx_n, i);
    $finish;
  end

endmodule
