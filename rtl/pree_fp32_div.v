// SPDX-License-Identifier: Apache-2.0
// pree_fp32_div: IEEE-754 binary32 divider, round to nearest even, fully pipelined (one new
// division every cycle), Stages pipeline stages (4 by default, the paper's; 31 with
// PipeFast = 1).
//
// y = a / b. Subnormal inputs and outputs in full, signed zeros, overflow to a signed infinity,
// x / 0 -> signed infinity for finite non-zero x. NaN result (x86-64 SSE rule): a NaN -> a
// quieted; else b NaN -> b quieted; else 0 / 0 or inf / inf -> 0xFFC00000.
//
// Parameters:
//   PipeFast  0: the paper's configuration (Stages = 4); 1: the deep configuration for FPGA
//             clock rates (Stages = 31: every seam below registered, one division step per
//             stage). docs/fpga.md.
//   Stages    2 .. 31, the latency of the datapath; overrides PipeFast's choice. Every value
//             gives the same bits.
//   InRegs    0 or 1: registers on the operands before the datapath (seam 0), so that a
//             caller's operand select ends in a register (the PREU with PipeFast = 1).
//             LATENCY = InRegs + Stages.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// Datapath: both significands are normalised, so their quotient lies in (1/2, 2). A restoring
// radix-2 array (pree_fp32_div_steps) produces 26 quotient bits of weights 2^0 .. 2^-25: 24
// significant bits and a guard bit whichever binade the quotient is in; the final remainder
// (non-zero: inexact) and the last bit form the sticky bit. It is cut at 31 seams (items; a
// pree_fp32_pipe after each, a register or a wire):
//   item 1      U1: classify both operands, count the leading zeros of their significands
//                   (pree_fp32_unpack_lz); special results decided here and carried beside the
//                   datapath to the final mux
//   item 2      U2: normalise the significands (pree_fp32_unpack_norm), quotient exponent
//   items 3-28  one division step each (quotient bits 1 .. 26)
//   item 29     N: normalise by one bit, sticky bit, the denormalising shift amount
//                  (pree_fp32_denorm_amt, for both binades, picked by the quotient's top bit)
//   item 30     D: denormalise (pree_fp32_denorm)
//   item 31     R: round (pree_fp32_round, Denorm = 0), final mux with the special result
// Stage plan: stage k (k = 1 .. Stages) ends at item CUT(k), CUT(Stages) = 31.
//   Stages 2 .. 8 (the paper's 4 and the earlier 8 included): the split of the previous
//   versions, unpack in stage 1 and normalise/round in the last stage, quotient bits spread so
//   that each of these weighs about three division steps: stage k < Stages ends with
//   round(32 k / Stages) - 3 bits, CUT(k) = 2 + that: 5 / 8 / 8 / 5 bits for Stages = 4,
//   1 / 4 / 4 / 4 / 4 / 4 / 4 / 1 for Stages = 8.
//   Stages 9 .. 31: the 31 items spread evenly, CUT(k) = round(31 k / Stages): Stages = 12 is
//   U1 U2 +1 bit | 3 bits | 2 | 3 | 2 | 3 | 2 | 3 | 2 | 3 | 2 bits N | D R; Stages = 20 has
//   1 or 2 items per stage; Stages = 31 one item per stage.
`default_nettype none

module pree_fp32_div #(
  parameter PipeFast = 0,
  parameter Stages   = (PipeFast != 0) ? 31 : 4,
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

  localparam MIN_STAGES = 2;
  localparam MAX_STAGES = 31;
  localparam ITEMS      = 31;
  localparam QW         = 26;                    // quotient bits
  localparam STEP0      = 2;                     // items before the first division step

  // The item that ends stage k.
  function integer cut_item;
    input integer k;
    begin
      if (k >= Stages)     cut_item = ITEMS;
      else if (Stages <= 8) cut_item = STEP0 + (k * 32 + Stages / 2) / Stages - 3;
      else                  cut_item = (k * ITEMS + Stages / 2) / Stages;
    end
  endfunction

  // Registers after item s: 1 when some stage ends there.
  function integer seam_regs;
    input integer s;
    integer k;
    begin
      seam_regs = 0;
      for (k = 1; k <= MAX_STAGES; k = k + 1)
        if (k <= Stages && cut_item(k) == s) seam_regs = 1;
    end
  endfunction

  // ---------------------------------------------------------------- entry: seam 0, the check
  // A Stages value outside its range, or PipeFast other than 0 or 1, stops elaboration (Verilator,
  // Icarus, Yosys) with a module named after the problem, however the unit is instantiated.
  generate
    if (Stages < MIN_STAGES || Stages > MAX_STAGES) begin : g_bad_stages
      pree_fp32_div_stages_is_2_to_31 u_fail ();
    end
    if (PipeFast < 0 || PipeFast > 1) begin : g_bad_pipefast
      pree_fp32_div_pipefast_is_0_or_1 u_fail ();
    end
  endgenerate

  // InRegs operand registers before A1 (pree_fp32_entry, which refuses InRegs other than 0, 1).
  wire        valid0;
  wire [31:0] a0, b0;

  pree_fp32_entry #(.InRegs(InRegs), .Width(64)) u_entry (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i), .d_i ({a_i, b_i}),
    .valid_o (valid0), .q_o ({a0, b0})
  );

  // ---------------------------------------------------------------- items 1, 2: unpack
  // Classify both operands, the special result (carried to the end with the sign: WK bits),
  // seam 1, normalise the significands (pree_fp32_unpack).
  localparam WK = 1 + 32 + 1;

  wire          s1_valid;
  wire [WK-1:0] s1_keep;
  wire [9:0]    exp_a, exp_b;
  wire [23:0]   man_a, man_b;

  pree_fp32_unpack #(.Div(1), .Regs(seam_regs(1))) u_unpack (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid0), .a_i (a0), .b_i (b0),
    .valid_o (s1_valid), .keep_o (s1_keep),
    .exp_a_o (exp_a), .man_a_o (man_a), .exp_b_o (exp_b), .man_b_o (man_b)
  );

  wire [9:0] exp_d = exp_a - exp_b + 10'd127;   // biased exponent of quotient bit 2^0

  // The division word: partial remainder, quotient bits, divisor, exponent, carried bits.
  localparam W = 25 + QW + 24 + 10 + WK;

  // word[j] / valid[j]: after j division steps (word[0]: the dividend significand seeds the
  // partial remainder, man_a < 2^24 <= 2 * man_b).
  wire [W-1:0] word  [0:QW] /* verilator split_var */;
  wire         valid [0:QW] /* verilator split_var */;

  pree_fp32_pipe #(.Width(W), .Regs(seam_regs(2))) u_seam2 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s1_valid),
    .d_i   ({1'b0, man_a, {QW{1'b0}}, man_b, exp_d, s1_keep}),
    .valid_o (valid[0]), .q_o (word[0])
  );

  // ---------------------------------------------------------------- items 3 .. 28: the steps
  genvar j;
  generate
    for (j = 1; j <= QW; j = j + 1) begin : g_step
      wire [24:0]   rem_in = word[j-1][W-1 -: 25];
      wire [QW-1:0] quo_in = word[j-1][W-26 -: QW];
      wire [23:0]   den    = word[j-1][W-26-QW -: 24];
      wire [10+WK-1:0] rest = word[j-1][10+WK-1:0];    // exponent and carried bits
      wire [24:0]   rem_out;
      wire [QW-1:0] quo_out;

      pree_fp32_div_steps #(.Steps(1)) u_steps (
        .rem_i (rem_in), .den_i (den), .quo_i (quo_in), .rem_o (rem_out), .quo_o (quo_out)
      );

      pree_fp32_pipe #(.Width(W), .Regs(seam_regs(STEP0 + j))) u_seam (
        .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid[j-1]),
        .d_i   ({rem_out, quo_out, den, rest}),
        .valid_o (valid[j]), .q_o (word[j])
      );
    end
  endgenerate

  // ---------------------------------------------------------------- item 29, N: normalise
  wire [24:0]   rem    = word[QW][W-1 -: 25];
  wire [QW-1:0] quo    = word[QW][W-26 -: QW];
  wire [9:0]    exp_q  = word[QW][10+WK-1 -: 10];
  wire [WK-1:0] keep_q = word[QW][WK-1:0];
  wire [23:0]   den_unused = word[QW][W-26-QW -: 24];    // the divisor: not needed after the steps

  // Quotient in [1, 2): bits 25..2 significant, bit 1 guard; in (1/2, 1): bits 24..1, 0.
  wire        top         = quo[QW-1];
  wire [26:0] norm_man    = top ? {quo[25:1], 2'b00} : {quo[24:0], 2'b00};
  wire        norm_sticky = (rem != 25'd0) | (top & quo[0]);
  wire [9:0]  norm_exp    = exp_q - {9'd0, ~top};

  // The denormalising shift amount: for either binade, picked by the quotient's top bit, when a
  // register follows N; otherwise from the normalised exponent (fewer LUTs).
  localparam BOTH = (seam_regs(STEP0 + QW + 1) != 0);

  wire       norm_tiny;
  wire [4:0] norm_sh;

  pree_fp32_denorm_sel #(.Both(BOTH)) u_amt (
    .top_i (top), .exp_i (norm_exp), .exp_lo_i (exp_q - 10'd1), .exp_hi_i (exp_q),
    .tiny_o (norm_tiny), .sh_o (norm_sh)
  );

  wire          n_valid;
  wire [WK-1:0] n_keep;
  wire [9:0]    n_exp;
  wire [26:0]   n_man;
  wire          n_sticky, n_tiny;
  wire [4:0]    n_sh;

  pree_fp32_pipe #(.Width(WK + 10 + 27 + 1 + 6), .Regs(seam_regs(STEP0 + QW + 1))) u_seam_n (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid[QW]),
    .d_i   ({keep_q, norm_exp, norm_man, norm_sticky, norm_tiny, norm_sh}),
    .valid_o (n_valid), .q_o ({n_keep, n_exp, n_man, n_sticky, n_tiny, n_sh})
  );

  // ---------------------------------------------------------------- items 30, 31, D R: the tail
  pree_fp32_tail #(
    .MaskSticky (BOTH), .RegsDen (seam_regs(STEP0 + QW + 2)), .RegsOut (seam_regs(ITEMS))
  ) u_tail (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (n_valid),
    .keep_i (n_keep), .exp_i (n_exp), .man_i (n_man), .sticky_i (n_sticky),
    .tiny_i (n_tiny), .sh_i (n_sh),
    .valid_o (valid_o), .y_o (y_o)
  );

endmodule
