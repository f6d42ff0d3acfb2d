// SPDX-License-Identifier: Apache-2.0
// pree_top_offer: the offer stage A reads (docs/pree_top.md, "Pipeline, memories and hazards"):
// the controller's lanes (update: AFTSO-HpUOC's index-entry addresses and photons; radiance:
// ADISO-REC's hit-point addresses) with each lane's bank (update: the index table's, the address's
// low IdxBankW bits; radiance: the hit-point memory's, hp_bank of the address).
// Reg = 1 (PipeFast 1): a two-offer buffer. Slot 0 is the offer A reads (from flip-flops); slot 1
// holds one more. The controller's offer is taken whenever slot 1 is free (full_o low, a
// register), and stored when it has a valid lane; A leaves slot 0 once it has read every lane of
// it (pop_i, pree_top_read's all_o), and slot 1 or the offer taken in that cycle moves up. So
// neither controller waits on A's read plan in the same cycle: their stall is a flip-flop.
// Reg = 0: the controller's lanes as they come, taken once A has read all of them
// (full_o = ~pop_i).
`default_nettype none

module pree_top_offer #(
  parameter Reg     = 1,    // 1 the register, 0 none
  parameter NumPreu = 4,    // lanes
  parameter IdxAW   = 12,   // index-table address bits
  parameter IdxBankW = 2,   // log2 of the index-table banks (pree_top: log2 NumPreu, at least 1)
  parameter HpAW    = 18,   // hit-point address bits
  parameter HpBankW = 4,    // log2 of the hit-point banks
  parameter BankW   = 4,    // a lane's bank number: the wider of IdxBankW and HpBankW
  parameter DataW   = 192   // a lane's photon (update)
) (
  input  wire                       clk_i,
  input  wire                       rst_ni,
  input  wire                       mode_i,   // 0 update, 1 radiance
  input  wire                       pop_i,    // A has read every lane of the offer it holds
  output wire                       full_o,   // the controllers' offer is not taken (their stall)
  // AFTSO-HpUOC's offer (update) and ADISO-REC's (radiance).
  input  wire [NumPreu-1:0]         af_valid_i,
  input  wire [NumPreu*IdxAW-1:0]   af_ref_i,
  input  wire [NumPreu-1:0]         af_last_i,
  input  wire [NumPreu*DataW-1:0]   af_data_i,
  input  wire [NumPreu-1:0]         ad_valid_i,
  input  wire [NumPreu*HpAW-1:0]    ad_addr_i,
  // The offer stage A reads.
  output wire [NumPreu-1:0]         valid_o,
  output reg  [NumPreu*IdxAW-1:0]   idx_o,    // update: index-entry addresses
  output reg  [NumPreu*HpAW-1:0]    hp_o,     // radiance: hit-point addresses
  output wire [NumPreu*BankW-1:0]   bank_o,
  output wire [NumPreu-1:0]         last_o,   // update: the photon's last index entry
  output wire [NumPreu*DataW-1:0]   data_o
);

`include "pree_hp_bank.vh"

  localparam ADDR_W = IdxAW > HpAW ? IdxAW : HpAW;   // a lane's address, either kind

  // The controller's lanes: valid, address and bank.
  wire [NumPreu-1:0]        valid = mode_i ? ad_valid_i : af_valid_i;
  reg  [NumPreu*ADDR_W-1:0] addr;
  reg  [NumPreu*BankW-1:0]  bank;
  always @* begin : lanes
    integer l;
    for (l = 0; l < NumPreu; l = l + 1) begin
      addr[l*ADDR_W +: ADDR_W] = {ADDR_W{1'b0}};
      bank[l*BankW +: BankW]   = {BankW{1'b0}};
      if (mode_i) begin
        addr[l*ADDR_W +: HpAW]   = ad_addr_i[l*HpAW +: HpAW];
        bank[l*BankW +: HpBankW] = hp_bank(ad_addr_i[l*HpAW +: 2*HpBankW]);
      end else begin
        addr[l*ADDR_W +: IdxAW]  = af_ref_i[l*IdxAW +: IdxAW];
        bank[l*BankW +: IdxBankW] = af_ref_i[l*IdxAW +: IdxBankW];
      end
    end
  end

  wire [NumPreu*ADDR_W-1:0] addr_a;   // the addresses A reads, split by kind below
  generate
    if (Reg != 0) begin : g_reg
      // Slot k: occupied (occ_q[k]), lanes, addresses, banks, last flags, photons (slot 0 *0_q,
      // slot 1 *1_q). Slot 1 is occupied only with slot 0.
      reg [1:0]                occ_q;
      reg [NumPreu-1:0]        valid0_q, valid1_q, last0_q, last1_q;
      reg [NumPreu*ADDR_W-1:0] addr0_q, addr1_q;
      reg [NumPreu*BankW-1:0]  bank0_q, bank1_q;
      reg [NumPreu*DataW-1:0]  data0_q, data1_q;
      wire push   = ~occ_q[1] & (|valid);         // an offer with a lane, taken
      wire pop    = pop_i & occ_q[0];
      wire load0  = ~occ_q[0] | pop;              // slot 0 takes slot 1's offer, or the new one
      wire load1  = occ_q[0] & ~pop & push;       // the new offer waits behind slot 0's
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          occ_q    <= 2'b00;
          valid0_q <= {NumPreu{1'b0}};
        end else begin
          if (load0) begin
            occ_q[0] <= occ_q[1] | push;
            valid0_q <= occ_q[1] ? valid1_q : valid;
          end
          occ_q[1] <= load1 | (occ_q[1] & ~pop);
        end
      end
      always @(posedge clk_i) begin
        if (load0) begin
          addr0_q <= occ_q[1] ? addr1_q : addr;
          bank0_q <= occ_q[1] ? bank1_q : bank;
          last0_q <= occ_q[1] ? last1_q : af_last_i;
          data0_q <= occ_q[1] ? data1_q : af_data_i;
        end
        if (load1) begin
          valid1_q <= valid;
          addr1_q  <= addr;
          bank1_q  <= bank;
          last1_q  <= af_last_i;
          data1_q  <= af_data_i;
        end
      end
      assign full_o  = occ_q[1];
      assign valid_o = valid0_q;
      assign addr_a  = addr0_q;
      assign bank_o  = bank0_q;
      assign last_o  = last0_q;
      assign data_o  = data0_q;
    end else begin : g_pass
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused = &{1'b0, clk_i, rst_ni};
      /* verilator lint_on UNUSEDSIGNAL */
      assign full_o  = ~pop_i;
      assign valid_o = valid;
      assign addr_a  = addr;
      assign bank_o  = bank;
      assign last_o  = af_last_i;
      assign data_o  = af_data_i;
    end
  endgenerate

  always @* begin : split
    integer l;
    for (l = 0; l < NumPreu; l = l + 1) begin
      idx_o[l*IdxAW +: IdxAW] = addr_a[l*ADDR_W +: IdxAW];
      hp_o[l*HpAW +: HpAW]    = addr_a[l*ADDR_W +: HpAW];
    end
  end

endmodule

`default_nettype wire
