// pree_preu: one progressive radiance estimation unit (paper 000 Section IV.A, Fig. 6 and 7),
// configurable between hit-point update (mode_i = 0) and radiance evaluation (mode_i = 1),
// built from the binary32 units pree_fp32_{add,mul,sqr,div,cmp}, in one of two datapaths:
//
//   Datapath 0, paper:  the paper's arithmetic. State {n, r2, tau b g r} (160 bits): update
//                       10 stages, radiance 12.
//   Datapath 1, stable: the same estimator, held so that it stays accurate for any photon
//                       count (model/pree/preu_stable.h): state {k, w, T b g r} (320 bits) with an
//                       exact 64-bit count k, w = 1/r2 and T = PI tau / r2 in the 64-bit wide
//                       format (pree_wacc), and kf = binary32(k + 1) (pree_u64_to_f32).
//                       Update 12 stages, radiance 12.
//
// The operation order, the operand order of every unit and the stage of every value are those
// of docs/preu_datapath.md, which model/pree/preu_fp32.c and model/pree/preu_stable.c implement in C;
// the two are bit-exact.
//
// Protocol: one operation may enter every cycle with valid_i (no back-pressure). Its result
// appears with valid_o and its tag exactly UpdLatency cycles later in update mode, 12 in
// radiance mode. Update mode: accept_o says whether the photon is inside the radius; only then
// the caller writes state_o back to the hit point. Radiance mode: lreq_o/lreq_tag_o in stage
// S10 ask for the pixel's running sum, which the caller drives on l_i in the next cycle (S11);
// l_o = l_i + (the hit point's radiance) comes out with valid_o.
// Run-time constants: alpha_i (paper: N + alpha) and kappa_i (stable: fl(fl(1 - alpha) /
// alpha), model/pree/preu_stable.c preu_kappa); change them only while busy_o = 0.
// Mode switch: the units serve different stages in the two modes, so mode_i may change only in
// a cycle where busy_o = 0 (an operation of the new mode may enter in that cycle). With
// PREE_ASSERT defined, a violation stops the simulation; so does a unit whose valid_o is out of
// step with the stage plan.
// Reset: asynchronous, active low; it clears the valid bits only (data registers load on valid).
`default_nettype none

module pree_preu #(
  parameter TagW     = 32,
  parameter Datapath = 0,                        // 0: paper, 1: stable
  parameter StateW   = (Datapath != 0) ? 320 : 160 // do not override: set by Datapath
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
  output wire              lreq_o,      // radiance S10: drive the pixel sum of lreq_tag_o next cycle
  output wire [TagW-1:0]   lreq_tag_o,
  input  wire [95:0]       l_i,         // {b, g, r} pixel running sum, in the cycle after lreq_o
  output wire              valid_o,
  output wire [TagW-1:0]   tag_o,
  output wire              accept_o,    // update: photon inside the radius, write back
  output wire [StateW-1:0] state_o,     // update: the new state, layout as hp_state_i
  output wire [95:0]       l_o,         // radiance: new pixel sum {b, g, r}
  output wire              busy_o       // an operation is in flight; mode_i must hold
);

  localparam        STABLE   = (Datapath != 0);
  localparam [31:0] ONE      = 32'h3F80_0000;  // 1.0f
  localparam [31:0] INV_PI   = 32'h3EA2_F983;  // (float)(1.0 / 3.14159265358979)
  localparam [31:0] PI       = 32'h4049_0FDB;  // (float)3.14159265358979
  localparam        RAD_LAST = 12;             // stage of the radiance result
  localparam        UPD_LAST = STABLE ? 12 : 10; // stage of the update result

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
  // valid_q[k]: an operation is k cycles past its entry. In the paper datapath stages 11 and 12
  // exist only in radiance mode, so an update operation never reaches them.
  reg [RAD_LAST:1] valid_q;
  wire [RAD_LAST:1] valid_d;
  generate
    if (STABLE) begin : g_valid_stable
      assign valid_d = {valid_q[RAD_LAST-1:1], valid_i};
    end else begin : g_valid_paper
      assign valid_d = {valid_q[RAD_LAST-1:UPD_LAST+1], valid_q[UPD_LAST] & rad,
                        valid_q[UPD_LAST-1:1], valid_i};
    end
  endgenerate

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {RAD_LAST{1'b0}};
    else         valid_q <= valid_d;
  end

  // ------------------------------------------------------------------ tag delay line
  // Flat vectors, slot k-1 holds stage k. Each slot loads when its operation moves into it.
  reg [12*TagW-1:0] tag_q;
  integer ts;
  always @(posedge clk_i) begin
    if (valid_i) tag_q[0 +: TagW] <= tag_i;
    for (ts = 1; ts < RAD_LAST; ts = ts + 1)
      if (valid_q[ts]) tag_q[ts*TagW +: TagW] <= tag_q[(ts-1)*TagW +: TagW];
  end

  // ------------------------------------------------------------------ shared units
  // The units both datapaths use, with their operands chosen below per datapath and mode.
  // Their own valid_o bits are only checked against valid_q (under PREE_ASSERT), and the
  // comparator's other flags are not needed: these wires are deliberately left unread.
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
  wire        cmp_le;

  // Operands that differ between the datapaths (assigned in g_paper / g_stable).
  wire [31:0] lo0_b;           // MUL0's b in radiance mode: paper r2, stable PI
  wire [95:0] mid_b_upd;       // MUL3..5's b in update mode: paper INV_PI x3, stable w32 x3
  wire        div_v_upd;       // DIV fed (update mode)
  wire [31:0] div_a_upd, div_b_upd;
  wire [95:0] hi_a;            // MUL6..8's a (both modes, muxed inside the datapath block)
  wire [2:0]  hi_fed;          // MUL6..8 fed
  wire [2:0]  addc_fed;        // ADD0..2 fed
  wire [95:0] addc_a, addc_b;
  wire [31:0] mul9_a;
  wire        mul9_fed;
  wire [31:0] cmp_a, cmp_b;

  // ------------------------------------------------------------------ S1-S2
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s1
      // SUB0..2: d_k = H.pos_k - P.pos_k (update)
      pree_fp32_add u_sub (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
        .a_i(hp_pos_i[32*c +: 32]), .b_i(ph_pos_i[32*c +: 32]), .sub_i(1'b1),
        .valid_o(sub_v[c]), .y_o(d_y[32*c +: 32]));
      // MUL0..2: m_c = H.f_c * P.phi_c (update); MUL0: a = PI * (r2 | PI) (radiance)
      pree_fp32_mul u_mul_lo (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & (upd | (c == 0))),
        .a_i((rad && c == 0) ? PI : hp_f_i[32*c +: 32]),
        .b_i((rad && c == 0) ? lo0_b : ph_phi_i[32*c +: 32]),
        .valid_o(mul_lo_v[c]), .y_o(mul_lo_y[32*c +: 32]));
    end
  endgenerate

  // ------------------------------------------------------------------ S3-S4
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s3
      // SQR0..2: q_k = d_k * d_k (update)
      pree_fp32_sqr u_sqr (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[2] & upd),
        .a_i(d_y[32*c +: 32]), .valid_o(sqr_v[c]), .y_o(q_y[32*c +: 32]));
      // MUL3..5: t_c = m_c * (INV_PI | w32) (update); MUL3: b = a * NE (radiance)
      pree_fp32_mul u_mul_mid (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[2] & (upd | (c == 0))),
        .a_i(mul_lo_y[32*c +: 32]),
        .b_i((rad && c == 0) ? ne_i : mid_b_upd[32*c +: 32]),
        .valid_o(mul_mid_v[c]), .y_o(mul_mid_y[32*c +: 32]));
    end
  endgenerate

  // DIV: paper g = na / n1, stable e = kappa / kf, in S3-S6 (update); k = ONE / b in S5-S8
  // (radiance)
  pree_fp32_div u_div (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(rad ? valid_q[4] : div_v_upd),
    .a_i(rad ? ONE : div_a_upd), .b_i(rad ? mul_mid_y[0 +: 32] : div_b_upd),
    .valid_o(div_v), .y_o(div_y));

  // ------------------------------------------------------------------ S5-S8
  // ADD3: s = q_x + q_y (update, S5-S6); ADD4: d2 = s + q_z (update, S7-S8)
  reg [2*32-1:0] qz_q;    // stages 5..6: q_z waits for s
  always @(posedge clk_i) begin
    if (valid_q[4]) qz_q[0 +: 32] <= q_y[64 +: 32];
    if (valid_q[5]) qz_q[32 +: 32] <= qz_q[0 +: 32];
  end
  pree_fp32_add u_add3 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[4] & upd),
    .a_i(q_y[0 +: 32]), .b_i(q_y[32 +: 32]), .sub_i(1'b0), .valid_o(add3_v), .y_o(s_y));
  pree_fp32_add u_add4 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[6] & upd),
    .a_i(s_y), .b_i(qz_q[32 +: 32]), .sub_i(1'b0), .valid_o(add4_v), .y_o(d2_y));

  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s5
      // ADD0..2: paper u_c = H.tau_c + t_c in S5-S6 (update); L'_c = L_c + c_c in S11-S12
      // (radiance)
      pree_fp32_add u_addc (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(addc_fed[c]),
        .a_i(addc_a[32*c +: 32]), .b_i(addc_b[32*c +: 32]), .sub_i(1'b0),
        .valid_o(addc_v[c]), .y_o(addc_y[32*c +: 32]));
      // MUL6..8: paper tau_n_c = u_c * g in S7-S8, stable MUL6 d2w = d2 * w32 in S9-S10
      // (update); c_c = (tau_c | T32_c) * k in S9-S10 (radiance)
      pree_fp32_mul u_mul_hi (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(hi_fed[c]),
        .a_i(hi_a[32*c +: 32]), .b_i((STABLE && rad == 1'b0) ? wide_f32(w_s8) : div_y),
        .valid_o(mul_hi_v[c]), .y_o(mul_hi_y[32*c +: 32]));
    end
  endgenerate

  // MUL9: paper r2n = H.r2 * g, stable p = w32 * e, in S7-S8 (update)
  pree_fp32_mul u_mul9 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(mul9_fed),
    .a_i(mul9_a), .b_i(div_y), .valid_o(mul9_v), .y_o(mul9_y));

  // CMP: accept = paper d2 <= H.r2 (S9), stable d2w <= ONE (S11); false on NaN.
  pree_fp32_cmp u_cmp (
    .a_i(cmp_a), .b_i(cmp_b), .lt_o(cmp_lt), .le_o(cmp_le), .eq_o(cmp_eq),
    .unordered_o(cmp_unordered));

  // w at stage 8 (stable only; 0 in the paper datapath, where it is not read).
  wire [63:0] w_s8;

  // ------------------------------------------------------------------ the paper datapath
  generate
    if (!STABLE) begin : g_paper
      // State {n, r2, tau}: tau [95:0], r2 [127:96], n [159:128].
      reg [8*96-1:0] tau_q;   // stages 1..8: read in S5 (update, stage-4 value) and S9 (radiance)
      reg [8*32-1:0] r2_q;    // stages 1..8: read by MUL9 (stage 6) and CMP (stage 8)
      reg [6*32-1:0] na_q;    // stages 3..8: N + ALPHA to the output
      integer j;
      /* verilator lint_off UNUSEDSIGNAL */
      wire add5_v, add6_v;
      /* verilator lint_on UNUSEDSIGNAL */
      wire [31:0] na_y, n1_y;

      always @(posedge clk_i) begin
        if (valid_i) begin
          tau_q[0 +: 96] <= hp_state_i[0 +: 96];
          r2_q[0 +: 32]  <= hp_state_i[96 +: 32];
        end
        for (j = 1; j < 8; j = j + 1)
          if (valid_q[j]) begin
            tau_q[j*96 +: 96] <= tau_q[(j-1)*96 +: 96];
            r2_q[j*32 +: 32]  <= r2_q[(j-1)*32 +: 32];
          end
        if (valid_q[2]) na_q[0 +: 32] <= na_y;
        for (j = 1; j < 6; j = j + 1)
          if (valid_q[j+2]) na_q[j*32 +: 32] <= na_q[(j-1)*32 +: 32];
      end

      wire [95:0] tau_s4 = tau_q[3*96 +: 96];
      wire [95:0] tau_s8 = tau_q[7*96 +: 96];

      // ADD5: na = N + alpha; ADD6: n1 = N + ONE (update, S1-S2)
      pree_fp32_add u_add5 (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
        .a_i(hp_state_i[128 +: 32]), .b_i(alpha_i), .sub_i(1'b0), .valid_o(add5_v), .y_o(na_y));
      pree_fp32_add u_add6 (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
        .a_i(hp_state_i[128 +: 32]), .b_i(ONE), .sub_i(1'b0), .valid_o(add6_v), .y_o(n1_y));

      assign lo0_b     = hp_state_i[96 +: 32];
      assign mid_b_upd = {INV_PI, INV_PI, INV_PI};
      assign div_v_upd = valid_q[2];
      assign div_a_upd = na_y;
      assign div_b_upd = n1_y;
      assign addc_fed  = {3{rad ? valid_q[10] : valid_q[4]}};
      assign addc_a    = rad ? l_i : tau_s4;
      assign addc_b    = rad ? mul_hi_y : mul_mid_y;
      assign hi_fed    = {3{rad ? valid_q[8] : valid_q[6]}};
      assign hi_a      = rad ? tau_s8 : addc_y;
      assign mul9_fed  = valid_q[6] & upd;
      assign mul9_a    = r2_q[5*32 +: 32];
      assign cmp_a     = d2_y;
      assign cmp_b     = r2_q[7*32 +: 32];
      assign w_s8      = 64'd0;

      // S9-S10: the comparison and the results, registered in S9, again in S10.
      reg        acc_q9, acc_q10;
      reg [95:0] taun_q9, taun_q10;
      reg [31:0] r2n_q9, r2n_q10, na_q9, na_q10;
      always @(posedge clk_i) begin
        if (valid_q[8]) begin
          acc_q9  <= cmp_le;
          taun_q9 <= mul_hi_y;
          r2n_q9  <= mul9_y;
          na_q9   <= na_q[5*32 +: 32];
        end
        if (valid_q[9]) begin
          acc_q10  <= acc_q9;
          taun_q10 <= taun_q9;
          r2n_q10  <= r2n_q9;
          na_q10   <= na_q9;
        end
      end
      assign accept_o = upd & valid_q[UPD_LAST] & acc_q10;
      assign state_o  = {na_q10, r2n_q10, taun_q10};

      // kappa_i belongs to the stable datapath.
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused_kappa = &{1'b0, kappa_i};
      /* verilator lint_on UNUSEDSIGNAL */
`ifdef PREE_ASSERT
      always @(posedge clk_i) begin
        if (add5_v != (valid_q[2] & upd) || add6_v != (valid_q[2] & upd))
          $fatal(1, "pree_preu: a unit's valid_o is out of step with the stage plan");
      end
