// SPDX-License-Identifier: Apache-2.0
// pree_fp32_lzc: leading-zero counter, combinational.
//
// cnt_o is the number of zero bits above the most significant one of x_i; Width when x_i is
// zero. A helper of the binary32 units (operand and sum normalisation). Yosys and ABC
// restructure the priority chain below into a shallow tree when mapping to LUTs.
`default_nettype none

module pree_fp32_lzc #(
  parameter Width    = 24,
  parameter CntWidth = 5    // must hold Width
) (
  input  wire [Width-1:0]    x_i,
  output reg  [CntWidth-1:0] cnt_o
);

  localparam [CntWidth-1:0] WIDTH_C = Width;

  integer i;

  // Scan upward: the last one found is the most significant, so it sets the count.
  always @* begin
    cnt_o = WIDTH_C;
    for (i = 0; i < Width; i = i + 1) begin
      if (x_i[i]) cnt_o = WIDTH_C - 1'b1 - i[CntWidth-1:0];
    end
  end

endmodule
