// SPDX-License-Identifier: Apache-2.0
// pree_ram_banks: 2^BankW banks of pree_ram_sdp (Width bits, 2^RowW words each) shared by Lanes
// request lanes: pree_top's index table, hit-point memory (constant and state parts) and pixel
// memory, each with the PREU lanes and the host as its lanes.
//
// Each lane may ask for one read and one write a cycle, each at an address {row, bank} (the bank
// in the low BankW bits: the caller puts there the bank its address maps to). A bank serves the
// lanes that address it: at most one reader and one writer a cycle, which the callers' issue
// rules guarantee (with PREE_ASSERT defined, a violation stops the simulation). So a bank's
// enable is the OR of its lanes' and its address and data are the OR of theirs (zero when no
// lane asks), an AND-OR per bit and no priority chain.
// rdata_o: every bank's read port (bank b in [b*Width +: Width]), which pree_ram_sdp loads one
// cycle after the read and holds while no lane reads the bank.
`default_nettype none

module pree_ram_banks #(
  parameter BankW = 2,
  parameter RowW  = 8,
  parameter Width = 32,
  parameter Lanes = 4
) (
  input  wire                           clk_i,
  input  wire [Lanes-1:0]              rd_i,
  input  wire [Lanes*(RowW+BankW)-1:0] rd_addr_i,
  input  wire [Lanes-1:0]              wr_i,
  input  wire [Lanes*(RowW+BankW)-1:0] wr_addr_i,
  input  wire [Lanes*Width-1:0]        wr_data_i,
  output wire [(1 << BankW)*Width-1:0] rdata_o
);

  localparam AW    = RowW + BankW;
  localparam Banks = 1 << BankW;

  // Every bank's enables, addresses and data, flat (bank b's at [b], [b*RowW +: RowW] and
  // [b*Width +: Width]), from one loop over the banks: the same AND-OR logic as a block per bank,
  // but a loop that Verilator keeps as one (a block per bank made the 16-PREU model's C++ 2.4x
  // larger and its build take minutes more).
  reg [Banks-1:0]       re, we;
  reg [Banks*RowW-1:0]  raddr, waddr;
  reg [Banks*Width-1:0] wdata;
  integer b, j;
  always @* begin
    for (b = 0; b < Banks; b = b + 1) begin
      re[b] = 1'b0; raddr[b*RowW +: RowW] = {RowW{1'b0}};
      we[b] = 1'b0; waddr[b*RowW +: RowW] = {RowW{1'b0}}; wdata[b*Width +: Width] = {Width{1'b0}};
      for (j = 0; j < Lanes; j = j + 1) begin
        if (rd_i[j] && rd_addr_i[j*AW +: BankW] == b[BankW-1:0]) begin
          re[b] = 1'b1;
          raddr[b*RowW +: RowW] = raddr[b*RowW +: RowW] | rd_addr_i[j*AW + BankW +: RowW];
        end
        if (wr_i[j] && wr_addr_i[j*AW +: BankW] == b[BankW-1:0]) begin
          we[b] = 1'b1;
          waddr[b*RowW +: RowW] = waddr[b*RowW +: RowW] | wr_addr_i[j*AW + BankW +: RowW];
          wdata[b*Width +: Width] = wdata[b*Width +: Width] | wr_data_i[j*Width +: Width];
        end
      end
    end
  end

  genvar gb;
  generate
    for (gb = 0; gb < Banks; gb = gb + 1) begin : g_bank
      pree_ram_sdp #(.Width(Width), .AddrW(RowW)) u_ram (
        .clk_i(clk_i), .we_i(we[gb]), .waddr_i(waddr[gb*RowW +: RowW]), .wdata_i(wdata[gb*Width +: Width]),
        .re_i(re[gb]), .raddr_i(raddr[gb*RowW +: RowW]), .rdata_o(rdata_o[gb*Width +: Width]));
    end
  endgenerate

`ifdef PREE_ASSERT
  integer nb, nr, nw, k;
  always @(posedge clk_i) begin
    for (nb = 0; nb < Banks; nb = nb + 1) begin
      nr = 0; nw = 0;
      for (k = 0; k < Lanes; k = k + 1) begin
        if (rd_i[k] && rd_addr_i[k*AW +: BankW] == nb[BankW-1:0]) nr = nr + 1;
        if (wr_i[k] && wr_addr_i[k*AW +: BankW] == nb[BankW-1:0]) nw = nw + 1;
      end
      if (nr > 1 || nw > 1)
        $fatal(1, "pree_ram_banks %m: bank %0d: %0d reads and %0d writes in one cycle", nb, nr, nw);
    end
  end
`endif

endmodule