`endif
    end
  endgenerate

  // ------------------------------------------------------------------ the stable datapath
  generate
    if (STABLE) begin : g_stable
      // State {k, w, T}: T_c [64c +: 64], w [255:192], k [319:256].
      reg [10*192-1:0] T_q;   // stages 1..10: T32 read in S9 (radiance), T into WACC0..2 in S11
      reg [10*64-1:0]  w_q;   // stages 1..10: w32 read in S3, S7, S9; w into WACC3 in S11
      reg [12*64-1:0]  kn_q;  // stages 1..12: k + 1 to the output
      reg [6*96-1:0]   t_q;   // stages 5..10: t_c = m_c * w32 waits for WACC0..2
      reg [2*32-1:0]   p_q;   // stages 9..10: p = w32 * e waits for WACC3
      reg              acc_q11, acc_q12;
      integer j;
      /* verilator lint_off UNUSEDSIGNAL */
      wire       i2f_v, wacc3_v;
      wire [2:0] wacc_v;
      /* verilator lint_on UNUSEDSIGNAL */
      wire [31:0]  kf_y;
      wire [191:0] Tn_y;
      wire [63:0]  wn_y;
      wire [63:0]  kn = hp_state_i[256 +: 64] + 64'd1;   // the count incrementer (S1)

      always @(posedge clk_i) begin
        if (valid_i) begin
          T_q[0 +: 192] <= hp_state_i[0 +: 192];
          w_q[0 +: 64]  <= hp_state_i[192 +: 64];
          kn_q[0 +: 64] <= kn;
        end
        for (j = 1; j < 10; j = j + 1)
          if (valid_q[j]) begin
            T_q[j*192 +: 192] <= T_q[(j-1)*192 +: 192];
            w_q[j*64 +: 64]   <= w_q[(j-1)*64 +: 64];
          end
        for (j = 1; j < 12; j = j + 1)
          if (valid_q[j]) kn_q[j*64 +: 64] <= kn_q[(j-1)*64 +: 64];
        if (valid_q[4]) t_q[0 +: 96] <= mul_mid_y;
        for (j = 1; j < 6; j = j + 1)
          if (valid_q[j+4]) t_q[j*96 +: 96] <= t_q[(j-1)*96 +: 96];
        if (valid_q[8]) p_q[0 +: 32] <= mul9_y;
        if (valid_q[9]) p_q[32 +: 32] <= p_q[0 +: 32];
        if (valid_q[10]) acc_q11 <= cmp_le;
        if (valid_q[11]) acc_q12 <= acc_q11;
      end

      wire [31:0] w32_s2 = wide_f32(w_q[1*64 +: 64]);
      wire [31:0] w32_s6 = wide_f32(w_q[5*64 +: 64]);
      wire [191:0] T_s8  = T_q[7*192 +: 192];
      wire [191:0] T_s10 = T_q[9*192 +: 192];

      // I2F: kf = binary32(k + 1) (update, S1-S2)
      pree_u64_to_f32 u_i2f (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd), .a_i(kn),
        .valid_o(i2f_v), .y_o(kf_y));

      // WACC0..2: T'_c = T_c + t_c; WACC3: w' = w + p (update, S11-S12)
      genvar g;
      for (g = 0; g < 3; g = g + 1) begin : g_wacc
        pree_wacc u_wacc (
          .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[10] & upd),
          .a_i(T_s10[64*g +: 64]), .t_i(t_q[5*96 + 32*g +: 32]),
          .valid_o(wacc_v[g]), .y_o(Tn_y[64*g +: 64]));
      end
      pree_wacc u_wacc3 (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[10] & upd),
        .a_i(w_q[9*64 +: 64]), .t_i(p_q[32 +: 32]), .valid_o(wacc3_v), .y_o(wn_y));

      assign lo0_b     = PI;
      assign mid_b_upd = {w32_s2, w32_s2, w32_s2};
      assign div_v_upd = valid_q[2];
      assign div_a_upd = kappa_i;
      assign div_b_upd = kf_y;
      assign addc_fed  = {3{rad & valid_q[10]}};
      assign addc_a    = l_i;
      assign addc_b    = mul_hi_y;
      assign hi_fed    = {rad & valid_q[8], rad & valid_q[8], valid_q[8]};
      assign hi_a      = rad ? {wide_f32(T_s8[128 +: 64]), wide_f32(T_s8[64 +: 64]), wide_f32(T_s8[0 +: 64])}
                             : {64'd0, d2_y};
      assign mul9_fed  = valid_q[6] & upd;
      assign mul9_a    = w32_s6;
      assign cmp_a     = mul_hi_y[0 +: 32];
      assign cmp_b     = ONE;
      assign w_s8      = w_q[7*64 +: 64];

      assign accept_o = upd & valid_q[UPD_LAST] & acc_q12;
      assign state_o  = {kn_q[11*64 +: 64], wn_y, Tn_y};

      // alpha_i belongs to the paper datapath (the stable one takes kappa_i).
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused_alpha = &{1'b0, alpha_i};
      /* verilator lint_on UNUSEDSIGNAL */

`ifdef PREE_ASSERT
      always @(posedge clk_i) begin
        if (i2f_v != (valid_q[2] & upd) || wacc_v != {3{valid_q[12] & upd}} ||
            wacc3_v != (valid_q[12] & upd))
          $fatal(1, "pree_preu: a stable-datapath unit's valid_o is out of step with the stage plan");
      end
