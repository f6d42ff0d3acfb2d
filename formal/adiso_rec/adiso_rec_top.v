// SPDX-License-Identifier: Apache-2.0
// adiso_rec_top: the adiso_rec job's top: the harness at two parameter sets with free inputs
// each: NumPreu 2 with PipeDepth 2 (SHIFT 2, lv up to 7 at 5-bit N) and NumPreu 4 with
// PipeDepth 3 (SHIFT 4, a multiple of three as the paper's 4 x 12; lv up to 3 at 6-bit N).
// The taps (taps.ys) reach into both instances' controllers.
`default_nettype none

module adiso_rec_top #(
  parameter Strengthen = 1   // 0 for the bounded tasks (cover, bmc): no inductive invariants
) (
  input wire       clk_i,
  input wire       start_a_i,
  input wire [4:0] n_a_i,
  input wire       stall_a_i,
  input wire       start_b_i,
  input wire [5:0] n_b_i,
  input wire       stall_b_i
);

  adiso_rec_fv #(.NumPreu(2), .PipeDepth(2), .AddrW(5), .Strengthen(Strengthen)) u_np2 (
    .clk_i(clk_i), .start_i(start_a_i), .n_hit_i(n_a_i), .stall_i(stall_a_i)
  );

  adiso_rec_fv #(.NumPreu(4), .PipeDepth(3), .AddrW(6), .Strengthen(Strengthen)) u_np4 (
    .clk_i(clk_i), .start_i(start_b_i), .n_hit_i(n_b_i), .stall_i(stall_b_i)
  );

endmodule

`default_nettype wire
