// SPDX-License-Identifier: Apache-2.0
// uart_bridge_tb: pree_uart_axi (pree_uart_bridge in front of the real pree_axi, narrow memories),
// driven over its UART by a host written here (its own transmitter and receiver, Div clock
// cycles a bit). Checks: a register read (VERSION) and its 'r' reply; an
// unknown command byte's '?'; register writes ('b'); two hit points pushed on s_axis_hp ('a' each,
// HP_PTR then reads 2); CMD 2 reading them back, which must arrive as two m_axis beats (header
// 0x80, then 0x82 with TLAST) equal to what was pushed; photon beats ('a' each) until the
// wrapper's photon FIFO is full (no candidates), and a byte sent while the bridge waits on the
// next one sets the overrun flag. Prints "uart_bridge_tb: PASS" or the first difference and "FAIL".
`timescale 1ns / 1ps
`default_nettype none

module uart_bridge_tb;

  localparam Div = 4, HpRecW = 384, NB = HpRecW / 8;

  reg clk = 1'b0, rst_n = 1'b0, host_tx = 1'b1;
  always #5 clk = ~clk;

  wire dev_tx, overrun, irq;
  pree_uart_axi #(.NumPreu(2), .HpAW(6), .HpBankW(2), .IdxAW(4), .PxAW(4), .PxBankW(2), .CntW(8),
                  .PipeFast(0), .PhFifoAW(1), .CountW(6), .Div(Div)) u_dut (
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

  task reg_read_expect;
    input [15:0] addr;
    input [31:0] want;
    begin
      send_byte(8'h52);
      send_byte(addr[15:8]);
      send_byte(addr[7:0]);
      expect_byte(8'h72);
      expect_byte(want[31:24]);
      expect_byte(want[23:16]);
      expect_byte(want[15:8]);
      expect_byte(want[7:0]);
    end
  endtask

  reg [HpRecW-1:0] hp [0:1];
  reg [HpRecW-1:0] got_beat;
  reg [7:0]        h;
  integer          i, j, k2, beats, writes, blocked;

  initial begin
    #2_000_000;
    fail("timeout");
  end

  initial begin
    for (i = 0; i < 2; i = i + 1)
      for (j = 0; j < HpRecW / 32; j = j + 1)
        hp[i][32 * j +: 32] = 32'h9e3779b9 * (i * 16 + j + 1);
    for (i = 0; i < 2; i = i + 1) hp[i][HpRecW-1 -: 32] = i + 5;   // pixel slot: PxAW bits
    repeat (10) @(posedge clk);
    rst_n = 1'b1;
    repeat (10) @(posedge clk);
    reg_read_expect(16'h000, 32'h0002_0000);                 // VERSION
    send_byte(8'h5a);                                        // unknown
    expect_byte(8'h3f);
    reg_write(16'h040, 32'd0);                               // HP_PTR = 0
    expect_byte(8'h62);
    for (i = 0; i < 2; i = i + 1) begin
      send_byte(8'h48);
      for (j = NB - 1; j >= 0; j = j - 1) send_byte(hp[i] >> (8 * j));
      expect_byte(8'h61);
    end
    reg_read_expect(16'h040, 32'd2);                         // HP_PTR counted the beats
    reg_write(16'h040, 32'd0);
    expect_byte(8'h62);
    reg_write(16'h044, 32'd2);                               // HP_COUNT = 2
    expect_byte(8'h62);
    reg_write(16'h014, 32'd2);                               // CMD 2: read the hit points
    beats  = 0;
    writes = 0;
    while (beats < 2 || writes < 1) begin                    // the write's reply and the beats,
      next_byte(h);                                          // in either order
      if (h == 8'h62) begin
        writes = writes + 1;
      end else if (h == (beats == 1 ? 8'h82 : 8'h80)) begin
        for (j = NB - 1; j >= 0; j = j - 1) begin
          next_byte(rb);
          got_beat[8 * j +: 8] = rb;
        end
        if (got_beat !== hp[beats]) begin
          $display("uart_bridge_tb: beat %0d is %h", beats, got_beat);
          fail("a hit point read back differs");
        end
        beats = beats + 1;
      end else begin
        $display("uart_bridge_tb: byte %h after CMD 2", h);
        fail("unexpected byte");
      end
    end
    if (overrun !== 1'b0) fail("overrun set by a well-behaved host");
    // Photons without candidates stay in the wrapper's photon FIFO, so one is finally not taken;
    // a byte sent while the bridge waits on it is an overrun.
    i = 0;
    blocked = 0;
    while (!blocked && i < 8) begin
      send_byte(8'h50);
      for (j = 31; j >= 0; j = j - 1) send_byte(j == 24 ? 8'h01 : 8'h00);   // N^P = 1
      k2 = 0;
      while (rx_n <= rd && k2 < 2000) begin
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
    $display("uart_bridge_tb: PASS (%0d bytes received, photon %0d not taken)", rx_n, i);
    $finish;
  end

endmodule
