// SPDX-License-Identifier: Apache-2.0
// adiso_rec_fv: formal harness of pree_adiso_rec (ADISO-REC, paper 000 Eq. 10-13).
//
// Drives the controller with free inputs (start_i, n_hit_i, stall_i at every cycle, reset in
// the first cycle only) and checks, for every pass, started at any time:
//   - each group i offers only addresses of [size*i, end_i) (the groups partition [0, N));
//   - its first address is size*i, and after each taken address a the next one it offers is
//     a + lv while that stays below end_i, else the next residue class: the class start of a
//     (size*i + (a - size*i) mod lv) plus one (Eq. 12/13, lv = N >> SHIFT or 1, Eq. 10);
//   - a group offers exactly until it has taken end_i - size*i addresses;
//   - a watched address W (any constant) is taken at most once in a pass, and exactly once
//     (when W < N) by the time busy_o falls; the pass takes exactly N addresses;
//   - invalid groups drive 0; busy_o is the OR of the valid bits; N = 0 gives no valid cycle.
// The reference values (bounds, lv, class starts) are written here from the paper's equations,
// not taken from the controller.
//
// Inductive strengthening (so that k-induction proves the above for every reachable state, not
// only a bounded number of cycles from reset): the controller's registers, seen through taps,
// agree with the pass (lv, end), the count taken so far (rem), the class of the current address
// (start), and the number of addresses still to come in the documented order, in closed form:
//   rem = ceil((end - a) / lv) + (lv - 1 - c) * Q + max(0, R - c - 1)
// with c = start - size*i the current class, Q = size_i / lv, R = size_i mod lv (classes r < R
// hold Q + 1 addresses, the others Q). W's count equals "W lies before the current address in
// the order" (an earlier class, or the same class below the current address).
`default_nettype none

module adiso_rec_fv #(
  parameter NumPreu   = 2,
  parameter PipeDepth = 2,
  parameter AddrW     = 5,
  parameter Strengthen = 1   // 0: leave out the inductive strengthening (bounded checks from reset)
) (
  input wire             clk_i,
  input wire             start_i,
  input wire [AddrW-1:0] n_hit_i,
  input wire             stall_i
);

  localparam SHIFT   = $clog2(NumPreu * PipeDepth);
  localparam LOG_SET = $clog2(NumPreu);
  localparam CNTW    = AddrW + 1;

  // Reset held for the first cycle only.
  reg f_init = 1'b1;
  always @(posedge clk_i) f_init <= 1'b0;
  wire rst_ni = !f_init;

  wire [NumPreu-1:0]       addr_valid;
  wire [NumPreu*AddrW-1:0] addr;
  wire                     busy;

  pree_adiso_rec #(.NumPreu(NumPreu), .PipeDepth(PipeDepth), .AddrW(AddrW)) dut (
    .clk_i(clk_i), .rst_ni(rst_ni), .start_i(start_i), .n_hit_i(n_hit_i), .stall_i(stall_i),
    .addr_valid_o(addr_valid), .addr_o(addr), .busy_o(busy)
  );

  // Taps of the controller's registers (lv_q and, per group i at bits i*AddrW, start_q,
  // end_q, rem_q): wires the job's script connects to them after flattening (Yosys has no
  // hierarchical references or bind); used only in the inductive invariants.
  wire [AddrW-1:0]         f_t_lv;
  wire [NumPreu*AddrW-1:0] f_t_start, f_t_end, f_t_rem;

  // The pass in progress: its N, from the last start_i (after reset).
  reg             f_pass = 1'b0;    // a pass was started since reset
  reg [AddrW-1:0] f_n    = {AddrW{1'b0}};
  always @(posedge clk_i) begin
    if (!rst_ni)      f_pass <= 1'b0;
    else if (start_i) begin
      f_pass <= 1'b1;
      f_n    <= n_hit_i;
    end
  end

  wire [AddrW-1:0] f_lv_raw = f_n >> SHIFT;
  wire [AddrW-1:0] f_lv     = (f_lv_raw == 0) ? 1 : f_lv_raw;            // Eq. 10
  wire [AddrW-1:0] f_size   = f_n >> LOG_SET;

  // An address is taken on a rising edge with its valid bit set, stall_i low and no start_i.
  wire take_ok = rst_ni && !stall_i && !start_i;

  // The watched address W (any constant), counted over the pass, and all addresses taken.
  (* anyconst *) reg [AddrW-1:0] f_w;
  reg [CNTW-1:0] f_w_cnt   = 0;
  reg [CNTW-1:0] f_all_cnt = 0;
  integer k;
  reg [CNTW-1:0] w_hits, takes;
  always @* begin
    w_hits = 0;
    takes  = 0;
    for (k = 0; k < NumPreu; k = k + 1)
      if (addr_valid[k] && take_ok) begin
        takes = takes + 1;
        if (addr[k*AddrW +: AddrW] == f_w) w_hits = w_hits + 1;
      end
  end
  always @(posedge clk_i) begin
    if (!rst_ni || start_i) begin
      f_w_cnt   <= 0;
      f_all_cnt <= 0;
    end else begin
      f_w_cnt   <= f_w_cnt + w_hits;
      f_all_cnt <= f_all_cnt + takes;
    end
  end

  // Per group: the count taken and whether W lies before the current address (see g_group).
  wire [NumPreu*CNTW-1:0] f_cnt_all;
  wire [NumPreu-1:0]      f_w_before;
  reg  [CNTW-1:0]         f_cnt_sum, f_w_sum;
  always @* begin
    f_cnt_sum = 0;
    f_w_sum   = 0;
    for (k = 0; k < NumPreu; k = k + 1) begin
      f_cnt_sum = f_cnt_sum + f_cnt_all[k*CNTW +: CNTW];
      f_w_sum   = f_w_sum + f_w_before[k];
    end
  end

  always @* begin
    if (rst_ni) begin
      // Before any pass and at N = 0 nothing is offered; busy_o is the OR of the valid bits.
      assert (busy == |addr_valid);
      if (!f_pass || f_n == 0) assert (addr_valid == 0);
      // W is taken at most once; the pass never takes more than N addresses.
      assert (f_w_cnt + w_hits <= 1);
      assert (f_all_cnt + takes <= f_n);
      // When the pass is over (nothing offered) every address of [0, N) was taken once.
      if (f_pass && !busy) begin
        assert (f_all_cnt == f_n);
        assert (f_w_cnt == ((f_w < f_n) ? 1 : 0));
      end
      // Strengthening: the pass counts are the sums of the groups'.
      if (Strengthen) assert (f_all_cnt == f_cnt_sum);
      if (Strengthen && f_pass) begin
        assert (f_w_cnt == f_w_sum);
        assert (f_t_lv == f_lv);
      end
    end
  end

  // The per-group order.
  genvar gi;
  generate
    for (gi = 0; gi < NumPreu; gi = gi + 1) begin : g_group
      wire [AddrW-1:0] f_base = f_size * gi;
      wire [AddrW-1:0] f_end  = (gi == NumPreu - 1) ? f_n : f_size * (gi + 1);
      wire [AddrW-1:0] f_gsz  = f_end - f_base;                 // addresses of the group
      wire [AddrW-1:0] a      = addr[gi*AddrW +: AddrW];
      wire             v      = addr_valid[gi];

      reg             f_started = 1'b0;   // this group has taken an address in this pass
      reg [AddrW-1:0] f_prev    = 0;      // the address it took last
      reg [CNTW-1:0]  f_cnt     = 0;      // addresses it took in this pass
      always @(posedge clk_i) begin
        if (!rst_ni || start_i) begin
          f_started <= 1'b0;
          f_cnt     <= 0;
        end else if (v && take_ok) begin
          f_started <= 1'b1;
          f_prev    <= a;
          f_cnt     <= f_cnt + 1;
        end
      end
      assign f_cnt_all[gi*CNTW +: CNTW] = f_cnt;

      // The next address after f_prev (Eq. 12/13 written with the residue class of f_prev).
      wire [AddrW:0]   f_step      = {1'b0, f_prev} + {1'b0, f_lv};
      wire [AddrW-1:0] f_cls_start = f_base + (f_prev - f_base) % f_lv;
      wire [AddrW-1:0] f_expect    = (f_step >= {1'b0, f_end}) ? f_cls_start + 1
                                                                : f_step[AddrW-1:0];

      // Strengthening: the tapped registers, the current class c, the closed-form remainder.
      wire [AddrW-1:0] p_st  = f_t_start[gi*AddrW +: AddrW];
      wire [AddrW-1:0] p_en  = f_t_end[gi*AddrW +: AddrW];
      wire [AddrW-1:0] p_rm  = f_t_rem[gi*AddrW +: AddrW];
      wire [AddrW-1:0] f_c   = p_st - f_base;
      wire [AddrW-1:0] f_q   = f_gsz / f_lv;
      wire [AddrW-1:0] f_r   = f_gsz % f_lv;
      wire [2*AddrW:0] f_left = ({1'b0, f_end} - {1'b0, a} + {1'b0, f_lv} - 1) / f_lv
                               + (f_lv - 1 - f_c) * f_q
                               + ((f_r > f_c + 1) ? f_r - f_c - 1 : 0);
      // W before the current address: in this group, and in an earlier class, or in the same
      // class below it; every address of the group once the group is done.
      wire [AddrW-1:0] f_w_cls = (f_w - f_base) % f_lv;
      assign f_w_before[gi] = f_w >= f_base && f_w < f_end
                              && (!v || f_w_cls < f_c || (f_w_cls == f_c && f_w < a));

      always @* begin
        if (rst_ni) begin
          if (!v) assert (a == 0);
          if (v) begin
            assert (f_pass);
            assert (a >= f_base && a < f_end);
            if (!f_started) assert (a == f_base);
            else            assert (a == f_expect);
          end
          // A group offers until it has taken all of its end_i - size*i addresses.
          if (f_pass) assert (v == (f_cnt < f_gsz));
        end
        if (rst_ni && Strengthen) begin
          // Strengthening.
          assert (f_started == (f_cnt != 0));
          if (!f_pass) assert (p_rm == 0 && f_cnt == 0);
          if (f_pass) begin
            assert (f_cnt <= f_gsz);
            assert (p_rm == f_gsz - f_cnt);
            assert (p_en == f_end);
          end
          if (v) begin
            assert (f_c < f_lv && f_c < f_gsz);
            assert (p_st <= a && (a - p_st) % f_lv == 0);
            assert (f_left == p_rm);
            if (!f_started) assert (p_st == f_base);
          end
        end
      end

      // Covers: this group exhausted while another still offers (not the last group, the
      // largest); a leap that wraps to the next residue class with lv > 1 (a leaping pass).
      always @* begin
        if (rst_ni) begin
          if (gi < NumPreu - 1) cover (f_pass && f_started && !v && busy);
          cover (f_pass && v && f_started && f_lv > 1 && f_step >= {1'b0, f_end}
                 && f_cnt > 1);
        end
      end
    end
  endgenerate

  // Cover: a whole pass of a leaping N ends (busy_o falls with no new start).
  reg f_busy_q = 1'b0;
  always @(posedge clk_i) f_busy_q <= busy;
  always @* begin
    if (rst_ni) cover (f_pass && f_busy_q && !busy && f_lv > 1 && f_n > 2 * NumPreu);
  end

endmodule

`default_nettype wire
