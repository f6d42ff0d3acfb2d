// SPDX-License-Identifier: Apache-2.0
// pree_top_pxmem: pree_top's pixel memory (docs/pree_top.md, "Pipeline, memories and hazards"):
// 2^PxBankW banks (pree_ram_banks) of a pixel's sum {b, g, r}; the bank is the pixel's low bits.
// Lanes: the PREU lanes (radiance: the pixel-sum read, lreq, and the write-back of the new sum),
// then the host. Each lane's read data is that of the bank it read last (a registered bank
// number per lane, as in pree_top_hpmem); the host's is hp_rdata_o's counterpart px_rdata_o.
`default_nettype none

module pree_top_pxmem #(
  parameter NumPreu = 4,    // PREU lanes
  parameter PxAW    = 17,   // pixel address bits
  parameter PxBankW = 4     // log2 of the banks (1 .. PxAW-1)
) (
  input  wire                    clk_i,
  input  wire [NumPreu-1:0]      rd_i,       // lane reads (lreq)
  input  wire [NumPreu*PxAW-1:0] rd_addr_i,
  input  wire [NumPreu-1:0]      wr_i,       // lane writes (the new sums)
  input  wire [NumPreu*PxAW-1:0] wr_addr_i,
  input  wire [NumPreu*96-1:0]   wr_data_i,
  output reg  [NumPreu*96-1:0]   rd_data_o,  // each lane's data: the bank it read last
  // Host port: read data one cycle after px_re_i.
  input  wire                    px_we_i,
  input  wire                    px_re_i,
  input  wire [PxAW-1:0]         px_addr_i,
  input  wire [95:0]             px_wdata_i,
  output wire [95:0]             px_rdata_o
);

  localparam BANKS = 1 << PxBankW;
  localparam ROW_W = PxAW - PxBankW;

  wire [BANKS*96-1:0] rdata;
  pree_ram_banks #(.BankW(PxBankW), .RowW(ROW_W), .Width(96), .Lanes(NumPreu + 1)) u_px (
    .clk_i(clk_i), .rd_i({px_re_i, rd_i}), .rd_addr_i({px_addr_i, rd_addr_i}),
    .wr_i({px_we_i, wr_i}), .wr_addr_i({px_addr_i, wr_addr_i}), .wr_data_i({px_wdata_i, wr_data_i}),
    .rdata_o(rdata));

  // Bank outputs as an array (one word per bank), read with narrow registered indices.
  wire [95:0] rd [0:BANKS-1];
  genvar gb;
  generate
    for (gb = 0; gb < BANKS; gb = gb + 1) begin : g_bank
      assign rd[gb] = rdata[gb*96 +: 96];
    end
  endgenerate

  reg [NumPreu*PxBankW-1:0] sel_q;   // the bank each lane read last
  reg [PxBankW-1:0]         hsel_q;  // ... and the host
  always @(posedge clk_i) begin : sel
    integer l;
    for (l = 0; l < NumPreu; l = l + 1)
      if (rd_i[l]) sel_q[l*PxBankW +: PxBankW] <= rd_addr_i[l*PxAW +: PxBankW];
    if (px_re_i) hsel_q <= px_addr_i[PxBankW-1:0];
  end

  always @* begin : out
    integer l;
    for (l = 0; l < NumPreu; l = l + 1)
      rd_data_o[l*96 +: 96] = rd[sel_q[l*PxBankW +: PxBankW]];
  end
  assign px_rdata_o = rd[hsel_q];

endmodule

`default_nettype wire
