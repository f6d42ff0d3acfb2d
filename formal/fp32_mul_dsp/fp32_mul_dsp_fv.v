// SPDX-License-Identifier: Apache-2.0
// fp32_mul_dsp_fv: the fp32_mul_dsp job's top (docs/formal.md): the product stage of
// pree_fp32_mul's deep configuration (Stages 7: seams 2 and 3 registered, the 24 x 24 significand
// product as four partial products of 17-bit and 7-bit pieces, each in a pree_fp32_dsp_mul with
// its own input and output registers) computes the product of the significands that entered it.
// Proven, for every operand stream (the unit reset in the first cycle, free operands after):
//   - the four DSP blocks load their input registers where seam 1's valid bit is set and their
//     output registers where seam 2's is (their enables), so they always work on one operation;
//   - their input registers hold the 17-bit and 7-bit pieces of the significands last taken into
//     the stage (ghost sx1/sy1: fp32_prod_ghost), each piece at the right multiplier, and the
//     operands of their output registers' products (ghost, loaded with the output registers) are
//     the pieces of the significands of the operation leaving the stage (sx2/sy2): u_ll multiplies
//     sx2[16:0] by sy2[16:0], u_lh sx2[16:0] by sy2[23:17], u_hl sx2[23:17] by sy2[16:0], u_hh
//     sx2[23:17] by sy2[23:17];
//   - the stage's 48-bit output prod_d is hh * 2^34 + ll + (lh + hl) * 2^17 of the four output
//     registers, in 48 bits (the recombination).
// Not checked by the solver: that an output register holds the product of the operands it loaded
// (pree_fp32_dsp_mul's `p_q <= a_q * b_q`, the Verilog operator at full width), and the
// distributive law: with x = xh * 2^17 + xl and y = yh * 2^17 + yl, hh * 2^34 + ll + (lh + hl) *
// 2^17 = x * y, every term exact and the sum x * y < 2^48 losing no bit. Together: prod_d is
// sx2 * sy2, the product fp32_mul assumes of its cut. (A solver given the product itself,
// prod_d == sx2 * sy2, bit-blasts two different multiplier circuits and does not answer.)
`default_nettype none

module fp32_mul_dsp_fv (
  input wire        clk_i,
  input wire        valid_i,
  input wire [31:0] a_i,
  input wire [31:0] b_i
);

  reg f_init = 1'b1;
  always @(posedge clk_i) f_init <= 1'b0;

  wire        valid_o;
  wire [31:0] y_o;
  pree_fp32_mul #(.Stages(7)) u_dut (
    .clk_i(clk_i), .rst_ni(!f_init), .valid_i(valid_i), .a_i(a_i), .b_i(b_i),
    .valid_o(valid_o), .y_o(y_o));

  // Taps (taps.ys): the stage's valid bits and significands, its registers and its output.
  wire        f_t_v1, f_t_v2;
  wire [23:0] f_t_x, f_t_y;
  wire [16:0] f_t_ll_a, f_t_ll_b, f_t_lh_a, f_t_hl_b;
  wire [6:0]  f_t_lh_b, f_t_hl_a, f_t_hh_a, f_t_hh_b;
  wire [33:0] f_t_ll_p;
  wire [23:0] f_t_lh_p, f_t_hl_p;
  wire [13:0] f_t_hh_p;
  wire [47:0] f_t_prod;
  wire [3:0]  f_t_in_en, f_t_out_en;        // the DSP blocks' enables: ll, lh, hl, hh

  wire [23:0] sx1, sy1, sx2, sy2;
  fp32_prod_ghost #(.Width(48)) u_ghost (
    .clk_i(clk_i), .en1_i(f_t_v1), .d_i({f_t_x, f_t_y}), .en2_i(f_t_v2),
    .q1_o({sx1, sy1}), .q2_o({sx2, sy2}));

  // Ghost: the operands of each DSP block's output register, loaded with it.
  wire [16:0] g_ll_a, g_ll_b, g_lh_a, g_hl_b;
  wire [6:0]  g_lh_b, g_hl_a, g_hh_a, g_hh_b;
  wire [95:0] g_unused;
  fp32_prod_ghost #(.Width(96)) u_ghost_ops (
    .clk_i(clk_i), .en1_i(f_t_v2),
    .d_i({f_t_ll_a, f_t_ll_b, f_t_lh_a, f_t_lh_b, f_t_hl_a, f_t_hl_b, f_t_hh_a, f_t_hh_b}),
    .en2_i(1'b0), .q1_o({g_ll_a, g_ll_b, g_lh_a, g_lh_b, g_hl_a, g_hl_b, g_hh_a, g_hh_b}),
    .q2_o(g_unused));

  wire in_regs_ok  = f_t_ll_a == sx1[16:0]  && f_t_ll_b == sy1[16:0] &&
                     f_t_lh_a == sx1[16:0]  && f_t_lh_b == sy1[23:17] &&
                     f_t_hl_a == sx1[23:17] && f_t_hl_b == sy1[16:0] &&
                     f_t_hh_a == sx1[23:17] && f_t_hh_b == sy1[23:17];
  wire out_ops_ok  = g_ll_a == sx2[16:0]  && g_ll_b == sy2[16:0] &&
                     g_lh_a == sx2[16:0]  && g_lh_b == sy2[23:17] &&
                     g_hl_a == sx2[23:17] && g_hl_b == sy2[16:0] &&
                     g_hh_a == sx2[23:17] && g_hh_b == sy2[23:17];
  wire [47:0] sum  = {f_t_hh_p, 34'd0} + {14'd0, f_t_ll_p} + {7'd0, f_t_lh_p, 17'd0} +
                     {7'd0, f_t_hl_p, 17'd0};

  always @* begin
    // The ghost starts as the registers' (free) contents imply: the stage's history before the
    // first cycle.
    if (f_init) assume (in_regs_ok && out_ops_ok);
    assert (f_t_in_en == {4{f_t_v1}} && f_t_out_en == {4{f_t_v2}});
    assert (in_regs_ok);
    assert (out_ops_ok);
    assert (f_t_prod == sum);
  end

  // Cover: an operation leaves the stage with both significands normalised, and the unit's result.
  always @* begin
    if (!f_init) begin
      cover (f_t_v2 && sx1[23] && sy1[23]);
      cover (valid_o && y_o[30:23] != 8'h00);
    end
  end

  wire unused = ^{valid_o, y_o, g_unused};

endmodule

`default_nettype wire
