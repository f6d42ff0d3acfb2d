// SPDX-License-Identifier: Apache-2.0
// pree_fp32_add: IEEE-754 binary32 adder/subtractor, round to nearest even, Stages pipeline
// stages (2 by default, the paper's; 7 with PipeFast = 1).
//
// y = a + b, or a - b when sub_i. Subnormal inputs and outputs in full, x - x = +0,
// (-0) + (-0) = -0, overflow to a signed infinity. NaN result (x86-64 SSE rule): a NaN -> a
// quieted; else b NaN -> b quieted, its sign not flipped by sub_i; else inf - inf -> 0xFFC00000.
//
// Parameters:
//   PipeFast  0: the paper's configuration (Stages = 2); 1: the deep configuration for FPGA
//             clock rates (Stages = 7: every seam below registered). docs/fpga.md.
//   Stages    1 .. 7, the latency of the datapath; overrides PipeFast's choice. Every value
//             gives the same bits.
//   InRegs    0 or 1: registers on the operands before the datapath (seam 0), so that a
//             caller's operand select ends in a register (the PREU with PipeFast = 1).
//             LATENCY = InRegs + Stages.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// The datapath is cut at seven seams (pree_fp32_pipe each, a register or a wire):
//   A1 classify: special results (NaN, infinity) decided and carried beside the datapath;
//      compare the magnitudes (binary32 magnitudes order as integers) and, beside the compare,
//      both exponent differences clamped to shift amounts                           -> seam 1
//   A2 order the operands by the comparison: L the larger, S the smaller             -> seam 2
//   B  align: the smaller significand, extended by 3 bits, shifted right; every bit shifted
//      out beyond those 3 is ORed into the lowest one (sticky)                       -> seam 3
//   C  add or subtract: a 28-bit unnormalised sum                                    -> seam 4
//   D  leading-zero count of the sum, limited to exponent - 1 (so that the exponent never
//      falls below 1: the result is then an exact subnormal): when seam 5 is registered by a
//      sentinel bit that B places at bit 27 - exponent, else by a compare; zero test: an
//      exact zero sum, which packs as a zero, gets the sign of a zero sum            -> seam 5
//   E  normalise: one right shift on a carry out (the lost bit becomes sticky), else the
//      left shift                                                                    -> seam 6
//   F  round to nearest even and final mux with the special result (pree_fp32_final)
//                                                                                    -> seam 7
// Stage plan (registered seams per Stages; the last seam is always the output register):
//   Stages 1: 7 | 2: 4 7 | 3: 3 5 7 | 4: 3 5 6 7 | 5: 2 3 5 6 7 | 6: 2 3 4 5 6 7 | 7: all
// Stages = 2 is the paper's split (stage 1 = A1 A2 B C, stage 2 = D E F).
// Why 3 extra bits suffice: with an exponent difference of 0 or 1 the aligned sum is exact; with
// 2 or more, cancellation removes at most one leading bit, so guard and sticky survive.
`default_nettype none

module pree_fp32_add #(
  parameter PipeFast = 0,
  parameter Stages   = (PipeFast != 0) ? 7 : 2,
  parameter InRegs   = 0
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  input  wire        sub_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam MAX_STAGES = 7;

  // Registers at seam s (1 .. 7) under the stage plan above: bit s-1 of row Stages of PLANS
  // (rows Stages = 7 .. 1, left to right).
  localparam [7*7-1:0] PLANS = {7'b1111111, 7'b1111110, 7'b1110110, 7'b1110100,
                                7'b1010100, 7'b1001000, 7'b1000000};
  function integer seam_regs;
    input integer s;
    seam_regs = PLANS[((Stages < 1) ? 0 : (Stages > MAX_STAGES) ? MAX_STAGES - 1 : Stages - 1)
                      * MAX_STAGES + s - 1] ? 1 : 0;
  endfunction

  // D's count limited by a sentinel bit (set in B) when D ends with a register.
  localparam SENTINEL = (seam_regs(5) != 0);
  // B's sticky bit from a mask when B lies between two registers.
  localparam ALIGN_MASK = (seam_regs(2) != 0) && (seam_regs(3) != 0);

  // ---------------------------------------------------------------- entry: seam 0, the check
  // A Stages value outside its range, or PipeFast other than 0 or 1, stops elaboration (Verilator,
  // Icarus, Yosys) with a module named after the problem, however the unit is instantiated.
  generate
    if (Stages < 1 || Stages > MAX_STAGES) begin : g_bad_stages
      pree_fp32_add_stages_is_1_to_7 u_fail ();
    end
    if (PipeFast < 0 || PipeFast > 1) begin : g_bad_pipefast
      pree_fp32_add_pipefast_is_0_or_1 u_fail ();
    end
  endgenerate

  // InRegs operand registers before A1 (pree_fp32_entry, which refuses InRegs other than 0, 1).
  wire        valid0, sub0;
  wire [31:0] a0, b0;

  pree_fp32_entry #(.InRegs(InRegs), .Width(65)) u_entry (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i), .d_i ({sub_i, a_i, b_i}),
    .valid_o (valid0), .q_o ({sub0, a0, b0})
  );

  // ---------------------------------------------------------------- A1: classify, compare
  wire       sign_a = a0[31];
  wire       sign_b = b0[31] ^ sub0;          // effective sign of the second operand
  wire [7:0] exp_a  = a0[30:23];
  wire [7:0] exp_b  = b0[30:23];
  wire       expz_a, expz_b, zero_a_unused, zero_b_unused, inf_a, inf_b, nan_a, nan_b;

  pree_fp32_class u_class_a (
    .x_i (a0[30:0]), .exp_zero_o (expz_a), .zero_o (zero_a_unused), .inf_o (inf_a),
    .nan_o (nan_a)
  );
  pree_fp32_class u_class_b (
    .x_i (b0[30:0]), .exp_zero_o (expz_b), .zero_o (zero_b_unused), .inf_o (inf_b),
    .nan_o (nan_b)
  );

  // Special result (pree_fp32_special): NaN rule first, then inf - inf, then infinities.
  wire        special_d;
  wire [31:0] special_y_d;

  pree_fp32_special u_special (
    .a_i (a0), .b_i (b0), .nan_a_i (nan_a), .nan_b_i (nan_b),
    .invalid_i (inf_a & inf_b & (sign_a != sign_b)), .inf_i (inf_a | inf_b), .zero_i (1'b0),
    .sign_i (inf_a ? sign_a : sign_b),
    .special_o (special_d), .y_o (special_y_d)
  );

  // Order by magnitude (L the larger or equal operand, S the smaller) and the alignment
  // shift, exp_l - exp_s clamped to 31: both differences are formed beside the magnitude
  // comparison, and the comparison picks one in A2, so no subtraction follows the compare.
  wire        swap    = (b0[30:0] > a0[30:0]);
  wire [7:0]  exp_a1  = expz_a ? 8'd1 : exp_a;   // subnormal: exponent 1, no hidden bit
  wire [7:0]  exp_b1  = expz_b ? 8'd1 : exp_b;
  wire [7:0]  diff_ab = exp_a1 - exp_b1;
  wire [7:0]  diff_ba = exp_b1 - exp_a1;
  wire [4:0]  sh_ab   = (diff_ab[7:5] != 3'd0) ? 5'd31 : diff_ab[4:0];
  wire [4:0]  sh_ba   = (diff_ba[7:5] != 3'd0) ? 5'd31 : diff_ba[4:0];

  // Carried to the end: the special result.
  localparam WS = 1 + 32;

  wire          s1_valid;
  wire [WS-1:0] s1_special;
  wire          s1_sign_a, s1_sign_b, s1_swap;
  wire          s1_expz_a, s1_expz_b;             // the classes: exponent field 0
  wire [4:0]    s1_sh_ab, s1_sh_ba;
  wire [30:0]   s1_a, s1_b;                       // the operands' magnitudes

  pree_fp32_pipe #(.Width(WS + 5 + 10 + 62), .Regs(seam_regs(1))) u_seam1 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid0),
    .d_i   ({special_d, special_y_d, sign_a, sign_b, swap, expz_a, expz_b, sh_ab, sh_ba,
             a0[30:0], b0[30:0]}),
    .valid_o (s1_valid),
    .q_o   ({s1_special, s1_sign_a, s1_sign_b, s1_swap, s1_expz_a, s1_expz_b, s1_sh_ab,
             s1_sh_ba, s1_a, s1_b})
  );

  // ---------------------------------------------------------------- A2: order the operands
  wire [23:0] man_a    = {~s1_expz_a, s1_a[22:0]};
  wire [23:0] man_b    = {~s1_expz_b, s1_b[22:0]};
  wire [7:0]  exp_a1_q = s1_expz_a ? 8'd1 : s1_a[30:23];
  wire [7:0]  exp_b1_q = s1_expz_b ? 8'd1 : s1_b[30:23];
  wire        sign_l   = s1_swap ? s1_sign_b : s1_sign_a;
  wire        sign_s   = s1_swap ? s1_sign_a : s1_sign_b;
  wire [7:0]  exp_l    = s1_swap ? exp_b1_q  : exp_a1_q;
  wire [23:0] man_l    = s1_swap ? man_b     : man_a;
  wire [23:0] man_s    = s1_swap ? man_a     : man_b;
  wire [4:0]  sh       = s1_swap ? s1_sh_ba  : s1_sh_ab;

  // Carried to the end: the special result, the sign of the larger operand and the sign of an
  // exact zero sum (negative only for (-x) + (-x) = -0).
  localparam WK = WS + 1 + 1;
  wire [WK-1:0] keep_d = {s1_special, sign_l, sign_l & sign_s};

  wire          s2_valid;
  wire [WK-1:0] s2_keep;
  wire          s2_eff_sub;
  wire [7:0]    s2_exp;
  wire [4:0]    s2_sh;
  wire [23:0]   s2_man_l, s2_man_s;

  pree_fp32_pipe #(.Width(WK + 1 + 8 + 5 + 24 + 24), .Regs(seam_regs(2))) u_seam2 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s1_valid),
    .d_i   ({keep_d, sign_l != sign_s, exp_l, sh, man_l, man_s}),
    .valid_o (s2_valid), .q_o ({s2_keep, s2_eff_sub, s2_exp, s2_sh, s2_man_l, s2_man_s})
  );

  // ---------------------------------------------------------------- B: align
  // ALIGN_MASK (B between two registers): the bits that the shift drops below the 3 extra bits
  // are found with a mask of the low s2_sh bits beside the shifter (a shorter path on ECP5,
  // measured); otherwise from the low word of a 59-bit shift (fewer LUTs, measured).
  wire [26:0] al_small;

  generate
    if (ALIGN_MASK) begin : g_align_mask
      wire [26:0] aligned = {s2_man_s, 3'd0} >> s2_sh;
      wire [26:0] dropped = ~(27'h7FF_FFFF << s2_sh);
      wire        lost    = (({s2_man_s, 3'd0} & dropped) != 27'd0);
      assign al_small = {aligned[26:1], aligned[0] | lost};
    end else begin : g_align_shift
      wire [58:0] aligned = {s2_man_s, 3'd0, 32'd0} >> s2_sh;
      assign al_small = {aligned[58:33], aligned[32] | (aligned[31:0] != 32'd0)};
    end
  endgenerate

  // The normalising left shift may not take the exponent below 1, so it is at most exp - 1.
  // With a register after D (SENTINEL), a sentinel one at bit 27 - exp of the sum's 27 low
  // bits (none when exp >= 28) makes D's leading-zero count stop there by itself, with no
  // compare after the count; without one, D compares (fewer LUTs, measured).
  wire [26:0] floor_d  = (SENTINEL && s2_exp <= 8'd27) ? (27'd1 << (8'd27 - s2_exp)) : 27'd0;

  wire          s3_valid;
  wire [WK-1:0] s3_keep;
  wire          s3_eff_sub;
  wire [7:0]    s3_exp;
  wire [26:0]   s3_floor;
  wire [23:0]   s3_man_l;
  wire [26:0]   s3_al_small;

  pree_fp32_pipe #(.Width(WK + 1 + 8 + 27 + 24 + 27), .Regs(seam_regs(3))) u_seam3 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s2_valid),
    .d_i   ({s2_keep, s2_eff_sub, s2_exp, floor_d, s2_man_l, al_small}),
    .valid_o (s3_valid), .q_o ({s3_keep, s3_eff_sub, s3_exp, s3_floor, s3_man_l, s3_al_small})
  );

  // ---------------------------------------------------------------- C: add or subtract
  wire [26:0] al_large = {s3_man_l, 3'd0};
  wire [27:0] sum_d    = s3_eff_sub ? ({1'b0, al_large} - {1'b0, s3_al_small})
                                    : ({1'b0, al_large} + {1'b0, s3_al_small});

  wire          s4_valid;
  wire [WK-1:0] s4_keep;
  wire [7:0]    s4_exp;
  wire [26:0]   s4_floor;
  wire [27:0]   s4_sum;

  pree_fp32_pipe #(.Width(WK + 8 + 27 + 28), .Regs(seam_regs(4))) u_seam4 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s3_valid),
    .d_i   ({s3_keep, s3_exp, s3_floor, sum_d}),
    .valid_o (s4_valid), .q_o ({s4_keep, s4_exp, s4_floor, s4_sum})
  );

  // ---------------------------------------------------------------- D: leading zeros
  // The left shift: the leading-zero count, but never below exponent 1 (B's sentinel, or a
  // compare with exponent - 1; lz <= 27 < 32).
  wire [4:0] lz;
  pree_fp32_lzc #(.Width(27), .CntWidth(5)) u_lzc (
    .x_i   (s4_sum[26:0] | s4_floor),
    .cnt_o (lz)
  );
  wire [7:0] exp_m1 = s4_exp - 8'd1;
  wire [4:0] lshift = (!SENTINEL && ({3'd0, lz} > exp_m1)) ? exp_m1[4:0] : lz;

  // An exact zero sum normalises to a zero significand, which rounds and packs as a zero of
  // the result's sign; so its sign (zero_sign) replaces the larger operand's here, and no zero
  // case reaches the final mux. From here on the carried bits are the special result and the
  // sign (WS + 1).
  wire          sum_zero = (s4_sum == 28'd0);
  wire [WS:0]   keep_e   = {s4_keep[WK-1:2], sum_zero ? s4_keep[0] : s4_keep[1]};

  wire          s5_valid;
  wire [WS:0]   s5_keep;
  wire [7:0]    s5_exp;
  wire [27:0]   s5_sum;
  wire [4:0]    s5_lshift;

  pree_fp32_pipe #(.Width(WS + 1 + 8 + 28 + 5), .Regs(seam_regs(5))) u_seam5 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s4_valid),
    .d_i   ({keep_e, s4_exp, s4_sum, lshift}),
    .valid_o (s5_valid), .q_o ({s5_keep, s5_exp, s5_sum, s5_lshift})
  );

  // ---------------------------------------------------------------- E: normalise
  wire        carry       = s5_sum[27];
  wire [26:0] man_left    = s5_sum[26:0] << s5_lshift;
  wire [26:0] norm_man    = carry ? s5_sum[27:1] : man_left;
  wire        norm_sticky = carry & s5_sum[0];
  wire [9:0]  norm_exp    = carry ? ({2'b00, s5_exp} + 10'd1)
                                  : ({2'b00, s5_exp} - {5'd0, s5_lshift});

  wire          s6_valid;
  wire [WS:0]   s6_keep;
  wire [9:0]    s6_exp;
  wire [26:0]   s6_man;
  wire          s6_sticky;

  pree_fp32_pipe #(.Width(WS + 1 + 10 + 27 + 1), .Regs(seam_regs(6))) u_seam6 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s5_valid),
    .d_i   ({s5_keep, norm_exp, norm_man, norm_sticky}),
    .valid_o (s6_valid), .q_o ({s6_keep, s6_exp, s6_man, s6_sticky})
  );

  // ---------------------------------------------------------------- F: round, final mux
  pree_fp32_final #(.Regs(seam_regs(7))) u_final (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s6_valid),
    .special_i (s6_keep[WS]), .special_y_i (s6_keep[WS-1:1]), .sign_i (s6_keep[0]),
    .exp_i (s6_exp), .man_i (s6_man), .sticky_i (s6_sticky),
    .valid_o (valid_o), .y_o (y_o)
  );

endmodule
