// SPDX-License-Identifier: Apache-2.0
// pree_top_hpmem: pree_top's hit-point memory (docs/pree_top.md, "Pipeline, memories and
// hazards"): 2^HpBankW banks (pree_ram_banks) of a constant part {pixel, f, pos} and a state part,
// shared by the PREU lanes and the host. Addresses are hit points; the bank is hp_bank() of the
// address (rtl/pree_hp_bank.vh), the row the address without its low HpBankW bits.
// Lanes: reads (update: B's issue; radiance: A's read), state writes (update write-back), and the
// host (both parts; the constant part has no other writer). Each lane's read data is that of the
// bank the lane read last (hsel_q, registered when the lane reads), so a lane's selection is a
// 2^HpBankW:1 multiplexer on a registered bank number. Lane 0 also carries the host's reads
// (hp_re_i, only while the engine is idle): hp_rdata_o is lane 0's selection.
`default_nettype none

module pree_top_hpmem #(
  parameter NumPreu = 4,    // PREU lanes
  parameter HpAW    = 18,   // hit-point address bits
  parameter HpBankW = 4,    // log2 of the banks
  parameter ConstW  = 209,  // {pixel, f, pos}
  parameter StateW  = 160   // paper {n, r2, tau}, stable {k, w, T}
) (
  input  wire                      clk_i,
  input  wire [NumPreu-1:0]        rd_i,       // lane reads
  input  wire [NumPreu*HpAW-1:0]   rd_addr_i,
  input  wire [NumPreu-1:0]        wr_i,       // lane state writes
  input  wire [NumPreu*HpAW-1:0]   wr_addr_i,
  input  wire [NumPreu*StateW-1:0] wr_state_i,
  output reg  [NumPreu*ConstW-1:0] rd_const_o, // each lane's data: the bank it read last
  output reg  [NumPreu*StateW-1:0] rd_state_o,
  // Host port: {const, state}; read data one cycle after hp_re_i.
  input  wire                      hp_we_i,
  input  wire                      hp_re_i,
  input  wire [HpAW-1:0]           hp_addr_i,
  input  wire [ConstW+StateW-1:0]  hp_wdata_i,
  output wire [ConstW+StateW-1:0]  hp_rdata_o
);

`include "pree_hp_bank.vh"

  localparam BANKS = 1 << HpBankW;
  localparam ROW_W = HpAW - HpBankW;
  localparam LANES = NumPreu + 1;   // the PREU lanes, then the host

  generate
    if (HpAW < 2 * HpBankW) begin : g_bad_hpbankw   // (elaboration fails: no such module)
      pree_top_hpaw_must_be_at_least_twice_hpbankw u_fail ();
    end
  endgenerate

  // An address as the banks take it: {row, bank}.
  function [HpAW-1:0] banked;
    input [HpAW-1:0] a;
    begin
      banked = {a[HpAW-1:HpBankW], hp_bank(a[2*HpBankW-1:0])};
    end
  endfunction

  reg  [LANES*HpAW-1:0]    rd_addr, wr_addr;
  reg  [NumPreu*HpBankW-1:0] hsel_q;
  wire [BANKS*ConstW-1:0]  c_rdata;
  wire [BANKS*StateW-1:0]  s_rdata;

  always @* begin : lanes
    integer l;
    for (l = 0; l < NumPreu; l = l + 1) begin
      rd_addr[l*HpAW +: HpAW] = banked(rd_addr_i[l*HpAW +: HpAW]);
      wr_addr[l*HpAW +: HpAW] = banked(wr_addr_i[l*HpAW +: HpAW]);
    end
    rd_addr[NumPreu*HpAW +: HpAW] = banked(hp_addr_i);
    wr_addr[NumPreu*HpAW +: HpAW] = banked(hp_addr_i);
  end

  pree_ram_banks #(.BankW(HpBankW), .RowW(ROW_W), .Width(ConstW), .Lanes(LANES)) u_const (
    .clk_i(clk_i), .rd_i({hp_re_i, rd_i}), .rd_addr_i(rd_addr),
    .wr_i({hp_we_i, {NumPreu{1'b0}}}), .wr_addr_i(wr_addr),
    .wr_data_i({hp_wdata_i[StateW +: ConstW], {NumPreu*ConstW{1'b0}}}), .rdata_o(c_rdata));
  pree_ram_banks #(.BankW(HpBankW), .RowW(ROW_W), .Width(StateW), .Lanes(LANES)) u_state (
    .clk_i(clk_i), .rd_i({hp_re_i, rd_i}), .rd_addr_i(rd_addr),
    .wr_i({hp_we_i, wr_i}), .wr_addr_i(wr_addr),
    .wr_data_i({hp_wdata_i[0 +: StateW], wr_state_i}), .rdata_o(s_rdata));

  always @(posedge clk_i) begin : sel
    integer l;
    for (l = 0; l < NumPreu; l = l + 1)
      if (rd_i[l])                hsel_q[l*HpBankW +: HpBankW] <= rd_addr[l*HpAW +: HpBankW];
      else if (l == 0 && hp_re_i) hsel_q[l*HpBankW +: HpBankW] <= rd_addr[NumPreu*HpAW +: HpBankW];
  end

  // Bank outputs as arrays (one word per bank), read with narrow indices. RAM ports drive plain
  // wires that are then assigned to the array words (Yosys re-derives, and renames, a module
  // whose cell ports drive array words directly).
  wire [ConstW-1:0] c_rd [0:BANKS-1];
  wire [StateW-1:0] s_rd [0:BANKS-1];
  genvar gb;
  generate
    for (gb = 0; gb < BANKS; gb = gb + 1) begin : g_bank
      assign c_rd[gb] = c_rdata[gb*ConstW +: ConstW];
      assign s_rd[gb] = s_rdata[gb*StateW +: StateW];
    end
  endgenerate

  always @* begin : out
    integer l;
    for (l = 0; l < NumPreu; l = l + 1) begin
      rd_const_o[l*ConstW +: ConstW] = c_rd[hsel_q[l*HpBankW +: HpBankW]];
      rd_state_o[l*StateW +: StateW] = s_rd[hsel_q[l*HpBankW +: HpBankW]];
    end
  end
  assign hp_rdata_o = {rd_const_o[0 +: ConstW], rd_state_o[0 +: StateW]};

endmodule

`default_nettype wire
