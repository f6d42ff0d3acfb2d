// SPDX-License-Identifier: Apache-2.0
// aftso_tb: self-checking Icarus bench for pree_aftso_hpuoc over vectors from aftso_vecgen.
//
// Each cycle: apply stim[c] (flags {rst_n, in_valid, stall, 0}, N^P, p_addr, id, data), let the
// combinational outputs settle, compare in_ready_o/empty_o/busy_o and every lane (valid, last,
// ref_addr, id, data; invalid lanes must be zero) with exp[c], then clock. Any mismatch is
// printed (first 10) and ends the run with $fatal. Plusargs: +stim=FILE +exp=FILE +ncyc=N.
// Parameters NumPreu and EarlyReady must match the vecgen run (iverilog -P).
`default_nettype none

module aftso_tb;
  parameter NumPreu    = 4;
  parameter EarlyReady = 1;
  localparam MAXCYC = 20000;
  localparam STIM_W = 4 + 3 * 32 + 192;
  localparam LANE_W = 32 + 32 + 192;
  localparam EXP_W  = 4 + 16 + 16 + NumPreu * LANE_W;

`define VEC_TB "aftso_tb"
`include "vec_tb.vh"
  integer          l;

  reg                      clk, rst_n, in_valid, stall;
  reg  [191:0]             in_data;
  reg  [31:0]              in_id, in_p_addr, in_n;
  wire                     in_ready, busy, empty;
  wire [NumPreu-1:0]       lane_valid, lane_last;
  wire [NumPreu*32-1:0]    lane_ref_addr, lane_id;
  wire [NumPreu*192-1:0]   lane_data;

  pree_aftso_hpuoc #(
    .NumPreu(NumPreu), .BufDepth(4), .DataW(192), .IdW(32), .AddrW(32), .CntW(32),
    .EarlyReady(EarlyReady)
  ) dut (
    .clk_i(clk), .rst_ni(rst_n),
    .in_valid_i(in_valid), .in_ready_o(in_ready), .in_data_i(in_data), .in_id_i(in_id),
    .in_p_addr_i(in_p_addr), .in_n_i(in_n),
    .stall_i(stall), .lane_valid_o(lane_valid), .lane_ref_addr_o(lane_ref_addr),
    .lane_data_o(lane_data), .lane_id_o(lane_id), .lane_last_o(lane_last),
    .busy_o(busy), .empty_o(empty)
  );

  reg [EXP_W-1:0]  e;
  reg [LANE_W-1:0] el;
  reg [15:0]       got_valid, got_last;

  task mismatch;
    input [8*24-1:0] what;
    input integer    lane;
    input [191:0]    got;
    input [191:0]    want;
    begin
      if (errors < 10)
        $display("MISMATCH cycle=%0d lane=%0d %0s: rtl=%h expected=%h", c, lane, what, got, want);
      errors = errors + 1;
    end
  endtask

  initial begin
    vec_load;
    clk = 1'b0;
    for (c = 0; c < ncyc; c = c + 1) begin
      {rst_n, in_valid, stall} = stim[c][STIM_W-1 -: 3];
      in_n      = stim[c][287 -: 32];
      in_p_addr = stim[c][255 -: 32];
      in_id     = stim[c][223 -: 32];
      in_data   = stim[c][191:0];
      #1;
      e = expv[c];
      if (in_ready !== e[EXP_W-1]) mismatch("in_ready_o", -1, in_ready, e[EXP_W-1]);
      if (empty !== e[EXP_W-2])    mismatch("empty_o", -1, empty, e[EXP_W-2]);
      if (busy !== e[EXP_W-3])     mismatch("busy_o", -1, busy, e[EXP_W-3]);
      got_valid = 16'd0;
      got_last  = 16'd0;
      got_valid[NumPreu-1:0] = lane_valid;
      got_last[NumPreu-1:0]  = lane_last;
      if (got_valid !== e[EXP_W-5 -: 16]) mismatch("lane_valid_o", -1, got_valid, e[EXP_W-5 -: 16]);
      if (got_last !== e[EXP_W-21 -: 16]) mismatch("lane_last_o", -1, got_last, e[EXP_W-21 -: 16]);
      for (l = 0; l < NumPreu; l = l + 1) begin
        el = e[l*LANE_W +: LANE_W];
        if (lane_ref_addr[l*32 +: 32] !== el[255:224]) mismatch("ref_addr", l, lane_ref_addr[l*32 +: 32], el[255:224]);
        if (lane_id[l*32 +: 32] !== el[223:192])       mismatch("id", l, lane_id[l*32 +: 32], el[223:192]);
        if (lane_data[l*192 +: 192] !== el[191:0])     mismatch("data", l, lane_data[l*192 +: 192], el[191:0]);
      end
      vec_clock;
    end
    vec_end;
    $display("aftso_tb: PASS preu=%0d early_ready=%0d cycles=%0d", NumPreu, EarlyReady, ncyc);
    $finish;
  end
endmodule

`default_nettype wire