`endif
    end
  endgenerate

  // ------------------------------------------------------------------ outputs
  assign lreq_o     = rad & valid_q[9];
  assign lreq_tag_o = tag_q[8*TagW +: TagW];
  assign valid_o    = rad ? valid_q[RAD_LAST] : valid_q[UPD_LAST];
  assign tag_o      = rad ? tag_q[(RAD_LAST-1)*TagW +: TagW] : tag_q[(UPD_LAST-1)*TagW +: TagW];
  assign l_o        = addc_y;
  assign busy_o     = rad ? (|valid_q) : (|valid_q[UPD_LAST:1]);

`ifdef PREE_ASSERT
  // Checks of the protocol and of the stage plan; simulation only.
  reg mode_q;
  wire busy_old = mode_q ? (|valid_q) : (|valid_q[UPD_LAST:1]);
  wire [2:0] hi_v_want = STABLE ? {rad & valid_q[10], rad & valid_q[10], valid_q[10]}
                                : {3{rad ? valid_q[10] : valid_q[8]}};
  wire [2:0] addc_v_want = STABLE ? {3{rad & valid_q[12]}} : {3{rad ? valid_q[12] : valid_q[6]}};
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      mode_q <= 1'b0;
    end else begin
      mode_q <= mode_i;
      if (mode_i != mode_q && busy_old)
        $fatal(1, "pree_preu: mode_i changed while operations were in flight (valid_q=%b)", valid_q);
      if (sub_v != {3{valid_q[2] & upd}} ||
          mul_lo_v != {valid_q[2] & upd, valid_q[2] & upd, valid_q[2]} ||
          sqr_v != {3{valid_q[4] & upd}} ||
          mul_mid_v != {valid_q[4] & upd, valid_q[4] & upd, valid_q[4]} ||
          div_v != (rad ? valid_q[8] : valid_q[6]) ||
          add3_v != (valid_q[6] & upd) ||
          addc_v != addc_v_want || mul_hi_v != hi_v_want ||
          add4_v != (valid_q[8] & upd) || mul9_v != (valid_q[8] & upd))
        $fatal(1, "pree_preu: a unit's valid_o is out of step with the stage plan");
    end
  end
`endif

endmodule
