// SPDX-License-Identifier: Apache-2.0
// pree_wacc: the stable datapath's wide accumulator add, y = A + t, truncating, Stages pipeline
// stages (2 by default, the paper's; 5 with PipeFast = 1).
//
// Bit-exact with wide_add() of model/pree/wide_acc.h. A wide word (64 bits) is e = bits 63..56, an
// 8-bit exponent biased as binary32's, and M = bits 55..0, a 56-bit significand with its leading
// bit stored: value M * 2^(max(e, 1) - 182); e = 255 is +infinity (M = 0) or NaN (M != 0).
// t is binary32. A binary32 significand {hidden, fraction} placed in M[55:32] has the same
// exponent scale, so the two operands align by their effective exponents max(e, 1) alone.
//
// Special cases, in the model's priority order:
//   A NaN               -> A
//   t NaN               -> WIDE_NAN (0xFF40000000000000)
//   A +infinity         -> A
//   t negative (not NaN, -0 and -inf included) -> A unchanged (a dropped term)
//   t +infinity         -> WIDE_MAX (0xFEFFFFFFFFFFFFFF)
// Otherwise the operand with the smaller effective exponent is shifted right by the difference
// (bits shifted out are dropped; a shift of 56 or more gives 0), the significands are added, a
// carry out of bit 55 shifts the sum right by one (dropping its low bit) and raises the
// exponent, an exponent reaching 255 saturates to WIDE_MAX, and the exponent field is written
// as 0 when the sum's bit 55 is 0. Every input word is handled as the model handles it,
// including words whose M[55] disagrees with their e field.
//
// Parameters:
//   PipeFast  0: the paper's configuration (Stages = 2); 1: the deep configuration for FPGA
//             clock rates (Stages = 5: every seam below registered). docs/fpga.md.
//   Stages    1 .. 5, the latency of the datapath; overrides PipeFast's choice. Every value
//             gives the same bits.
//   InRegs    0 or 1: registers on the operands before the datapath (seam 0), so that a
//             caller's operand select ends in a register (the PREU with PipeFast = 1).
//             LATENCY = InRegs + Stages.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// The datapath is cut at five seams (pree_fp32_pipe each, a register or a wire):
//   A classify; the special results are carried as two flags (NaN, WIDE_MAX) and a pass flag
//     (the result is A); compare the effective exponents and form both differences, with their
//     "shifted out entirely" flags, beside the compare                             -> seam 1
//   B1 pick the big and the small operand by the compare (for "pass" the datapath carries A
//     itself: the big operand is M_A, the small one dropped, the exponent A's raw e field, so
//     no 64-bit special word is registered)                                         -> seam 2
//   B2 align the small operand (truncating shift)                                  -> seam 3
//   C 57-bit add; beside it the exponent after a carry and the saturation test      -> seam 4
//   D carry-out normalisation, saturation, exponent field, final mux                 -> seam 5
// Stage plan (registered seams per Stages; the last seam is always the output register):
//   Stages 1: 5 | 2: 3 5 | 3: 3 4 5 | 4: 1 3 4 5 | 5: all
// Stages = 2 is the paper's split (stage 1 = A B1 B2, stage 2 = C D).
`default_nettype none

module pree_wacc #(
  parameter PipeFast = 0,
  parameter Stages   = (PipeFast != 0) ? 5 : 2,
  parameter InRegs   = 0
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [63:0] a_i,
  input  wire [31:0] t_i,
  output wire        valid_o,
  output wire [63:0] y_o
);

  localparam MAX_STAGES = 5;
  localparam [63:0] WIDE_NAN = 64'hFF40_0000_0000_0000;
  localparam [63:0] WIDE_MAX = 64'hFEFF_FFFF_FFFF_FFFF;

  // Registers at seam s (1 .. 5) under the stage plan above: bit s-1 of row Stages of PLANS
  // (rows Stages = 5 .. 1, left to right).
  localparam [5*5-1:0] PLANS = {5'b11111, 5'b11101, 5'b11100, 5'b10100,
                                5'b10000};
  function integer seam_regs;
    input integer s;
    seam_regs = PLANS[((Stages < 1) ? 0 : (Stages > MAX_STAGES) ? MAX_STAGES - 1 : Stages - 1)
                      * MAX_STAGES + s - 1] ? 1 : 0;
  endfunction

  // ---------------------------------------------------------------- entry: seam 0, the check
  // A Stages value outside its range, or PipeFast other than 0 or 1, stops elaboration (Verilator,
  // Icarus, Yosys) with a module named after the problem, however the unit is instantiated.
  generate
    if (Stages < 1 || Stages > MAX_STAGES) begin : g_bad_stages
      pree_wacc_stages_is_1_to_5 u_fail ();
    end
    if (PipeFast < 0 || PipeFast > 1) begin : g_bad_pipefast
      pree_wacc_pipefast_is_0_or_1 u_fail ();
    end
  endgenerate

  // InRegs operand registers before A1 (pree_fp32_entry, which refuses InRegs other than 0, 1).
  wire        valid0;
  wire [63:0] a0;
  wire [31:0] t0;

  pree_fp32_entry #(.InRegs(InRegs), .Width(96)) u_entry (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i), .d_i ({a_i, t_i}),
    .valid_o (valid0), .q_o ({a0, t0})
  );

  // ---------------------------------------------------------------- A: classify, compare
  wire [7:0]  exp_a  = a0[63:56];
  wire [55:0] man_a  = a0[55:0];
  wire [7:0]  exp_t  = t0[30:23];
  wire        sign_t = t0[31];
  wire        nan_a  = (exp_a == 8'hFF) && (man_a != 56'd0);
  wire        inf_a  = (exp_a == 8'hFF) && (man_a == 56'd0);
  wire        expz_t, zero_t_unused, inf_t, nan_t;

  pree_fp32_class u_class_t (
    .x_i (t0[30:0]), .exp_zero_o (expz_t), .zero_o (zero_t_unused), .inf_o (inf_t),
    .nan_o (nan_t)
  );

  // Special results (priority as in wide_add): pass = the result is A.
  wire pass_d = nan_a | (~nan_t & (inf_a | sign_t));
  wire nan_d  = ~nan_a & nan_t;
  wire max_d  = ~nan_a & ~nan_t & ~inf_a & ~sign_t & inf_t;

  // Effective exponents; the operand with the larger one is "big" (on a tie, A; for pass, A).
  wire [7:0]  exp_a1  = (exp_a == 8'd0) ? 8'd1 : exp_a;
  wire [7:0]  exp_t1  = expz_t ? 8'd1 : exp_t;
  wire        swap    = (exp_t1 > exp_a1) & ~pass_d;
  wire [7:0]  diff_at = exp_a1 - exp_t1;
  wire [7:0]  diff_ta = exp_t1 - exp_a1;
  // A shift of 56 or more (or pass) leaves nothing of the small operand.
  wire        gone_at = pass_d | (diff_at >= 8'd56);
  wire        gone_ta = (diff_ta >= 8'd56);

  wire        s1_valid;
  wire [63:0] s1_a;
  wire [23:0] s1_t;                                // t's significand field and hidden bit
  wire [7:0]  s1_exp_t1;
  wire        s1_pass, s1_nan, s1_max, s1_swap, s1_gone_at, s1_gone_ta;
  wire [5:0]  s1_diff_at, s1_diff_ta;

  pree_fp32_pipe #(.Width(64 + 24 + 8 + 6 + 12), .Regs(seam_regs(1))) u_seam1 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid0),
    .d_i   ({a0, ~expz_t, t0[22:0], exp_t1, pass_d, nan_d, max_d, swap,
             gone_at, gone_ta, diff_at[5:0], diff_ta[5:0]}),
    .valid_o (s1_valid),
    .q_o   ({s1_a, s1_t, s1_exp_t1, s1_pass, s1_nan, s1_max, s1_swap,
             s1_gone_at, s1_gone_ta, s1_diff_at, s1_diff_ta})
  );

  // ---------------------------------------------------------------- B1: pick the operands
  wire [7:0]  s1_exp_a  = s1_a[63:56];
  wire [55:0] s1_man_a  = s1_a[55:0];
  wire [7:0]  s1_exp_a1 = (s1_exp_a == 8'd0) ? 8'd1 : s1_exp_a;
  wire [55:0] man_t     = {s1_t, 32'd0};           // t's significand sits in M[55:32]
  wire [55:0] man_big   = s1_swap ? man_t : s1_man_a;
  wire [55:0] man_sml   = s1_swap ? s1_man_a : man_t;
  wire [7:0]  exp_big   = s1_pass ? s1_exp_a : (s1_swap ? s1_exp_t1 : s1_exp_a1);
  wire [5:0]  sh        = s1_swap ? s1_diff_ta : s1_diff_at;
  wire        sml_gone  = s1_swap ? s1_gone_ta : s1_gone_at;

  wire        s2_valid;
  wire [55:0] s2_big, s2_sml;
  wire [7:0]  s2_exp;
  wire [5:0]  s2_sh;
  wire        s2_gone, s2_pass, s2_nan, s2_max;

  pree_fp32_pipe #(.Width(56 + 56 + 8 + 6 + 4), .Regs(seam_regs(2))) u_seam2 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s1_valid),
    .d_i   ({man_big, man_sml, exp_big, sh, sml_gone, s1_pass, s1_nan, s1_max}),
    .valid_o (s2_valid), .q_o ({s2_big, s2_sml, s2_exp, s2_sh, s2_gone, s2_pass, s2_nan, s2_max})
  );

  // ---------------------------------------------------------------- B2: align
  wire [55:0] aligned = s2_gone ? 56'd0 : (s2_sml >> s2_sh);

  wire        s3_valid;
  wire [55:0] s3_big, s3_sml;
  wire [7:0]  s3_exp;
  wire        s3_pass, s3_nan, s3_max;

  pree_fp32_pipe #(.Width(56 + 56 + 8 + 3), .Regs(seam_regs(3))) u_seam3 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s2_valid),
    .d_i   ({s2_big, aligned, s2_exp, s2_pass, s2_nan, s2_max}),
    .valid_o (s3_valid), .q_o ({s3_big, s3_sml, s3_exp, s3_pass, s3_nan, s3_max})
  );

  // ---------------------------------------------------------------- C: add
  wire [56:0] sum_d = {1'b0, s3_big} + {1'b0, s3_sml};
  // Beside the add: the exponent after a carry, and whether a carry saturates (without pass
  // the exponent is at most 254, so it reaches 255 only by a carry from 254).
  wire [7:0]  exp_up_d  = s3_exp + 8'd1;
  wire        exp_top_d = (s3_exp == 8'd254);

  wire        s4_valid;
  wire [56:0] s4_sum;
  wire [55:0] s4_big;
  wire [7:0]  s4_exp, s4_exp_up;
  wire        s4_exp_top, s4_pass, s4_nan, s4_max;

  pree_fp32_pipe #(.Width(57 + 56 + 8 + 8 + 4), .Regs(seam_regs(4))) u_seam4 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s3_valid),
    .d_i   ({sum_d, s3_big, s3_exp, exp_up_d, exp_top_d, s3_pass, s3_nan, s3_max}),
    .valid_o (s4_valid),
    .q_o   ({s4_sum, s4_big, s4_exp, s4_exp_up, s4_exp_top, s4_pass, s4_nan, s4_max})
  );

  // ---------------------------------------------------------------- D: normalise, final mux
  wire [56:0] sum   = s4_sum;
  wire        carry = sum[56];
  wire [55:0] man_s = carry ? sum[56:1] : sum[55:0];    // truncating: sum[0] is dropped
  wire [7:0]  exp_s = carry ? s4_exp_up : s4_exp;
  wire        sat   = carry & s4_exp_top;

  wire [63:0] y_d = s4_nan             ? WIDE_NAN
                  : s4_pass            ? {s4_exp, s4_big}
                  : (s4_max | sat)     ? WIDE_MAX
                  :                      {man_s[55] ? exp_s : 8'd0, man_s};

  pree_fp32_pipe #(.Width(64), .Regs(seam_regs(5))) u_seam5 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s4_valid), .d_i (y_d),
    .valid_o (valid_o), .q_o (y_o)
  );

endmodule
