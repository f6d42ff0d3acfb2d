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

  localparam AW = RowW + BankW;

  genvar gb;
  generate
    for (gb = 0; gb < (1 << BankW); gb = gb + 1) begin : g_bank
      localparam [BankW-1:0] BANK = gb;
      reg             re, we;
      reg [RowW-1:0]  raddr, waddr;
      reg [Width-1:0] wdata;
      integer j;
      always @* begin
        re = 1'b0; raddr = {RowW{1'b0}};
        we = 1'b0; waddr = {RowW{1'b0}}; wdata = {Width{1'b0}};
        for (j = 0; j < Lanes; j = j + 1) begin
          if (rd_i[j] && rd_addr_i[j*AW +: BankW] == BANK) begin
            re    = 1'b1;
            raddr = raddr | rd_addr_i[j*AW + BankW +: RowW];
          end
          if (wr_i[j] && wr_addr_i[j*AW +: BankW] == BANK) begin
            we    = 1'b1;
            waddr = waddr | wr_addr_i[j*AW + BankW +: RowW];
            wdata = wdata | wr_data_i[j*Width +: Width];
          end
        end
      end
      pree_ram_sdp #(.Width(Width), .AddrW(RowW)) u_ram (
        .clk_i(clk_i), .we_i(we), .waddr_i(waddr), .wdata_i(wdata),
        .re_i(re), .raddr_i(raddr), .rdata_o(rdata_o[gb*Width +: Width]));

`ifdef PREE_ASSERT
      integer nr, nw, k;
      always @(posedge clk_i) begin
        nr = 0; nw = 0;
        for (k = 0; k < Lanes; k = k + 1) begin
          if (rd_i[k] && rd_addr_i[k*AW +: BankW] == BANK) nr = nr + 1;
          if (wr_i[k] && wr_addr_i[k*AW +: BankW] == BANK) nw = nw + 1;
        end
        if (nr > 1 || nw > 1)
          $fatal(1, "pree_ram_banks %m: %0d reads and %0d writes in one cycle", nr, nw);
      end
`endif
    end
  endgenerate

endmodule
