// SPDX-License-Identifier: Apache-2.0
// pree_fp32_sqr: IEEE-754 binary32 squarer, y = a * a, round to nearest even, Stages pipeline
// stages (2 by default, the paper's; 6 with PipeFast = 1: every seam below registered).
//
// Bit-identical to pree_fp32_mul with both operands equal, but cheaper:
//  - one operand, so one classifier and no subnormal normalisation: the square of any subnormal
//    (< 2^-126) is below 2^-252, far under half the smallest subnormal, so it is +0;
//  - the significand square uses the symmetry of a square. With m = H * 2^17 + L
//    (H = m[23:17], 7 bits; L = m[16:0], 17 bits):  m^2 = H^2 * 2^34 + H*L * 2^18 + L^2.
//    The cross term H*L is needed once (doubled by the shift) instead of twice. In the paper's
//    configuration L^2 is one 17 x 17 product (one DSP48 on a 7-series FPGA), while H^2 and H*L
//    are written as seven shifted partial products each, so they map to LUT adders instead of a
//    second DSP. With the products registered (seam 2 below) all three are `*` between two
//    registers, each within one DSP multiplier (7-series 25 x 18, ECP5 18 x 18), since a LUT
//    adder tree would be the slowest part of a deep pipeline.
// The result is never negative: -x * -x = +x^2, (-0)^2 = +0, (-inf)^2 = +inf.
// NaN result (x86-64 SSE rule): a NaN -> a quieted (sign and payload kept).
//
// Parameters:
//   PipeFast  0: the paper's configuration (Stages = 2); 1: the deep configuration for FPGA
//             clock rates (Stages = 6). docs/fpga.md.
//   Stages    1 .. 6, the latency of the datapath; overrides PipeFast's choice. Every value
//             gives the same bits.
//   InRegs    0 or 1: registers on the operands before the datapath (seam 0), so that a
//             caller's operand select ends in a register (the PREU with PipeFast = 1).
//             LATENCY = InRegs + Stages.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// The datapath is cut at six seams (pree_fp32_pipe each, a register or a wire):
//   A classify (special result carried beside the datapath), double the exponent, split the
//     significand into H and L                                                      -> seam 1
//   B the products H^2, H*L, L^2 (with seams 1 and 2 registered, each in a pree_fp32_dsp_mul
//     whose input and output registers are those seams for it)                       -> seam 2
//   C their sum: {H^2, L^2} + H*L * 2^18 (H^2 and L^2 do not overlap)               -> seam 3
//   D normalise: one-bit select, sticky bit, exponent, the denormalising shift amount
//     (pree_fp32_denorm_amt, formed for both binades and picked by the select)     -> seam 4
//   E denormalise (pree_fp32_denorm)                                                 -> seam 5
//   F round (pree_fp32_round, Denorm = 0), final mux with the special result        -> seam 6
// Stage plan (registered seams per Stages; the last seam is always the output register):
//   Stages 1: 6 | 2: 3 6 | 3: 3 5 6 | 4: 2 3 5 6 | 5: 1 2 3 5 6 | 6: all
// Stages = 2 is the paper's split (stage 1 = A B C, stage 2 = D E F).
`default_nettype none

module pree_fp32_sqr #(
  parameter PipeFast = 0,
  parameter Stages   = (PipeFast != 0) ? 6 : 2,
  parameter InRegs   = 0
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam MAX_STAGES = 6;

  // Registers at seam s (1 .. 6) under the stage plan above: bit s-1 of row Stages of PLANS
  // (rows Stages = 6 .. 1, left to right).
  localparam [6*6-1:0] PLANS = {6'b111111, 6'b110111, 6'b110110, 6'b110100,
                                6'b100100, 6'b100000};
  function integer seam_regs;
    input integer s;
    seam_regs = PLANS[((Stages < 1) ? 0 : (Stages > MAX_STAGES) ? MAX_STAGES - 1 : Stages - 1)
                      * MAX_STAGES + s - 1] ? 1 : 0;
  endfunction

  // All three products as `*` when they are registered; each in a DSP block with its own input
  // and output registers (pree_fp32_dsp_mul) when the seams before and after them are registered.
  localparam SPLIT    = (seam_regs(2) != 0);
  localparam DSP_REGS = SPLIT && (seam_regs(1) != 0);

  // ---------------------------------------------------------------- entry: seam 0, the check
  // A Stages value outside its range, or PipeFast other than 0 or 1, stops elaboration (Verilator,
  // Icarus, Yosys) with a module named after the problem, however the unit is instantiated.
  generate
    if (Stages < 1 || Stages > MAX_STAGES) begin : g_bad_stages
      pree_fp32_sqr_stages_is_1_to_6 u_fail ();
    end
    if (PipeFast < 0 || PipeFast > 1) begin : g_bad_pipefast
      pree_fp32_sqr_pipefast_is_0_or_1 u_fail ();
    end
  endgenerate

  // InRegs operand registers before A1 (pree_fp32_entry, which refuses InRegs other than 0, 1).
  wire        valid0;
  wire [31:0] a0;

  pree_fp32_entry #(.InRegs(InRegs), .Width(32)) u_entry (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i), .d_i ({a_i}),
    .valid_o (valid0), .q_o ({a0})
  );

  // ---------------------------------------------------------------- A: classify
  wire        exp_low, zero_unused, inf_a, nan_a;   // exp_low: zero or subnormal, square +0

  pree_fp32_class u_class (
    .x_i (a0[30:0]), .exp_zero_o (exp_low), .zero_o (zero_unused), .inf_o (inf_a),
    .nan_o (nan_a)
  );

  wire [9:0]  exp_d = {1'b0, a0[30:23], 1'b0} - 10'd127;   // biased exponent of product bit 46

  // Special result (pree_fp32_special): a NaN quieted, +inf, +0; the square is never negative.
  wire        special_d;
  wire [31:0] special_y_d;

  pree_fp32_special u_special (
    .a_i (a0), .b_i (a0), .nan_a_i (nan_a), .nan_b_i (1'b0),
    .invalid_i (1'b0), .inf_i (inf_a), .zero_i (exp_low), .sign_i (1'b0),
    .special_o (special_d), .y_o (special_y_d)
  );

  // Carried to the end: the special result and the sign (+); beside it the exponent.
  localparam WK = 1 + 32 + 1;

  // ---------------------------------------------------------------- B: the products
  wire          s2_valid;
  wire [WK-1:0] s2_keep;
  wire [9:0]    s2_exp;
  wire [13:0]   s2_hi;                               // H^2
  wire [23:0]   s2_mid;                              // H*L
  wire [33:0]   s2_lo;                               // L^2
  wire [23:0]   man = {1'b1, a0[22:0]};              // only used for normal operands

  generate
    if (DSP_REGS) begin : g_dsp_regs
      // Seams 1 and 2 both registered: each product in a pree_fp32_dsp_mul whose input and
      // output registers are those seams for it (the DSP block's own); the carried fields ride
      // the seams beside them.
      wire          s1_valid;
      wire [WK-1:0] s1_keep;
      wire [9:0]    s1_exp;

      pree_fp32_pipe #(.Width(WK + 10), .Regs(seam_regs(1))) u_seam1 (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid0),
        .d_i ({special_d, special_y_d, 1'b0, exp_d}), .valid_o (s1_valid), .q_o ({s1_keep, s1_exp})
      );
      pree_fp32_dsp_mul #(.AW(7), .BW(7)) u_hi (
        .clk_i (clk_i), .in_en_i (valid0), .a_i (man[23:17]), .b_i (man[23:17]),
        .out_en_i (s1_valid), .p_o (s2_hi));
      pree_fp32_dsp_mul #(.AW(7), .BW(17)) u_mid (
        .clk_i (clk_i), .in_en_i (valid0), .a_i (man[23:17]), .b_i (man[16:0]),
        .out_en_i (s1_valid), .p_o (s2_mid));
      pree_fp32_dsp_mul #(.AW(17), .BW(17)) u_lo (
        .clk_i (clk_i), .in_en_i (valid0), .a_i (man[16:0]), .b_i (man[16:0]),
        .out_en_i (s1_valid), .p_o (s2_lo));
      pree_fp32_pipe #(.Width(WK + 10), .Regs(seam_regs(2))) u_seam2 (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s1_valid), .d_i ({s1_keep, s1_exp}),
        .valid_o (s2_valid), .q_o ({s2_keep, s2_exp})
      );
    end else begin : g_seams
      wire          s1_valid;
      wire [WK-1:0] s1_keep;
      wire [9:0]    s1_exp;
      wire [23:0]   s1_man;

      pree_fp32_pipe #(.Width(WK + 10 + 24), .Regs(seam_regs(1))) u_seam1 (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid0),
        .d_i   ({special_d, special_y_d, 1'b0, exp_d, man}),
        .valid_o (s1_valid), .q_o ({s1_keep, s1_exp, s1_man})
      );

      wire [6:0]  man_hi = s1_man[23:17];
      wire [16:0] man_lo = s1_man[16:0];
      wire [13:0] sq_hi;
      wire [23:0] sq_mid;
      wire [33:0] sq_lo  = man_lo * man_lo;

      if (SPLIT) begin : g_dsp
        assign sq_hi  = man_hi * man_hi;
        assign sq_mid = man_hi * man_lo;
      end else begin : g_lut
        // Shift-and-add over the 7 bits of H (small products: LUT logic rather than a DSP).
        reg  [13:0] sq_hi_r;
        reg  [23:0] sq_mid_r;
        integer     i;
        always @* begin
          sq_hi_r  = 14'd0;
          sq_mid_r = 24'd0;
          for (i = 0; i < 7; i = i + 1) begin
            sq_hi_r  = sq_hi_r  + ({7'd0, man_hi & {7{man_hi[i]}}} << i);
            sq_mid_r = sq_mid_r + ({7'd0, man_lo & {17{man_hi[i]}}} << i);
          end
        end
        assign sq_hi  = sq_hi_r;
        assign sq_mid = sq_mid_r;
      end

      pree_fp32_pipe #(.Width(WK + 10 + 14 + 24 + 34), .Regs(seam_regs(2))) u_seam2 (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s1_valid),
        .d_i   ({s1_keep, s1_exp, sq_hi, sq_mid, sq_lo}),
        .valid_o (s2_valid), .q_o ({s2_keep, s2_exp, s2_hi, s2_mid, s2_lo})
      );
    end
  endgenerate

  // ---------------------------------------------------------------- C: the square
  // (H^2 and L^2 do not overlap; the three-term form lets Yosys use the DSP's post-adder and
  // output register in the paper's configuration.)
  wire [47:0] prod_d = SPLIT ? ({s2_hi, s2_lo} + {6'd0, s2_mid, 18'd0})
                             : ({s2_hi, 34'd0} + {6'd0, s2_mid, 18'd0} + {14'd0, s2_lo});

  wire          s3_valid;
  wire [WK-1:0] s3_keep;
  wire [9:0]    s3_exp;
  wire [47:0]   s3_prod;

  pree_fp32_pipe #(.Width(WK + 10 + 48), .Regs(seam_regs(3))) u_seam3 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s2_valid),
    .d_i   ({s2_keep, s2_exp, prod_d}),
    .valid_o (s3_valid), .q_o ({s3_keep, s3_exp, s3_prod})
  );

  // ---------------------------------------------------------------- D, E, F: the back end
  pree_fp32_mul_back #(
    .RegsNorm (seam_regs(4)), .RegsDen (seam_regs(5)), .RegsOut (seam_regs(6))
  ) u_back (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s3_valid),
    .keep_i (s3_keep), .exp_i (s3_exp), .prod_i (s3_prod),
    .valid_o (valid_o), .y_o (y_o)
  );

endmodule
