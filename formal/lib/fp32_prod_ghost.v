// SPDX-License-Identifier: Apache-2.0
// fp32_prod_ghost: formal ghost state of a product stage with two registers (a DSP block's input
// and output registers, pree_fp32_dsp_mul): the operand bits d_i are taken into q1_o where the
// stage's input registers load (en1_i) and move on to q2_o where its output registers load
// (en2_i). So q2_o holds the operands whose product the stage's output registers hold. Its initial
// value is free (a harness ties it to the unit's registers in the first cycle where it needs to).
`default_nettype none

module fp32_prod_ghost #(
  parameter Width = 48
) (
  input  wire             clk_i,
  input  wire             en1_i,
  input  wire [Width-1:0] d_i,
  input  wire             en2_i,
  output reg  [Width-1:0] q1_o,
  output reg  [Width-1:0] q2_o
);

  always @(posedge clk_i) begin
    if (en1_i) q1_o <= d_i;
    if (en2_i) q2_o <= q1_o;
  end

endmodule

`default_nettype wire
