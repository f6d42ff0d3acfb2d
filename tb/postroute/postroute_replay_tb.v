`timescale 1ps / 1ps
// SPDX-License-Identifier: Apache-2.0
// postroute_replay_tb: the timing-annotated post-route run (docs/fpga_board.md, "Timing-annotated
// run"; mk/postroute.mk, tests/checks/postroute_sdf.sh) under Icarus Verilog. It replays a
// recorded UART exchange on a routed netlist with the board top's ports (module pree_ulx3s,
// written back by Yosys with the cell models of tb/postroute/): the ftdi_txd level of every
// clock cycle from a record, and compares the ftdi_rxd level after every rising edge with the
// record's, sampled 1 ps before the next rising edge (so an output has the whole period).
// The records are those of host/postroute_uart.cpp (PREE_POSTROUTE_RECORD): one line
// "<cycle> <level>" each time a level changes, ftdi_txd set before that cycle's rising edge
// (idle high before the first line), ftdi_rxd seen after it (compared from the record's first
// line on). Cycle n's rising edge is at settle + (n + 1/2) x the period; btn_pwr_n is low for
// cycles 0 and 1 (the harness's reset), then high. Before cycle 0 the clock stays low for the
// settle time: in silicon every LUT and wire holds its value when configuration ends, while in
// simulation each net starts x and takes its path's delays to settle, and a first edge before
// that stores x in registers without reset (on d1, at 23.8 ns and a first edge at 11.9 ns, the
// hit-point queue's payload from cycle 0, and the first reply never came).
// Plusargs:
//   +txd=FILE      the ftdi_txd record (required)
//   +rxd=FILE      the expected ftdi_rxd record: the first differing cycle is a FAIL
//   +rxd_out=FILE  write the ftdi_rxd record of this run instead
//   +cycles=N      cycles to run (required)
//   +period=PS     the clock period in picoseconds (default 40000)
//   +sdf=FILE      $sdf_annotate this SDF (scripts/postroute_sdf.py's) on the netlist
//   +settle=PS     the time before cycle 0, the clock low (default 1000000: 1 us)
// Prints "PASS: ..." or "FAIL: ..." with the first differing cycle.
`default_nettype none

module postroute_replay_tb;
  reg         clk = 1'b0, btn = 1'b0, txd = 1'b1;
  wire        rxd;
  wire [3:0]  led;

  pree_ulx3s dut (.clk_25mhz(clk), .btn_pwr_n(btn), .ftdi_txd(txd), .ftdi_rxd(rxd), .led(led));

  reg [8*512-1:0] txd_file, rxd_file, out_file, sdf_file;
  integer     fd_txd, fd_rxd, fd_out, period, settle, cycles, n, rc;
  integer     next_txd_cyc, next_txd_lvl, next_rxd_cyc, next_rxd_lvl, want_rxd, last_rxd;
  integer     compared, txd_changes, rxd_changes;
  reg         compare;

  // The next change of a record (cycle -1: none left).
  task next_line;
    input  integer fd;
    output integer cyc;
    output integer lvl;
    begin
      if ($fscanf(fd, "%d %d\n", cyc, lvl) != 2) cyc = -1;
    end
  endtask

  initial begin
    if (!$value$plusargs("txd=%s", txd_file) || !$value$plusargs("cycles=%d", cycles)) begin
      $display("FAIL: +txd=FILE and +cycles=N are required");
      $finish;
    end
    if (!$value$plusargs("period=%d", period)) period = 40000;
    if (!$value$plusargs("settle=%d", settle)) settle = 1000000;
    compare = $value$plusargs("rxd=%s", rxd_file);
    fd_txd = $fopen(txd_file, "r");
    if (fd_txd == 0) begin
      $display("FAIL: cannot open %0s", txd_file);
      $finish;
    end
    fd_rxd = 0;
    fd_out = 0;
    if (compare) begin
      fd_rxd = $fopen(rxd_file, "r");
      if (fd_rxd == 0) begin
        $display("FAIL: cannot open %0s", rxd_file);
        $finish;
      end
      next_line(fd_rxd, next_rxd_cyc, next_rxd_lvl);
    end else if ($value$plusargs("rxd_out=%s", out_file)) begin
      fd_out = $fopen(out_file, "w");
    end
    if ($value$plusargs("sdf=%s", sdf_file)) $sdf_annotate(sdf_file, dut);
    next_line(fd_txd, next_txd_cyc, next_txd_lvl);
    want_rxd = -1;
    last_rxd = -1;
    compared = 0;
    txd_changes = 0;
    rxd_changes = 0;
    #(settle);
    for (n = 0; n < cycles; n = n + 1) begin
      // Cycle n: the clock falls, the inputs of this cycle, the rising edge at half the period.
      clk = 1'b0;
      btn = (n >= 2);
      while (next_txd_cyc >= 0 && next_txd_cyc <= n) begin
        txd = next_txd_lvl[0];
        txd_changes = txd_changes + 1;
        next_line(fd_txd, next_txd_cyc, next_txd_lvl);
      end
      #(period / 2);
      clk = 1'b1;
      #(period - period / 2 - 1);
      // ftdi_rxd after rising edge n, 1 ps before the next one.
      if (rxd !== 1'b0 && rxd !== 1'b1) begin
        $display("FAIL: ftdi_rxd is %b after cycle %0d", rxd, n);
        $finish;
      end
      if (rxd != last_rxd) begin
        rxd_changes = rxd_changes + 1;
        if (fd_out != 0) $fdisplay(fd_out, "%0d %0d", n, rxd);
        last_rxd = rxd;
      end
      if (compare) begin
        while (next_rxd_cyc >= 0 && next_rxd_cyc <= n) begin
          want_rxd = next_rxd_lvl;
          next_line(fd_rxd, next_rxd_cyc, next_rxd_lvl);
        end
        if (want_rxd >= 0 && rxd != want_rxd) begin
          $display("FAIL: ftdi_rxd %b after cycle %0d, the record has %0d (period %0d ps; %0d ftdi_txd and %0d ftdi_rxd changes before)",
                   rxd, n, want_rxd, period, txd_changes, rxd_changes - 1);
          $finish;
        end
        if (want_rxd >= 0) compared = compared + 1;
      end
      #1;
    end
    if (fd_out != 0) $fclose(fd_out);
    if (compare)
      $display("PASS: %0d cycles at %0d ps, ftdi_rxd equal to the record in each (%0d ftdi_txd and %0d ftdi_rxd changes)",
               compared, period, txd_changes, rxd_changes);
    else
      $display("PASS: %0d cycles at %0d ps run (%0d ftdi_txd and %0d ftdi_rxd changes)", cycles, period,
               txd_changes, rxd_changes);
    $finish;
  end
endmodule
