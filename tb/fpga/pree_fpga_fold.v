// SPDX-License-Identifier: Apache-2.0
// pree_fpga_fold: W register bits folded into one output pin through a pipelined XOR tree, one
// LUT4 level per register stage, for the place-and-route wrappers (tb/fpga/pree_fpga_*_wrap.v):
// no bit can be removed by synthesis, and every path of the tree is one LUT deep.
`default_nettype none

module pree_fpga_fold #(
  parameter W = 8     // bits in (at most 4^6 = 4096)
) (
  input  wire         clk_i,
  input  wire [W-1:0] d_i,
  output wire         fold_o
);

  localparam LEVELS = 6;
  genvar gv, gi;
  generate
    for (gv = 0; gv < LEVELS; gv = gv + 1) begin : g_fold
      localparam IN_N  = (W + (1 << (2 * gv)) - 1) >> (2 * gv);   // bits into this level
      localparam OUT_N = (IN_N + 3) / 4;
      wire [4*OUT_N-1:0] src;
      reg  [OUT_N-1:0]   q;
      if (gv == 0) begin : g_src0
        assign src = {{(4 * OUT_N - W){1'b0}}, d_i};
      end else begin : g_srcn
        assign src = {{(4 * OUT_N - IN_N){1'b0}}, g_fold[gv-1].q};
      end
      for (gi = 0; gi < OUT_N; gi = gi + 1) begin : g_xor
        always @(posedge clk_i) q[gi] <= ^src[4*gi +: 4];
      end
    end
  endgenerate
  assign fold_o = g_fold[LEVELS-1].q[0];

endmodule

`default_nettype wire
