// SPDX-License-Identifier: Apache-2.0
// fp32_cut_miter: formal miter of a binary32 unit whose significand product is cut out (jobs
// fp32_mul and fp32_sqr_cut; docs/formal.md): a deep configuration (Stages = DutStages) against
// the paper's (Stages 2) in one fp32_equiv_miter, with the job's taps.ys making each unit's 48-bit
// product (prod_d, where the unit's back end takes it) a cut point (Yosys cutpoint: a free value
// every cycle, its multipliers removed), so the solver never sees a multiplier. The products are
// then constrained only as a function of the operands could be:
//   - congruence: the deep unit's product, when consumed, equals the paper unit's product of the
//     same operation (CutDelay cycles earlier) whenever the two operand words are equal (the same
//     function on both sides: an uninterpreted function);
//   - range: when the operand bits TopMask are all set (normalised significands, [2^23, 2^24)),
//     the product lies in [2^46, 2^48), as x * y and m * m do.
// So the miter proves that front (classify, normalise, exponent), pipeline and back end
// (normalise, denormalise, round, special results) of the two configurations agree for EVERY such
// product function, the true one among them. That each configuration's product stage computes the
// product of the operands it consumes is proven apart (fp32_mul_dsp, fp32_sqr_prod).
//
// Ghost state (fp32_prod_ghost): the deep plan's product stage holds its operands in a DSP
// block's input and output registers; the ghost takes the operand word where they load (taps), so
// its second stage holds the operands whose product the stage now delivers. Asserted (so proven):
// the deep unit consumes a product exactly when the paper unit consumed one CutDelay cycles
// earlier, and of the same operands.
`default_nettype none

module fp32_cut_miter #(
  parameter Unit      = "mul",  // mul or sqr
  parameter DutStages = 7,
  parameter CutDelay  = 3,      // the deep plan's product stage latency beyond the paper plan's
  parameter OpW       = 48,     // the operand word: {x, y} (mul) or m (sqr)
  parameter [OpW-1:0] TopMask = {1'b1, 23'd0, 1'b1, 23'd0}
) (
  input wire        clk_i,
  input wire        valid_i,
  input wire [31:0] a_i,
  input wire [31:0] b_i
);

  fp32_equiv_miter #(.Unit(Unit), .DutStages(DutStages), .DutInRegs(0)) u_m (
    .clk_i(clk_i), .valid_i(valid_i), .a_i(a_i), .b_i(b_i), .sub_i(1'b0));

  // Taps (taps.ys): the two cut products, where each unit consumes its product, the operands.
  wire [47:0]    f_t_ref_p, f_t_dut_p;  // the cut products: free
  wire           f_t_ref_v;             // the paper unit consumes f_t_ref_p
  wire [OpW-1:0] f_t_ref_ops;           // of these operands (combinational from its inputs)
  wire           f_t_dut_v;             // the deep unit consumes f_t_dut_p
  wire           f_t_dut_v1, f_t_dut_v2;  // its DSP input and output registers load
  wire [OpW-1:0] f_t_dut_ops;           // the operands its DSP input registers take

  reg f_init = 1'b1;
  always @(posedge clk_i) f_init <= 1'b0;

  wire [OpW-1:0] g_ops1, g_ops2;
  fp32_prod_ghost #(.Width(OpW)) u_ghost (
    .clk_i(clk_i), .en1_i(f_t_dut_v1), .d_i(f_t_dut_ops), .en2_i(f_t_dut_v2),
    .q1_o(g_ops1), .q2_o(g_ops2));

  // The paper unit's consumptions, CutDelay cycles late: valid, operands, product.
  localparam RW = OpW + 48;
  reg [CutDelay-1:0]    d_v = {CutDelay{1'b0}};
  reg [CutDelay*RW-1:0] d_op;
  wire [RW-1:0]         d_old = d_op[CutDelay*RW-1 -: RW];
  always @(posedge clk_i) begin
    d_v  <= {d_v, f_t_ref_v && !f_init};
    d_op <= {d_op, f_t_ref_ops, f_t_ref_p};
  end

  always @* begin
    // The product functions: in range for normalised operands, and the same on both sides.
    if (f_t_ref_v && (f_t_ref_ops & TopMask) == TopMask) assume (f_t_ref_p[47:46] != 2'b00);
    if (f_t_dut_v && d_v[CutDelay-1] && g_ops2 == d_old[RW-1:48]) assume (f_t_dut_p == d_old[47:0]);
    // The product stages are in step: proven.
    if (!f_init) begin
      assert (f_t_dut_v == d_v[CutDelay-1]);
      if (f_t_dut_v) assert (g_ops2 == d_old[RW-1:48]);
    end
  end

  wire unused = ^g_ops1;

endmodule

`default_nettype wire
