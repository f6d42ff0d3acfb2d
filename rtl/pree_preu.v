// SPDX-License-Identifier: Apache-2.0
// pree_preu: one progressive radiance estimation unit (paper 000 Section IV.A, Fig. 6 and 7),
// configurable between hit-point update (mode_i = 0) and radiance evaluation (mode_i = 1),
// built from the binary32 units pree_fp32_{add,mul,sqr,div,cmp}, in one of two datapaths:
//
//   Datapath 0, paper:  the paper's arithmetic. State {n, r2, tau b g r} (160 bits).
//   Datapath 1, stable: the same estimator, held so that it stays accurate for any photon
//                       count (model/pree/preu_stable.h): state {k, w, T b g r} (320 bits) with an
//                       exact 64-bit count k, w = 1/r2 and T = PI tau / r2 in the 64-bit wide
//                       format (pree_wacc), and kf = binary32(k + 1) (pree_u64_to_f32).
//
// Stage plan: derived from the units' latencies (rtl/pree_preu_plan.vh, also read by pree_top):
// every unit is fed in the stage where its operands are ready, and the values an operation
// carries (its tag, its state, results that wait for a later unit) ride in one indexed stage
// array, st_q, loaded stage by stage on the valid bits.
//   PipeFast 0 (the paper's units): update 10 stages (paper) / 12 (stable), radiance 12.
//   PipeFast 1 (the units' deep plans and an operand register in front of each unit,
//   docs/fpga.md): update 48 / 52, radiance 64.
// Each unit's Stages may be overridden (AddStages .. WaccStages); the plan follows.
// Operation order, operand order and values: docs/preu_datapath.md, which model/pree/preu_fp32.c
// and preu_stable.c implement in C, bit-exact with this RTL whatever the stage plan.
//
// Protocol: one operation may enter every cycle with valid_i (no back-pressure). Its result
// appears with valid_o and its tag exactly UPD_LATENCY cycles later in update mode, RAD_LATENCY
// in radiance mode. Update mode: accept_o says whether the photon is inside the radius; only
// then the caller writes state_o back to the hit point. Radiance mode: lreq_o/lreq_tag_o in stage
// LREQ_STAGE = RAD_LATENCY - (the add's latency) - 1 ask for the pixel's running sum, which the
// caller drives on l_i in the next cycle; l_o = l_i + (its radiance) comes with valid_o.
// Run-time constants: alpha_i (paper: N + alpha) and kappa_i (stable: fl(fl(1 - alpha) /
// alpha), model/pree/preu_stable.c preu_kappa); change them only while busy_o = 0.
// Mode switch: the units serve different stages in the two modes, so mode_i may change only in
// a cycle where busy_o = 0 (an operation of the new mode may enter in that cycle). With
// PREE_ASSERT defined, a violation stops the simulation; so does a unit whose valid_o is out of
// step with the stage plan (which also checks each unit's latency against the plan).
// Reset: asynchronous, active low; it clears the valid bits only (data registers load on valid).
`default_nettype none

module pree_preu #(
  parameter TagW       = 32,
  parameter Datapath   = 0,                          // 0: paper, 1: stable
  parameter PipeFast   = 0,                          // 0: the paper's units, 1: the deep plans
  parameter AddStages  = 0,  // each unit kind's Stages; 0: the unit's default for PipeFast
  parameter MulStages  = 0,
  parameter SqrStages  = 0,
  parameter DivStages  = 0,
  parameter U2fStages  = 0,
  parameter WaccStages = 0,
  parameter StateW     = (Datapath != 0) ? 320 : 160 // do not override: set by Datapath
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              mode_i,      // 0: hit-point update, 1: radiance evaluation
  input  wire              valid_i,
  input  wire [TagW-1:0]   tag_i,
  input  wire [95:0]       hp_pos_i,    // {z, y, x}
  input  wire [95:0]       hp_f_i,      // {b, g, r} weight
  input  wire [StateW-1:0] hp_state_i,  // paper {n, r2, tau b g r}; stable {k, w, T b g r}
  input  wire [95:0]       ph_pos_i,    // {z, y, x}
  input  wire [95:0]       ph_phi_i,    // {b, g, r}
  input  wire [31:0]       alpha_i,     // paper: alpha (binary32)
  input  wire [31:0]       kappa_i,     // stable: (1 - alpha) / alpha (binary32)
  input  wire [31:0]       ne_i,        // N_emitted as binary32 (radiance mode)
  output wire              lreq_o,      // radiance: drive the pixel sum of lreq_tag_o next cycle
  output wire [TagW-1:0]   lreq_tag_o,
  input  wire [95:0]       l_i,         // {b, g, r} pixel running sum, in the cycle after lreq_o
  output wire              valid_o,
  output wire [TagW-1:0]   tag_o,
  output wire              accept_o,    // update: photon inside the radius, write back
  output wire [StateW-1:0] state_o,     // update: the new state, layout as hp_state_i
  output wire [95:0]       l_o,         // radiance: new pixel sum {b, g, r}
  output wire              busy_o       // an operation is in flight; mode_i must hold
);

`include "pree_preu_lat.vh"

  localparam        STABLE = (Datapath != 0);
  localparam [31:0] ONE    = 32'h3F80_0000;  // 1.0f
  localparam [31:0] INV_PI = 32'h3EA2_F983;  // (float)(1.0 / 3.14159265358979)
  localparam [31:0] PI     = 32'h4049_0FDB;  // (float)3.14159265358979
  // Each unit's latency (pree_preu_lat.vh) by the plan's letters: its operand registers (IR) and
  // its Stages (the unit's, below: A - IR ..). UPD_LATENCY and RAD_LATENCY come from there too.
  localparam IR = preu_in_regs(PipeFast);
  localparam A = LAT_ADD, M = LAT_MUL, Q = LAT_SQR, D = LAT_DIV, U = LAT_U2F, W = LAT_WACC;
  // The pixel-sum request stage, public to the Verilator benches.
  localparam LREQ_STAGE  /*verilator public*/ = RAD_LATENCY - A - 1;
  localparam LAST = preu_max(UPD_LATENCY, RAD_LATENCY);
  // Stages in which units are fed (update: S_*, radiance: R_*); CMP_S: the comparison.
  localparam S_SQR  = A;                    // SQR0..2, d ready
  localparam S_ADD3 = A + Q;                // q ready
  localparam S_ADD4 = 2 * A + Q;
  localparam S_D2   = 3 * A + Q;            // d2 ready
  localparam S_DIV  = STABLE ? U : A;
  localparam S_MUL9 = S_DIV + D;            // g / e ready
  localparam S_HI   = STABLE ? S_D2 : preu_taun_feed(A, M, D);
  localparam CMP_S  = preu_cmp_stage(Datapath, A, M, Q);
  localparam S_WACC = UPD_LATENCY - W;
  localparam R_DIV  = 2 * M;
  localparam R_HI   = 2 * M + D;
  localparam R_ADD  = LREQ_STAGE + 1;      // l_i arrives

  // The stage array's word: fields carried by an operation (F_*: offset). Common fields, then
  // the datapath's own (the paper's and the stable one's share the offsets from F_DP).
  localparam F_TAG = 0, F_QZ = TagW, F_ACC = TagW + 32, F_DP = TagW + 33;
  localparam F_TAU = F_DP, F_R2 = F_DP + 96, F_NA = F_DP + 128, F_U = F_DP + 160,
             F_G = F_DP + 256, F_TAUN = F_DP + 288, F_R2N = F_DP + 384;      // paper, 416 bits
  localparam F_T = F_DP, F_W = F_DP + 192, F_KN = F_DP + 256, F_TT = F_DP + 320,
             F_P = F_DP + 416;                                               // stable, 448 bits
  localparam CW = F_DP + (STABLE ? 448 : 416);

  generate
    if (StateW != (STABLE ? 320 : 160)) begin : g_bad_statew
      pree_preu_statew_is_set_by_datapath u_fail ();
    end
  endgenerate

  // The binary32 view of a wide word (model/pree/wide_acc.h wide_f32): truncation, a bit slice.
  /* verilator lint_off UNUSEDSIGNAL */
  function [31:0] wide_f32;
    input [63:0] a;       // the leading bit and the low 32 significand bits are dropped
    begin
      wide_f32 = {1'b0, a[63:56], a[54:32]};
    end
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  wire upd = ~mode_i;
  wire rad = mode_i;

  // ------------------------------------------------------------------ stage valid bits
  // vs[k]: an operation is k cycles past its entry (vs[0] = valid_i). An operation of the mode
  // with the shorter latency stops at its last stage.
  reg  [LAST:1] valid_q;
  wire [LAST:0] vs = {valid_q, valid_i};
  reg  [LAST:1] valid_d;
  always @* begin : valid_next
    integer k;
    for (k = 1; k <= LAST; k = k + 1)
      valid_d[k] = vs[k-1] & ((k - 1 != UPD_LATENCY) | rad) & ((k - 1 != RAD_LATENCY) | upd);
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {LAST{1'b0}};
    else         valid_q <= valid_d;
  end

  // ------------------------------------------------------------------ the stage array
  // st_q[k*CW +: CW]: the word in stage k (k = 1 .. LAST), loaded from stage k-1's view when
  // vs[k-1] is set. st_v[k*CW +: CW], the view of stage k: st_q's word with the values that units
  // deliver in stage k put in (st_v[0 +: CW]: the entry word). Readers take the view; fields
  // nobody reads past a stage are removed by synthesis. The accept bit enters the register
  // after the comparison (the comparator is combinational).
  reg  [(LAST+1)*CW-1:CW] st_q;
  wire [(LAST+1)*CW-1:0]  st_v;
  wire                    cmp_le;
  always @(posedge clk_i) begin : stage_array
    integer k;
    for (k = 1; k <= LAST; k = k + 1)
      if (vs[k-1]) st_q[k*CW +: CW] <= st_v[(k-1)*CW +: CW];
    if (vs[CMP_S]) st_q[(CMP_S+1)*CW + F_ACC] <= cmp_le;
  end

  // ------------------------------------------------------------------ shared units
  // The units both datapaths use, with their operands chosen below per datapath and mode.
  // Their own valid_o bits are only checked against the stage valid bits (under PREE_ASSERT),
  // and the comparator's other flags are not needed: these wires are deliberately left unread.
  /* verilator lint_off UNUSEDSIGNAL */
  wire [2:0]  sub_v, mul_lo_v, mul_mid_v, mul_hi_v, sqr_v, addc_v;
  wire        mul9_v, add3_v, add4_v, div_v;
  wire        cmp_lt, cmp_eq, cmp_unordered;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [95:0] d_y;        // SUB0..2:  d_k
  wire [95:0] mul_lo_y;   // MUL0..2:  m_c (update), MUL0 = a (radiance)
  wire [95:0] mul_mid_y;  // MUL3..5:  t_c (update), MUL3 = b (radiance)
  wire [95:0] mul_hi_y;   // MUL6..8:  paper tau_n_c / stable MUL6 d2w (update); c_c (radiance)
  wire [95:0] q_y;        // SQR0..2:  q_k
  wire [95:0] addc_y;     // ADD0..2:  paper u_c (update); L'_c (radiance)
  wire [31:0] mul9_y;     // MUL9:     paper r2n, stable p
  wire [31:0] s_y;        // ADD3
  wire [31:0] d2_y;       // ADD4
  wire [31:0] div_y;      // DIV:      paper g, stable e (update); k (radiance)

  // Operands that differ between the datapaths (assigned in g_paper / g_stable).
  wire [31:0] lo0_b;           // MUL0's b in radiance mode: paper r2, stable PI
  wire [95:0] mid_b_upd;       // MUL3..5's b in update mode: paper INV_PI x3, stable w32 x3
  wire [31:0] div_a_upd, div_b_upd;
  wire [95:0] hi_a;            // MUL6..8's a (both modes, muxed inside the datapath block)
  wire [31:0] hi_b_upd;        // MUL6..8's b in update mode
  wire [2:0]  hi_fed;          // MUL6..8 fed
  wire [2:0]  addc_fed;        // ADD0..2 fed
  wire [95:0] addc_a, addc_b;
  wire [31:0] mul9_a;
  wire [31:0] cmp_a, cmp_b;

  // The common fields' views: the tag, q_z (waits for s) and the accept bit.
  assign st_v[F_TAG +: TagW] = tag_i;
  assign st_v[F_QZ +: 33]    = 33'd0;
  genvar c, gs;
  generate
    for (gs = 1; gs <= LAST; gs = gs + 1) begin : g_view
      localparam B = gs * CW;
      assign st_v[B + F_TAG +: TagW] = st_q[B + F_TAG +: TagW];
      assign st_v[B + F_QZ +: 32]    = (gs == S_ADD3) ? q_y[64 +: 32] : st_q[B + F_QZ +: 32];
      assign st_v[B + F_ACC]         = st_q[B + F_ACC];
    end
  endgenerate

  // SUB0..2 and MUL0..2 in stage 0; SQR0..2 and MUL3..5 when d and m are ready.
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s1
      // SUB0..2: d_k = H.pos_k - P.pos_k (update)
      pree_fp32_add #(.Stages(A - IR), .InRegs(IR)) u_sub (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
        .a_i(hp_pos_i[32*c +: 32]), .b_i(ph_pos_i[32*c +: 32]), .sub_i(1'b1),
        .valid_o(sub_v[c]), .y_o(d_y[32*c +: 32]));
      // MUL0..2: m_c = H.f_c * P.phi_c (update); MUL0: a = PI * (r2 | PI) (radiance)
      pree_fp32_mul #(.Stages(M - IR), .InRegs(IR)) u_mul_lo (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & (upd | (c == 0))),
        .a_i((rad && c == 0) ? PI : hp_f_i[32*c +: 32]),
        .b_i((rad && c == 0) ? lo0_b : ph_phi_i[32*c +: 32]),
        .valid_o(mul_lo_v[c]), .y_o(mul_lo_y[32*c +: 32]));
      // SQR0..2: q_k = d_k * d_k (update)
      pree_fp32_sqr #(.Stages(Q - IR), .InRegs(IR)) u_sqr (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(vs[S_SQR] & upd),
        .a_i(d_y[32*c +: 32]), .valid_o(sqr_v[c]), .y_o(q_y[32*c +: 32]));
      // MUL3..5: t_c = m_c * (INV_PI | w32) (update); MUL3: b = a * NE (radiance)
      pree_fp32_mul #(.Stages(M - IR), .InRegs(IR)) u_mul_mid (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(vs[M] & (upd | (c == 0))),
        .a_i(mul_lo_y[32*c +: 32]),
        .b_i((rad && c == 0) ? ne_i : mid_b_upd[32*c +: 32]),
        .valid_o(mul_mid_v[c]), .y_o(mul_mid_y[32*c +: 32]));
    end
  endgenerate

  // DIV: paper g = na / n1, stable e = kappa / kf (update); k = ONE / b (radiance)
  pree_fp32_div #(.Stages(D - IR), .InRegs(IR)) u_div (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(rad ? vs[R_DIV] : vs[S_DIV]),
    .a_i(rad ? ONE : div_a_upd), .b_i(rad ? mul_mid_y[0 +: 32] : div_b_upd),
    .valid_o(div_v), .y_o(div_y));

  // ADD3: s = q_x + q_y; ADD4: d2 = s + q_z (update)
  pree_fp32_add #(.Stages(A - IR), .InRegs(IR)) u_add3 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(vs[S_ADD3] & upd),
    .a_i(q_y[0 +: 32]), .b_i(q_y[32 +: 32]), .sub_i(1'b0), .valid_o(add3_v), .y_o(s_y));
  pree_fp32_add #(.Stages(A - IR), .InRegs(IR)) u_add4 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(vs[S_ADD4] & upd),
    .a_i(s_y), .b_i(st_v[S_ADD4*CW + F_QZ +: 32]), .sub_i(1'b0), .valid_o(add4_v), .y_o(d2_y));

  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s5
      // ADD0..2: paper u_c = H.tau_c + t_c (update); L'_c = L_c + c_c (radiance)
      pree_fp32_add #(.Stages(A - IR), .InRegs(IR)) u_addc (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(addc_fed[c]),
        .a_i(addc_a[32*c +: 32]), .b_i(addc_b[32*c +: 32]), .sub_i(1'b0),
        .valid_o(addc_v[c]), .y_o(addc_y[32*c +: 32]));
      // MUL6..8: paper tau_n_c = u_c * g, stable MUL6 d2w = d2 * w32 (update);
      // c_c = (tau_c | T32_c) * k (radiance)
      pree_fp32_mul #(.Stages(M - IR), .InRegs(IR)) u_mul_hi (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(hi_fed[c]),
        .a_i(hi_a[32*c +: 32]), .b_i(rad ? div_y : hi_b_upd),
        .valid_o(mul_hi_v[c]), .y_o(mul_hi_y[32*c +: 32]));
    end
  endgenerate

  // MUL9: paper r2n = H.r2 * g, stable p = w32 * e (update)
  pree_fp32_mul #(.Stages(M - IR), .InRegs(IR)) u_mul9 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(vs[S_MUL9] & upd),
    .a_i(mul9_a), .b_i(div_y), .valid_o(mul9_v), .y_o(mul9_y));

  // CMP: accept = paper d2 <= H.r2, stable d2w <= ONE; false on NaN.
  pree_fp32_cmp u_cmp (
    .a_i(cmp_a), .b_i(cmp_b), .lt_o(cmp_lt), .le_o(cmp_le), .eq_o(cmp_eq),
    .unordered_o(cmp_unordered));

  // ------------------------------------------------------------------ the paper datapath
  generate
    if (!STABLE) begin : g_paper
      // State {n, r2, tau}: tau [95:0], r2 [127:96], n [159:128]. Fields: tau and r2 from the
      // entry; na (N + alpha) to the output; u waits for g, g for u (whichever is later);
      // tau' and r2' wait for the result stage.
      localparam S_U = 2 * M + A, S_TAUN = S_HI + M, S_R2N = S_MUL9 + M;
      /* verilator lint_off UNUSEDSIGNAL */
      wire add5_v, add6_v;
      /* verilator lint_on UNUSEDSIGNAL */
      wire [31:0] na_y, n1_y;

      // ADD5: na = N + alpha; ADD6: n1 = N + ONE (update, stage 0)
      pree_fp32_add #(.Stages(A - IR), .InRegs(IR)) u_add5 (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
        .a_i(hp_state_i[128 +: 32]), .b_i(alpha_i), .sub_i(1'b0), .valid_o(add5_v), .y_o(na_y));
      pree_fp32_add #(.Stages(A - IR), .InRegs(IR)) u_add6 (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
        .a_i(hp_state_i[128 +: 32]), .b_i(ONE), .sub_i(1'b0), .valid_o(add6_v), .y_o(n1_y));

      assign st_v[F_TAU +: 128]    = hp_state_i[0 +: 128];       // tau, r2
      assign st_v[F_NA +: 288]     = 288'd0;
      for (gs = 1; gs <= LAST; gs = gs + 1) begin : g_view_paper
        localparam B = gs * CW;
        assign st_v[B + F_TAU +: 128] = st_q[B + F_TAU +: 128];
        assign st_v[B + F_NA +: 32]   = (gs == A)      ? na_y     : st_q[B + F_NA +: 32];
        assign st_v[B + F_U +: 96]    = (gs == S_U)    ? addc_y   : st_q[B + F_U +: 96];
        assign st_v[B + F_G +: 32]    = (gs == S_MUL9) ? div_y    : st_q[B + F_G +: 32];
        assign st_v[B + F_TAUN +: 96] = (gs == S_TAUN) ? mul_hi_y : st_q[B + F_TAUN +: 96];
        assign st_v[B + F_R2N +: 32]  = (gs == S_R2N)  ? mul9_y   : st_q[B + F_R2N +: 32];
      end

      assign lo0_b     = hp_state_i[96 +: 32];
      assign mid_b_upd = {INV_PI, INV_PI, INV_PI};
      assign div_a_upd = na_y;
      assign div_b_upd = n1_y;
      assign addc_fed  = {3{rad ? vs[R_ADD] : vs[2*M]}};
      assign addc_a    = rad ? l_i : st_v[2*M*CW + F_TAU +: 96];
      assign addc_b    = rad ? mul_hi_y : mul_mid_y;
      assign hi_fed    = {3{rad ? vs[R_HI] : vs[S_HI]}};
      assign hi_a      = rad ? st_v[R_HI*CW + F_TAU +: 96] : st_v[S_HI*CW + F_U +: 96];
      assign hi_b_upd  = st_v[S_HI*CW + F_G +: 32];
      assign mul9_a    = st_v[S_MUL9*CW + F_R2 +: 32];
      assign cmp_a     = d2_y;
      assign cmp_b     = st_v[CMP_S*CW + F_R2 +: 32];
      assign state_o   = {st_v[UPD_LATENCY*CW + F_NA +: 32], st_v[UPD_LATENCY*CW + F_R2N +: 32],
                          st_v[UPD_LATENCY*CW + F_TAUN +: 96]};

      // kappa_i belongs to the stable datapath.
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused_kappa = &{1'b0, kappa_i};
      /* verilator lint_on UNUSEDSIGNAL */
`ifdef PREE_ASSERT
      always @(posedge clk_i) begin
        if (add5_v != (vs[A] & upd) || add6_v != (vs[A] & upd))
          $fatal(1, "pree_preu: a unit's valid_o is out of step with the stage plan");
      end
`endif
    end
  endgenerate

  // ------------------------------------------------------------------ the stable datapath
  generate
    if (STABLE) begin : g_stable
      // State {k, w, T}: T_c [64c +: 64], w [255:192], k [319:256]. Fields: T, w and k + 1
      // from the entry; t_c = m_c * w32 and p = w32 * e wait for the wide accumulators, which
      // end in the result stage.
      localparam S_TT = 2 * M, S_P = S_MUL9 + M;
      /* verilator lint_off UNUSEDSIGNAL */
      wire       i2f_v, wacc3_v;
      wire [2:0] wacc_v;
      /* verilator lint_on UNUSEDSIGNAL */
      wire [31:0]  kf_y;
      wire [191:0] Tn_y;
      wire [63:0]  wn_y;
      wire [63:0]  kn = hp_state_i[256 +: 64] + 64'd1;   // the count incrementer (stage 0)
      wire [191:0] T_r = st_v[R_HI*CW + F_T +: 192];
      localparam BW = S_WACC * CW;                      // the accumulators' stage

      // I2F: kf = binary32(k + 1) (update, stage 0)
      pree_u64_to_f32 #(.Stages(U - IR), .InRegs(IR)) u_i2f (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd), .a_i(kn),
        .valid_o(i2f_v), .y_o(kf_y));

      assign st_v[F_T +: 256]  = hp_state_i[0 +: 256];      // T, w
      assign st_v[F_KN +: 64]  = kn;
      assign st_v[F_TT +: 128] = 128'd0;
      for (gs = 1; gs <= LAST; gs = gs + 1) begin : g_view_stable
        localparam B = gs * CW;
        assign st_v[B + F_T +: 320] = st_q[B + F_T +: 320];  // T, w, k + 1
        assign st_v[B + F_TT +: 96] = (gs == S_TT) ? mul_mid_y : st_q[B + F_TT +: 96];
        assign st_v[B + F_P +: 32]  = (gs == S_P)  ? mul9_y    : st_q[B + F_P +: 32];
      end

      // WACC0..2: T'_c = T_c + t_c; WACC3: w' = w + p (update)
      genvar g;
      for (g = 0; g < 3; g = g + 1) begin : g_wacc
        pree_wacc #(.Stages(W - IR), .InRegs(IR)) u_wacc (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(vs[S_WACC] & upd),
          .a_i(st_v[BW + F_T + 64*g +: 64]), .t_i(st_v[BW + F_TT + 32*g +: 32]),
          .valid_o(wacc_v[g]), .y_o(Tn_y[64*g +: 64]));
      end
      pree_wacc #(.Stages(W - IR), .InRegs(IR)) u_wacc3 (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(vs[S_WACC] & upd),
        .a_i(st_v[BW + F_W +: 64]), .t_i(st_v[BW + F_P +: 32]), .valid_o(wacc3_v), .y_o(wn_y));

      assign lo0_b     = PI;
      assign mid_b_upd = {3{wide_f32(st_v[M*CW + F_W +: 64])}};
      assign div_a_upd = kappa_i;
      assign div_b_upd = kf_y;
      assign addc_fed  = {3{rad & vs[R_ADD]}};
      assign addc_a    = l_i;
      assign addc_b    = mul_hi_y;
      assign hi_fed    = {rad & vs[R_HI], rad & vs[R_HI], rad ? vs[R_HI] : vs[S_HI]};
      assign hi_a      = rad ? {wide_f32(T_r[128 +: 64]), wide_f32(T_r[64 +: 64]), wide_f32(T_r[0 +: 64])}
                             : {64'd0, d2_y};
      assign hi_b_upd  = wide_f32(st_v[S_HI*CW + F_W +: 64]);
      assign mul9_a    = wide_f32(st_v[S_MUL9*CW + F_W +: 64]);
      assign cmp_a     = mul_hi_y[0 +: 32];
      assign cmp_b     = ONE;
      assign state_o   = {st_v[UPD_LATENCY*CW + F_KN +: 64], wn_y, Tn_y};

      // alpha_i belongs to the paper datapath (the stable one takes kappa_i).
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused_alpha = &{1'b0, alpha_i};
      /* verilator lint_on UNUSEDSIGNAL */

`ifdef PREE_ASSERT
      always @(posedge clk_i) begin
        if (i2f_v != (vs[U] & upd) || wacc_v != {3{vs[UPD_LATENCY] & upd}} ||
            wacc3_v != (vs[UPD_LATENCY] & upd))
          $fatal(1, "pree_preu: a stable-datapath unit's valid_o is out of step with the stage plan");
      end
`endif
    end
  endgenerate

  // ------------------------------------------------------------------ outputs
  assign accept_o   = upd & vs[UPD_LATENCY] & st_q[UPD_LATENCY*CW + F_ACC];
  assign lreq_o     = rad & vs[R_ADD-1];
  assign lreq_tag_o = st_v[(R_ADD-1)*CW + F_TAG +: TagW];
  assign valid_o    = rad ? vs[RAD_LATENCY] : vs[UPD_LATENCY];
  assign tag_o      = rad ? st_v[RAD_LATENCY*CW + F_TAG +: TagW] : st_v[UPD_LATENCY*CW + F_TAG +: TagW];
  assign l_o        = addc_y;
  assign busy_o     = rad ? (|valid_q[RAD_LATENCY:1]) : (|valid_q[UPD_LATENCY:1]);

`ifdef PREE_ASSERT
  // Checks of the protocol and of the stage plan (each unit's valid_o must come LATENCY cycles
  // after the stage that fed it); simulation only.
  reg mode_q;
  wire busy_old = mode_q ? (|valid_q[RAD_LATENCY:1]) : (|valid_q[UPD_LATENCY:1]);
  wire [2:0] hi_v_want = STABLE ? {rad & vs[R_HI+M], rad & vs[R_HI+M], rad ? vs[R_HI+M] : vs[S_HI+M]}
                                : {3{rad ? vs[R_HI+M] : vs[S_HI+M]}};
  wire [2:0] addc_v_want = STABLE ? {3{rad & vs[RAD_LATENCY]}}
                                  : {3{rad ? vs[RAD_LATENCY] : vs[2*M+A]}};
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      mode_q <= 1'b0;
    end else begin
      mode_q <= mode_i;
      if (mode_i != mode_q && busy_old)
        $fatal(1, "pree_preu: mode_i changed while operations were in flight (valid_q=%b)", valid_q);
      if (sub_v != {3{vs[A] & upd}} ||
          mul_lo_v != {vs[M] & upd, vs[M] & upd, vs[M]} ||
          sqr_v != {3{vs[S_ADD3] & upd}} ||
          mul_mid_v != {vs[2*M] & upd, vs[2*M] & upd, vs[2*M]} ||
          div_v != (rad ? vs[R_HI] : vs[S_MUL9]) ||
          add3_v != (vs[S_ADD4] & upd) ||
          addc_v != addc_v_want || mul_hi_v != hi_v_want ||
          add4_v != (vs[S_D2] & upd) || mul9_v != (vs[S_MUL9+M] & upd))
        $fatal(1, "pree_preu: a unit's valid_o is out of step with the stage plan");
    end
  end
`endif

endmodule
