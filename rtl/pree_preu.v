// pree_preu: one progressive radiance estimation unit (paper 000 Section IV.A, Fig. 6 and 7),
// configurable between hit-point update (mode_i = 0, 10 stages) and radiance evaluation
// (mode_i = 1, 12 stages), built from the binary32 units pree_fp32_{add,mul,sqr,div,cmp}.
//
// The operation order, the operand order of every unit and the stage of every value are those
// of docs/preu_datapath.md, which model/preu_fp32.c implements in C; the two are bit-exact.
//
// Protocol: one operation may enter every cycle with valid_i (no back-pressure). Its result
// appears with valid_o and its tag exactly 10 cycles later in update mode, 12 in radiance mode.
// Update mode: accept_o says whether the photon is inside the radius; only then the caller
// writes tau_o, r2_o, n_o back to the hit point. Radiance mode: lreq_o/lreq_tag_o in stage S10
// ask for the pixel's running sum, which the caller drives on l_i in the next cycle (S11);
// l_o = l_i + tau * (1 / ((PI * r2) * NE)) comes out with valid_o.
// Mode switch: the units serve different stages in the two modes, so mode_i may change only in
// a cycle where busy_o = 0 (an operation of the new mode may enter in that cycle). With
// PREE_ASSERT defined, a violation stops the simulation; so does a unit whose latency differs
// from the one the stage plan assumes (add/mul/sqr 2, div 4).
// Reset: asynchronous, active low; it clears the valid bits only (data registers load on valid).
`default_nettype none

module pree_preu #(
  parameter TagW = 32
) (
  input  wire            clk_i,
  input  wire            rst_ni,
  input  wire            mode_i,      // 0: hit-point update, 1: radiance evaluation
  input  wire            valid_i,
  input  wire [TagW-1:0] tag_i,
  input  wire [95:0]     hp_pos_i,    // {z, y, x}
  input  wire [95:0]     hp_f_i,      // {b, g, r} weight
  input  wire [95:0]     hp_tau_i,    // {b, g, r} accumulated flux
  input  wire [31:0]     hp_r2_i,
  input  wire [31:0]     hp_n_i,
  input  wire [95:0]     ph_pos_i,    // {z, y, x}
  input  wire [95:0]     ph_phi_i,    // {b, g, r}
  input  wire [31:0]     ne_i,        // N_emitted as binary32 (radiance mode)
  output wire            lreq_o,      // radiance S10: drive the pixel sum of lreq_tag_o next cycle
  output wire [TagW-1:0] lreq_tag_o,
  input  wire [95:0]     l_i,         // {b, g, r} pixel running sum, in the cycle after lreq_o
  output wire            valid_o,
  output wire [TagW-1:0] tag_o,
  output wire            accept_o,    // update: photon inside the radius, write back
  output wire [95:0]     tau_o,       // update: new flux {b, g, r}
  output wire [31:0]     r2_o,        // update: new radius squared
  output wire [31:0]     n_o,         // update: new N
  output wire [95:0]     l_o,         // radiance: new pixel sum {b, g, r}
  output wire            busy_o       // an operation is in flight; mode_i must hold
);

  localparam [31:0] ALPHA  = 32'h3F33_3333;  // (float)0.7
  localparam [31:0] ONE    = 32'h3F80_0000;  // 1.0f
  localparam [31:0] INV_PI = 32'h3EA2_F983;  // (float)(1.0 / 3.14159265358979)
  localparam [31:0] PI     = 32'h4049_0FDB;  // (float)3.14159265358979
  localparam        UPD_LAST = 10;           // stage of the update result
  localparam        RAD_LAST = 12;           // stage of the radiance result

  wire upd = ~mode_i;
  wire rad = mode_i;

  // ------------------------------------------------------------------ stage valid bits
  // valid_q[k]: an operation is in stage k (k cycles after it entered). Stages 11 and 12
  // exist only in radiance mode, so an update operation never reaches them.
  reg [RAD_LAST:1] valid_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {RAD_LAST{1'b0}};
    else         valid_q <= {valid_q[RAD_LAST-1:UPD_LAST+1], valid_q[UPD_LAST] & rad,
                             valid_q[UPD_LAST-1:1], valid_i};
  end

  // ------------------------------------------------------------------ unit results
  // The units' own valid_o bits are only checked against valid_q (under PREE_ASSERT), and the
  // comparator's other flags are not needed: these wires are deliberately left unread.
  /* verilator lint_off UNUSEDSIGNAL */
  wire [2:0]  sub_v, mul_lo_v, mul_mid_v, mul_hi_v, sqr_v, addc_v;
  wire        mul9_v, add3_v, add4_v, add5_v, add6_v, div_v;
  wire        cmp_lt, cmp_eq, cmp_unordered;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [95:0] d_y;        // SUB0..2:  d_k
  wire [95:0] mul_lo_y;   // MUL0..2:  m_c (update), MUL0 = a (radiance)
  wire [95:0] mul_mid_y;  // MUL3..5:  t_c (update), MUL3 = b (radiance)
  wire [95:0] mul_hi_y;   // MUL6..8:  tau_n_c (update), c_c (radiance)
  wire [95:0] q_y;        // SQR0..2:  q_k
  wire [95:0] addc_y;     // ADD0..2:  u_c (update), L'_c (radiance)
  wire [31:0] r2n_y;      // MUL9
  wire [31:0] s_y;        // ADD3
  wire [31:0] d2_y;       // ADD4
  wire [31:0] na_y;       // ADD5
  wire [31:0] n1_y;       // ADD6
  wire [31:0] div_y;      // DIV: g (update), k (radiance)
  wire        cmp_le;

  // ------------------------------------------------------------------ delay registers
  // Flat vectors, slot k-1 holds stage k. Each slot loads when its operation moves into it.
  reg [12*TagW-1:0] tag_q;   // stages 1..12
  reg [8*96-1:0]    tau_q;   // stages 1..8: read in S5 (update, stage-4 value) and S9 (radiance)
  reg [8*32-1:0]    r2_q;    // stages 1..8: read by MUL9 (stage 6) and CMP (stage 8)
  reg [6*32-1:0]    na_q;    // stages 3..8: N + ALPHA to the output
  reg [2*32-1:0]    qz_q;    // stages 5..6: q_z waits for s
  integer k;

  always @(posedge clk_i) begin
    if (valid_i) begin
      tag_q[0 +: TagW] <= tag_i;
      tau_q[0 +: 96]   <= hp_tau_i;
      r2_q[0 +: 32]    <= hp_r2_i;
    end
    for (k = 1; k < RAD_LAST; k = k + 1)
      if (valid_q[k]) tag_q[k*TagW +: TagW] <= tag_q[(k-1)*TagW +: TagW];
    for (k = 1; k < 8; k = k + 1)
      if (valid_q[k]) begin
        tau_q[k*96 +: 96] <= tau_q[(k-1)*96 +: 96];
        r2_q[k*32 +: 32]  <= r2_q[(k-1)*32 +: 32];
      end
    if (valid_q[2]) na_q[0 +: 32] <= na_y;
    for (k = 1; k < 6; k = k + 1)
      if (valid_q[k+2]) na_q[k*32 +: 32] <= na_q[(k-1)*32 +: 32];
    if (valid_q[4]) qz_q[0 +: 32] <= q_y[64 +: 32];
    if (valid_q[5]) qz_q[32 +: 32] <= qz_q[0 +: 32];
  end

  wire [95:0] tau_s4 = tau_q[3*96 +: 96];
  wire [95:0] tau_s8 = tau_q[7*96 +: 96];
  wire [31:0] r2_s6  = r2_q[5*32 +: 32];
  wire [31:0] r2_s8  = r2_q[7*32 +: 32];
  wire [31:0] na_s8  = na_q[5*32 +: 32];
  wire [31:0] qz_s6  = qz_q[32 +: 32];

  // ------------------------------------------------------------------ S1-S2
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s1
      // SUB0..2: d_k = H.pos_k - P.pos_k (update)
      pree_fp32_add u_sub (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
        .a_i(hp_pos_i[32*c +: 32]), .b_i(ph_pos_i[32*c +: 32]), .sub_i(1'b1),
        .valid_o(sub_v[c]), .y_o(d_y[32*c +: 32]));
      // MUL0..2: m_c = H.f_c * P.phi_c (update); MUL0: a = PI * H.r2 (radiance)
      pree_fp32_mul u_mul_lo (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & (upd | (c == 0))),
        .a_i((rad && c == 0) ? PI : hp_f_i[32*c +: 32]),
        .b_i((rad && c == 0) ? hp_r2_i : ph_phi_i[32*c +: 32]),
        .valid_o(mul_lo_v[c]), .y_o(mul_lo_y[32*c +: 32]));
    end
  endgenerate

  // ADD5: na = N + ALPHA; ADD6: n1 = N + ONE (update)
  pree_fp32_add u_add5 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
    .a_i(hp_n_i), .b_i(ALPHA), .sub_i(1'b0), .valid_o(add5_v), .y_o(na_y));
  pree_fp32_add u_add6 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_i & upd),
    .a_i(hp_n_i), .b_i(ONE), .sub_i(1'b0), .valid_o(add6_v), .y_o(n1_y));

  // ------------------------------------------------------------------ S3-S4
  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s3
      // SQR0..2: q_k = d_k * d_k (update)
      pree_fp32_sqr u_sqr (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[2] & upd),
        .a_i(d_y[32*c +: 32]), .valid_o(sqr_v[c]), .y_o(q_y[32*c +: 32]));
      // MUL3..5: t_c = m_c * INV_PI (update); MUL3: b = a * NE (radiance)
      pree_fp32_mul u_mul_mid (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[2] & (upd | (c == 0))),
        .a_i(mul_lo_y[32*c +: 32]),
        .b_i((rad && c == 0) ? ne_i : INV_PI),
        .valid_o(mul_mid_v[c]), .y_o(mul_mid_y[32*c +: 32]));
    end
  endgenerate

  // DIV: g = na / n1 in S3-S6 (update); k = ONE / b in S5-S8 (radiance)
  pree_fp32_div u_div (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(rad ? valid_q[4] : valid_q[2]),
    .a_i(rad ? ONE : na_y), .b_i(rad ? mul_mid_y[0 +: 32] : n1_y),
    .valid_o(div_v), .y_o(div_y));

  // ------------------------------------------------------------------ S5-S6
  // ADD3: s = q_x + q_y (update)
  pree_fp32_add u_add3 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[4] & upd),
    .a_i(q_y[0 +: 32]), .b_i(q_y[32 +: 32]), .sub_i(1'b0), .valid_o(add3_v), .y_o(s_y));

  generate
    for (c = 0; c < 3; c = c + 1) begin : g_s5
      // ADD0..2: u_c = H.tau_c + t_c in S5-S6 (update); L'_c = L_c + c_c in S11-S12 (radiance)
      pree_fp32_add u_addc (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(rad ? valid_q[10] : valid_q[4]),
        .a_i(rad ? l_i[32*c +: 32] : tau_s4[32*c +: 32]),
        .b_i(rad ? mul_hi_y[32*c +: 32] : mul_mid_y[32*c +: 32]), .sub_i(1'b0),
        .valid_o(addc_v[c]), .y_o(addc_y[32*c +: 32]));
      // MUL6..8: tau_n_c = u_c * g in S7-S8 (update); c_c = H.tau_c * k in S9-S10 (radiance)
      pree_fp32_mul u_mul_hi (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(rad ? valid_q[8] : valid_q[6]),
        .a_i(rad ? tau_s8[32*c +: 32] : addc_y[32*c +: 32]), .b_i(div_y),
        .valid_o(mul_hi_v[c]), .y_o(mul_hi_y[32*c +: 32]));
    end
  endgenerate

  // ------------------------------------------------------------------ S7-S8
  // ADD4: d2 = s + q_z; MUL9: r2n = H.r2 * g (update)
  pree_fp32_add u_add4 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[6] & upd),
    .a_i(s_y), .b_i(qz_s6), .sub_i(1'b0), .valid_o(add4_v), .y_o(d2_y));
  pree_fp32_mul u_mul9 (
    .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(valid_q[6] & upd),
    .a_i(r2_s6), .b_i(div_y), .valid_o(mul9_v), .y_o(r2n_y));

  // ------------------------------------------------------------------ S9-S10
  // CMP: accept = d2 <= H.r2 (false on NaN), registered with the results in S9, again in S10.
  pree_fp32_cmp u_cmp (
    .a_i(d2_y), .b_i(r2_s8), .lt_o(cmp_lt), .le_o(cmp_le), .eq_o(cmp_eq),
    .unordered_o(cmp_unordered));

  reg        acc_q9, acc_q10;
  reg [95:0] taun_q9, taun_q10;
  reg [31:0] r2n_q9, r2n_q10, na_q9, na_q10;

  always @(posedge clk_i) begin
    if (valid_q[8]) begin
      acc_q9  <= cmp_le;
      taun_q9 <= mul_hi_y;
      r2n_q9  <= r2n_y;
      na_q9   <= na_s8;
    end
    if (valid_q[9]) begin
      acc_q10  <= acc_q9;
      taun_q10 <= taun_q9;
      r2n_q10  <= r2n_q9;
      na_q10   <= na_q9;
    end
  end

  // ------------------------------------------------------------------ outputs
  assign lreq_o     = rad & valid_q[9];
  assign lreq_tag_o = tag_q[8*TagW +: TagW];
  assign valid_o    = rad ? valid_q[RAD_LAST] : valid_q[UPD_LAST];
  assign tag_o      = rad ? tag_q[(RAD_LAST-1)*TagW +: TagW] : tag_q[(UPD_LAST-1)*TagW +: TagW];
  assign accept_o   = upd & valid_q[UPD_LAST] & acc_q10;
  assign tau_o      = taun_q10;
  assign r2_o       = r2n_q10;
  assign n_o        = na_q10;
  assign l_o        = addc_y;
  assign busy_o     = rad ? (|valid_q) : (|valid_q[UPD_LAST:1]);

`ifdef PREE_ASSERT
  // Checks of the protocol and of the stage plan; simulation only.
  reg mode_q;
  wire busy_old = mode_q ? (|valid_q) : (|valid_q[UPD_LAST:1]);
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      mode_q <= 1'b0;
    end else begin
      mode_q <= mode_i;
      if (mode_i != mode_q && busy_old)
        $fatal(1, "pree_preu: mode_i changed while operations were in flight (valid_q=%b)", valid_q);
      if (sub_v != {3{valid_q[2] & upd}} || add5_v != (valid_q[2] & upd) ||
          add6_v != (valid_q[2] & upd) ||
          mul_lo_v != {valid_q[2] & upd, valid_q[2] & upd, valid_q[2]} ||
          sqr_v != {3{valid_q[4] & upd}} ||
          mul_mid_v != {valid_q[4] & upd, valid_q[4] & upd, valid_q[4]} ||
          div_v != (rad ? valid_q[8] : valid_q[6]) ||
          add3_v != (valid_q[6] & upd) ||
          addc_v != {3{rad ? valid_q[12] : valid_q[6]}} ||
          mul_hi_v != {3{rad ? valid_q[10] : valid_q[8]}} ||
          add4_v != (valid_q[8] & upd) || mul9_v != (valid_q[8] & upd))
        $fatal(1, "pree_preu: a unit's valid_o is out of step with the stage plan");
    end
  end
`endif

endmodule
