// SPDX-License-Identifier: Apache-2.0
// pree_fp32_mul: IEEE-754 binary32 multiplier, round to nearest even, Stages pipeline stages
// (2 by default, the paper's; 7 with PipeFast = 1).
//
// y = a * b. Subnormal inputs and outputs in full, signed zeros, overflow to a signed infinity.
// NaN result (x86-64 SSE rule): a NaN -> a quieted; else b NaN -> b quieted; else
// 0 * inf or inf * 0 -> 0xFFC00000.
//
// Parameters:
//   PipeFast  0: the paper's configuration (Stages = 2); 1: the deep configuration for FPGA
//             clock rates (Stages = 7). docs/fpga.md.
//   Stages    1 .. 8, the latency of the datapath; overrides PipeFast's choice. Every value
//             gives the same bits.
//   InRegs    0 or 1: registers on the operands before the datapath (seam 0), so that a
//             caller's operand select ends in a register (the PREU with PipeFast = 1).
//             LATENCY = InRegs + Stages.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// The datapath is cut at eight seams (pree_fp32_pipe each, a register or a wire):
//   A1 classify both operands and count the leading zeros of their significands
//      (pree_fp32_unpack_lz); special results decided here and carried beside the datapath
//                                                                                   -> seam 1
//   A2 normalise the significands (a subnormal one shifted left by its count,
//      pree_fp32_unpack_norm), exponent sum, sign                                   -> seam 2
//   B  the significand product. With seam 3 registered (then seam 2 is too) it is four partial
//      products of 17-bit and 7-bit pieces (a = ah * 2^17 + al, b = bh * 2^17 + bl; each
//      product at most 17 x 17, so it fits one DSP multiplier on both 7-series (25 x 18
//      signed) and ECP5 (18 x 18)), each in a pree_fp32_dsp_mul whose input and output
//      registers are seams 2 and 3 for it, held by the DSP block itself; otherwise one
//      24 x 24 `*`                                                                  -> seam 3
//   C  the cross terms: mid_sum = al * bh + ah * bl                                 -> seam 4
//   D  the 48-bit product: {ah * bh, al * bl} + mid_sum * 2^17                     -> seam 5
//      (seams 3 and 4 are only registered with the split product; without it B, C, D are the
//      single `*`)
//   E  normalise: the product of two normalised significands lies in [2^46, 2^48), so a
//      one-bit select, the sticky bit and the exponent; the denormalising shift amount
//      (pree_fp32_denorm_amt, formed for both binades and picked by the select)     -> seam 6
//   F  denormalise: a tiny result shifted right into the subnormal range
//      (pree_fp32_denorm)                                                           -> seam 7
//   G  round to nearest even (pree_fp32_round, Denorm = 0; rounded exactly once), final mux
//      with the special result                                                      -> seam 8
// Stage plan (registered seams per Stages; the last seam is always the output register):
//   Stages 1: 8 | 2: 5 8 | 3: 2 5 8 | 4: 2 5 7 8 | 5: 2 3 5 7 8 | 6: 2 3 5 6 7 8 |
//   7: 1 2 3 5 6 7 8 | 8: all
// Stages = 2 is the paper's split (stage 1 = A1 A2 B C D, stage 2 = E F G).
`default_nettype none

module pree_fp32_mul #(
  parameter PipeFast = 0,
  parameter Stages   = (PipeFast != 0) ? 7 : 2,
  parameter InRegs   = 0
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam MAX_STAGES = 8;

  // Registers at seam s (1 .. 8) under the stage plan above: bit s-1 of row Stages of PLANS
  // (rows Stages = 8 .. 1, left to right).
  localparam [8*8-1:0] PLANS = {8'b11111111, 8'b11110111, 8'b11110110, 8'b11010110,
                                8'b11010010, 8'b10010010, 8'b10010000, 8'b10000000};
  function integer seam_regs;
    input integer s;
    seam_regs = PLANS[((Stages < 1) ? 0 : (Stages > MAX_STAGES) ? MAX_STAGES - 1 : Stages - 1)
                      * MAX_STAGES + s - 1] ? 1 : 0;
  endfunction

  // The split product (four partial products) when its products are registered.
  localparam SPLIT = (seam_regs(3) != 0);

  // Every plan that registers seam 3 registers seam 2 too: the split product's pree_fp32_dsp_mul
  // holds both registers, so a plan without seam 2 would be one cycle out of step.
  generate
    if (SPLIT && seam_regs(2) == 0) begin : g_bad_plan
      pree_fp32_mul_split_product_needs_seam_2 u_fail ();
    end
  endgenerate

  // ---------------------------------------------------------------- entry: seam 0, the check
  // A Stages value outside its range, or PipeFast other than 0 or 1, stops elaboration (Verilator,
  // Icarus, Yosys) with a module named after the problem, however the unit is instantiated.
  generate
    if (Stages < 1 || Stages > MAX_STAGES) begin : g_bad_stages
      pree_fp32_mul_stages_is_1_to_8 u_fail ();
    end
    if (PipeFast < 0 || PipeFast > 1) begin : g_bad_pipefast
      pree_fp32_mul_pipefast_is_0_or_1 u_fail ();
    end
  endgenerate

  // InRegs operand registers before A1 (pree_fp32_entry, which refuses InRegs other than 0, 1).
  wire        valid0;
  wire [31:0] a0, b0;

  pree_fp32_entry #(.InRegs(InRegs), .Width(64)) u_entry (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i), .d_i ({a_i, b_i}),
    .valid_o (valid0), .q_o ({a0, b0})
  );

  // ---------------------------------------------------------------- A1, A2: unpack
  // Classify both operands, the special result (carried to the end with the sign: WK bits),
  // seam 1, normalise the significands (pree_fp32_unpack).
  localparam WK = 1 + 32 + 1;

  wire          s1_valid;
  wire [WK-1:0] s1_keep;
  wire [9:0]    exp_a, exp_b;
  wire [23:0]   man_a, man_b;

  pree_fp32_unpack #(.Div(0), .Regs(seam_regs(1))) u_unpack (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid0), .a_i (a0), .b_i (b0),
    .valid_o (s1_valid), .keep_o (s1_keep),
    .exp_a_o (exp_a), .man_a_o (man_a), .exp_b_o (exp_b), .man_b_o (man_b)
  );

  wire [9:0]  exp_d = exp_a + exp_b - 10'd127;   // biased exponent of product bit 46

  // ---------------------------------------------------------------- B, C, D: the product
  wire          s5_valid_d;
  wire [WK-1:0] s5_keep_d;
  wire [9:0]    s5_exp_d;
  wire [47:0]   prod_d;

  generate
    if (SPLIT) begin : g_split
      // B: four partial products, each in a pree_fp32_dsp_mul whose two registers are seams 2
      // and 3 for it (the DSP block's own input and output registers); the carried fields ride
      // seams 2 and 3 beside them.
      wire          s2_valid, s3_valid;
      wire [WK-1:0] s2_keep, s3_keep;
      wire [9:0]    s2_exp, s3_exp;
      wire [33:0]   s3_ll;
      wire [23:0]   s3_lh, s3_hl;
      wire [13:0]   s3_hh;

      pree_fp32_pipe #(.Width(WK + 10), .Regs(seam_regs(2))) u_seam2 (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s1_valid), .d_i ({s1_keep, exp_d}),
        .valid_o (s2_valid), .q_o ({s2_keep, s2_exp})
      );
      pree_fp32_dsp_mul #(.AW(17), .BW(17)) u_ll (
        .clk_i (clk_i), .in_en_i (s1_valid), .a_i (man_a[16:0]), .b_i (man_b[16:0]),
        .out_en_i (s2_valid), .p_o (s3_ll));
      pree_fp32_dsp_mul #(.AW(17), .BW(7)) u_lh (
        .clk_i (clk_i), .in_en_i (s1_valid), .a_i (man_a[16:0]), .b_i (man_b[23:17]),
        .out_en_i (s2_valid), .p_o (s3_lh));
      pree_fp32_dsp_mul #(.AW(7), .BW(17)) u_hl (
        .clk_i (clk_i), .in_en_i (s1_valid), .a_i (man_a[23:17]), .b_i (man_b[16:0]),
        .out_en_i (s2_valid), .p_o (s3_hl));
      pree_fp32_dsp_mul #(.AW(7), .BW(7)) u_hh (
        .clk_i (clk_i), .in_en_i (s1_valid), .a_i (man_a[23:17]), .b_i (man_b[23:17]),
        .out_en_i (s2_valid), .p_o (s3_hh));
      pree_fp32_pipe #(.Width(WK + 10), .Regs(seam_regs(3))) u_seam3 (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s2_valid), .d_i ({s2_keep, s2_exp}),
        .valid_o (s3_valid), .q_o ({s3_keep, s3_exp})
      );

      // C: the cross terms.
      wire [24:0] mid_sum = {1'b0, s3_lh} + {1'b0, s3_hl};

      wire          s4_valid;
      wire [WK-1:0] s4_keep;
      wire [9:0]    s4_exp;
      wire [47:0]   s4_outer;
      wire [24:0]   s4_mid;

      pree_fp32_pipe #(.Width(WK + 10 + 48 + 25), .Regs(seam_regs(4))) u_seam4 (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s3_valid),
        .d_i   ({s3_keep, s3_exp, s3_hh, s3_ll, mid_sum}),
        .valid_o (s4_valid), .q_o ({s4_keep, s4_exp, s4_outer, s4_mid})
      );

      // D: the product (below 2^48: it is the product of two 24-bit numbers).
      assign prod_d     = s4_outer + {6'd0, s4_mid, 17'd0};
      assign s5_valid_d = s4_valid;
      assign s5_keep_d  = s4_keep;
      assign s5_exp_d   = s4_exp;
    end else begin : g_single
      // B, C, D: one 24 x 24 product after seam 2 (seams 3 and 4 are wires in these plans).
      wire          s2_valid;
      wire [WK-1:0] s2_keep;
      wire [9:0]    s2_exp;
      wire [23:0]   s2_man_a, s2_man_b;

      pree_fp32_pipe #(.Width(WK + 10 + 48), .Regs(seam_regs(2))) u_seam2 (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s1_valid),
        .d_i   ({s1_keep, exp_d, man_a, man_b}),
        .valid_o (s2_valid), .q_o ({s2_keep, s2_exp, s2_man_a, s2_man_b})
      );

      assign prod_d     = s2_man_a * s2_man_b;
      assign s5_valid_d = s2_valid;
      assign s5_keep_d  = s2_keep;
      assign s5_exp_d   = s2_exp;
    end
  endgenerate

  wire          s5_valid;
  wire [WK-1:0] s5_keep;
  wire [9:0]    s5_exp;
  wire [47:0]   s5_prod;

  pree_fp32_pipe #(.Width(WK + 10 + 48), .Regs(seam_regs(5))) u_seam5 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s5_valid_d),
    .d_i   ({s5_keep_d, s5_exp_d, prod_d}),
    .valid_o (s5_valid), .q_o ({s5_keep, s5_exp, s5_prod})
  );

  // ---------------------------------------------------------------- E, F, G: the back end
  pree_fp32_mul_back #(
    .RegsNorm (seam_regs(6)), .RegsDen (seam_regs(7)), .RegsOut (seam_regs(8))
  ) u_back (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s5_valid),
    .keep_i (s5_keep), .exp_i (s5_exp), .prod_i (s5_prod),
    .valid_o (valid_o), .y_o (y_o)
  );

endmodule
