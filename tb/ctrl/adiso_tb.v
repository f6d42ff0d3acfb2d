// SPDX-License-Identifier: Apache-2.0
// adiso_tb: self-checking Icarus bench for pree_adiso_rec over vectors from adiso_vecgen.
//
// Each cycle: apply stim[c] (flags {rst_n, start, stall, 0}, N), compare busy_o, addr_valid_o
// and every group's addr_o (invalid groups must be 0) with exp[c], then clock. Mismatches are
// printed (first 10) and end the run with $fatal. Plusargs: +stim=FILE +exp=FILE +ncyc=N.
// Parameters NumPreu and PipeDepth must match the vecgen run (iverilog -P).
`default_nettype none

module adiso_tb;
  parameter NumPreu   = 4;
  parameter PipeDepth = 12;
  localparam MAXCYC = 20000;
  localparam STIM_W = 4 + 32;
  localparam EXP_W  = 4 + 16 + NumPreu * 32;

`define VEC_TB "adiso_tb"
`include "vec_tb.vh"
  integer          g;

  reg                    clk, rst_n, start, stall;
  reg  [31:0]            n_hit;
  wire [NumPreu-1:0]     addr_valid;
  wire [NumPreu*32-1:0]  addr;
  wire                   busy;

  pree_adiso_rec #(.NumPreu(NumPreu), .PipeDepth(PipeDepth), .AddrW(32)) dut (
    .clk_i(clk), .rst_ni(rst_n), .start_i(start), .n_hit_i(n_hit), .stall_i(stall),
    .addr_valid_o(addr_valid), .addr_o(addr), .busy_o(busy)
  );

  reg [EXP_W-1:0] e;
  reg [15:0]      got_valid;

  task mismatch;
    input [8*16-1:0] what;
    input integer    group;
    input [31:0]     got;
    input [31:0]     want;
    begin
      if (errors < 10)
        $display("MISMATCH cycle=%0d group=%0d %0s: rtl=%h expected=%h (N=%0d)", c, group, what, got, want, n_hit);
      errors = errors + 1;
    end
  endtask

  initial begin
    vec_load;
    clk = 1'b0;
    for (c = 0; c < ncyc; c = c + 1) begin
      {rst_n, start, stall} = stim[c][STIM_W-1 -: 3];
      n_hit = stim[c][31:0];
      #1;
      e = expv[c];
      if (busy !== e[EXP_W-1]) mismatch("busy_o", -1, {31'd0, busy}, {31'd0, e[EXP_W-1]});
      got_valid = 16'd0;
      got_valid[NumPreu-1:0] = addr_valid;
      if (got_valid !== e[EXP_W-5 -: 16]) mismatch("addr_valid_o", -1, {16'd0, got_valid}, {16'd0, e[EXP_W-5 -: 16]});
      for (g = 0; g < NumPreu; g = g + 1)
        if (addr[g*32 +: 32] !== e[g*32 +: 32]) mismatch("addr_o", g, addr[g*32 +: 32], e[g*32 +: 32]);
      vec_clock;
    end
    vec_end;
    $display("adiso_tb: PASS preu=%0d pipe=%0d cycles=%0d", NumPreu, PipeDepth, ncyc);
    $finish;
  end
endmodule

`default_nettype wire
