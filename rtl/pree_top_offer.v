// pree_top_offer: the offer stage A reads (docs/pree_top.md, "Pipeline, memories and hazards"):
// the controller's lanes (update: AFTSO-HpUOC's index-entry addresses and photons; radiance:
// ADISO-REC's hit-point addresses) with each lane's bank (update: the index table's, the address
// mod NumPreu; radiance: the hit-point memory's, hp_bank of the address).
// Reg = 1 (PipeFast 1): the offer is taken into a register when stage A has read every lane of
// the one it holds (take_i, pree_top_read's all_o), and A reads from the register a cycle
// later. So a controller's offer is taken in the same cycle as without the register (its
// stall_i is ~take_i either way), and A's read plan starts from flip-flops instead of the
// controllers' outputs. Reg = 0: the controller's lanes as they come.
`default_nettype none

module pree_top_offer #(
  parameter Reg     = 1,    // 1 the register, 0 none
  parameter NumPreu = 4,    // lanes
  parameter IdxAW   = 12,   // index-table address bits
  parameter HpAW    = 18,   // hit-point address bits
  parameter HpBankW = 4,    // log2 of the hit-point banks
  parameter BankW   = 4,    // a lane's bank number: the wider of log2 NumPreu and HpBankW
  parameter DataW   = 192   // a lane's photon (update)
) (
  input  wire                       clk_i,
  input  wire                       rst_ni,
  input  wire                       mode_i,   // 0 update, 1 radiance
  input  wire                       take_i,   // A has read every lane of the offer it holds
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

  localparam LANE_W = $clog2(NumPreu);
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
        bank[l*BankW +: LANE_W]  = af_ref_i[l*IdxAW +: LANE_W];
      end
    end
  end

  wire [NumPreu*ADDR_W-1:0] addr_a;   // the addresses A reads, split by kind below
  generate
    if (Reg != 0) begin : g_reg
      reg [NumPreu-1:0]        valid_q;
      reg [NumPreu*ADDR_W-1:0] addr_q;
      reg [NumPreu*BankW-1:0]  bank_q;
      reg [NumPreu-1:0]        last_q;
      reg [NumPreu*DataW-1:0]  data_q;
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni)     valid_q <= {NumPreu{1'b0}};
        else if (take_i) valid_q <= valid;
      end
      always @(posedge clk_i) begin
        if (take_i) begin
          addr_q <= addr;
          bank_q <= bank;
          last_q <= af_last_i;
          data_q <= af_data_i;
        end
      end
      assign valid_o = valid_q;
      assign addr_a  = addr_q;
      assign bank_o  = bank_q;
      assign last_o  = last_q;
      assign data_o  = data_q;
    end else begin : g_pass
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused = &{1'b0, clk_i, rst_ni, take_i};
      /* verilator lint_on UNUSEDSIGNAL */
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
