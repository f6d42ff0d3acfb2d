// SPDX-License-Identifier: Apache-2.0
// fp32_sqr_prod_fv: the fp32_sqr_prod job's top (docs/formal.md): the product stages of
// pree_fp32_sqr's deep configuration (Stages 6) and of the paper's (Stages 2) both deliver the
// square of the significand m = H * 2^17 + L (H = m[23:17], L = m[16:0]) they consumed, the
// function fp32_sqr_cut assumes of its cut. Proven, for every operand stream:
//   - Stages 6 (H^2, H*L, L^2 each in a pree_fp32_dsp_mul with its own input and output
//     registers): the three DSP blocks load their input registers with seam 0's valid bit and their
//     output registers with seam 1's; their input registers hold the pieces of the significand
//     last taken (ghost g_m1: fp32_prod_ghost), and the operands of their output registers'
//     products (ghost, loaded with them) are the pieces of the significand of the operation leaving
//     the stage (g_m2): u_hi H * H, u_mid H * L, u_lo L * L; the stage's output prod_d is
//     H^2 * 2^34 + L^2 + H*L * 2^18 of the three output registers, in 48 bits;
//   - Stages 2 (H^2 and H*L by shift and add over H's 7 bits, L^2 one `*`, no register): its H
//     and L are the significand's pieces, its shift-and-add H^2 equals the `*` product H * H,
//     and prod_d is H^2 * 2^34 + H*L * 2^18 + L^2 of its three products, in 48 bits.
// Not checked by the solver: Stages 2's shift-and-add H*L against the `*` product (a 7 x 17
// multiplier equivalence: no answer in 5 minutes; the squarer's exhaustive significand sweep,
// make sim-fp32-sweep-sqr, checks every significand of the paper configuration against the C
// model instead); that a DSP output register holds the product of the operands it loaded
// (pree_fp32_dsp_mul's `p_q <= a_q * b_q`); and the algebra: (H * 2^17 + L)^2 = H^2 * 2^34 +
// 2 H L * 2^17 + L^2, every term exact and the sum m^2 < 2^48 losing no bit.
`default_nettype none

module fp32_sqr_prod_fv (
  input wire        clk_i,
  input wire        valid_i,
  input wire [31:0] a_i,
  output wire [63:0] y_o       // both results: an output, so that Yosys keeps both datapaths
);

  reg f_init = 1'b1;
  always @(posedge clk_i) f_init <= 1'b0;

  wire        dut_valid, ref_valid;
  wire [31:0] dut_y, ref_y;
  pree_fp32_sqr #(.Stages(6)) u_dut (
    .clk_i(clk_i), .rst_ni(!f_init), .valid_i(valid_i), .a_i(a_i),
    .valid_o(dut_valid), .y_o(dut_y));
  pree_fp32_sqr #(.Stages(2)) u_ref (
    .clk_i(clk_i), .rst_ni(!f_init), .valid_i(valid_i), .a_i(a_i),
    .valid_o(ref_valid), .y_o(ref_y));

  // Taps (taps.ys). The deep unit: the stage's valid bits, significand, registers, output.
  wire        f_t_v1, f_t_v2;
  wire [23:0] f_t_m;
  wire [2:0]  f_t_in_en, f_t_out_en;        // hi, mid, lo
  wire [6:0]  f_t_hi_a, f_t_hi_b, f_t_mid_a;
  wire [16:0] f_t_mid_b, f_t_lo_a, f_t_lo_b;
  wire [13:0] f_t_hi_p;
  wire [23:0] f_t_mid_p;
  wire [33:0] f_t_lo_p;
  wire [47:0] f_t_prod;
  // The paper unit: its significand's pieces, its three products and its output.
  wire [6:0]  f_t_r_h;
  wire [16:0] f_t_r_l;
  wire [13:0] f_t_r_hi;
  wire [23:0] f_t_r_mid;
  wire [33:0] f_t_r_lo;
  wire [47:0] f_t_r_prod;
  wire [23:0] f_t_r_m;

  wire [23:0] g_m1, g_m2;
  fp32_prod_ghost #(.Width(24)) u_ghost (
    .clk_i(clk_i), .en1_i(f_t_v1), .d_i(f_t_m), .en2_i(f_t_v2), .q1_o(g_m1), .q2_o(g_m2));

  // The operands of each DSP output register's product, loaded with it.
  wire [6:0]  g_hi_a, g_hi_b, g_mid_a;
  wire [16:0] g_mid_b, g_lo_a, g_lo_b;
  wire [71:0] g_unused;
  fp32_prod_ghost #(.Width(72)) u_ghost_ops (
    .clk_i(clk_i), .en1_i(f_t_v2),
    .d_i({f_t_hi_a, f_t_hi_b, f_t_mid_a, f_t_mid_b, f_t_lo_a, f_t_lo_b}), .en2_i(1'b0),
    .q1_o({g_hi_a, g_hi_b, g_mid_a, g_mid_b, g_lo_a, g_lo_b}), .q2_o(g_unused));

  wire in_regs_ok = f_t_hi_a == g_m1[23:17] && f_t_hi_b == g_m1[23:17] &&
                    f_t_mid_a == g_m1[23:17] && f_t_mid_b == g_m1[16:0] &&
                    f_t_lo_a == g_m1[16:0] && f_t_lo_b == g_m1[16:0];
  wire out_ops_ok = g_hi_a == g_m2[23:17] && g_hi_b == g_m2[23:17] &&
                    g_mid_a == g_m2[23:17] && g_mid_b == g_m2[16:0] &&
                    g_lo_a == g_m2[16:0] && g_lo_b == g_m2[16:0];
  wire [47:0] dut_sum = {f_t_hi_p, 34'd0} + {14'd0, f_t_lo_p} + {6'd0, f_t_mid_p, 18'd0};
  wire [47:0] ref_sum = {f_t_r_hi, 34'd0} + {14'd0, f_t_r_lo} + {6'd0, f_t_r_mid, 18'd0};

  always @* begin
    // The ghosts start as the registers' (free) contents imply.
    if (f_init) assume (in_regs_ok && out_ops_ok);
    assert (f_t_in_en == {3{f_t_v1}} && f_t_out_en == {3{f_t_v2}});
    assert (in_regs_ok);
    assert (out_ops_ok);
    assert (f_t_prod == dut_sum);
    assert (f_t_r_h == f_t_r_m[23:17] && f_t_r_l == f_t_r_m[16:0]);
    assert (f_t_r_hi == f_t_r_h * f_t_r_h);
    assert (f_t_r_lo == f_t_r_l * f_t_r_l);
    assert (f_t_r_prod == ref_sum);
  end

  // Cover: results leave both units.
  always @* begin
    if (!f_init) begin
      cover (f_t_v2 && g_m1[23]);
      cover (dut_valid && ref_valid && dut_y[30:23] != 8'h00);
    end
  end

  assign y_o = {dut_y, ref_y};
  wire unused = ^g_unused;

endmodule

`default_nettype wire
