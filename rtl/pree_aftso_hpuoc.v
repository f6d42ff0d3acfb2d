// SPDX-License-Identifier: Apache-2.0
// pree_aftso_hpuoc: approximate full-task-schedule hit-point update operation controller
// (AFTSO-HpUOC, paper 000 Sec. IV.B, Fig. 8).
//
// Purpose: turn a stream of photons, each with a candidate list of N^P hit points stored at
// index-table entries p_addr .. p_addr + N^P - 1, into up to NumPreu hit-point update
// operations per cycle, mixing the lists of up to BufDepth consecutive photons so that the
// PREUs stay busy. The intake takes up to PhotonsPerCycle photons a cycle (1 in the paper),
// so that NumPreu lanes stay fed when photons average fewer than NumPreu hit points.
//
// Buffer: BufDepth entries (4 in the paper, for any NumPreu) holding photon data, id, p_addr
// and rem (hit points not yet dispatched, >= 1). Valid entries are always 0 .. count-1, in
// arrival (photon) order. The rule is model/pree/aftso_rule.c's (the same in C). The registers
// hold each entry's accuHP (below) and its comparisons with 0 .. NumPreu rather than rem, so
// that no cycle sums the buffer: every path has at most 6 LUT levels in synth_xilinx
// (docs/controllers.md, "Registered accuHP"); the lanes and the cycles are the rule's.
//
// Dispatch rule, once per cycle in which stall_i is low:
//   accuHP_i   = rem_0 + ... + rem_i                      (valid entries only)
//   dispatch_i = accuHP_i >= NumPreu, buf_addr = first i with dispatch_i
//   entries before buf_addr leave whole (left side); entry buf_addr leaves whole when
//   accuHP_buf_addr == NumPreu, else only its first NumPreu - accuHP_{buf_addr-1} hit points
//   (right side). When no dispatch_i is set the whole buffer leaves (a partial cycle: this
//   case is not spelled out in the paper; dispatching it keeps the rule work-conserving).
//   Entries that left whole are removed and the others shift to the front; the partially
//   dispatched one, if any, becomes entry 0 with rem = accuHP_buf_addr - NumPreu.
//
// Lanes: lane l (0 <= l < NumPreu) carries hit point number l of the buffer counted in photon
// order, i.e. lanes are filled from entry 0 upwards; lane_valid_o is a thermometer code
// (lanes 0 .. min(total, NumPreu)-1). A photon's hit points leave in the paper's order,
// ref_addr = p_addr + N^P - 1, p_addr + N^P - 2, ..., p_addr. So for two valid lanes a < b,
// the photon of lane a is the same as or older than the photon of lane b. lane_last_o marks
// the photon's final hit point (ref_addr == p_addr).
//
// Hazards (not resolved here): one photon's candidate list must hold each hit point once, or
// two lanes of one cycle may update the same hit point with no order between them. Across
// photons the same hit point may appear in two lanes of one cycle or be in flight in a PREU;
// the top resolves that from the hit-point addresses it reads through ref_addr, using the lane
// order above as photon order, and holds this block with stall_i.
//
// Handshake:
//   in_valid_i/in_ready_o  the PhotonsPerCycle photon slots (slot s in bits [s*W +: W], slot 0
//                          the oldest) are taken together in a cycle with both high; they
//                          enter the buffer in slot order. A slot with N^P = 0 is taken and
//                          dropped (no entry, no lane): a source with fewer photons fills the
//                          remaining slots with N^P = 0.
//   in_ready_o             PhotonsPerCycle entries are free after this cycle's departures.
//                          EarlyReady = 0: free now (PhotonsPerCycle = 1: an entry is free;
//                          busy_o = buffer full, as in the paper). EarlyReady = 1: the entries
//                          that leave whole in this cycle count as free when stall_i is low,
//                          so a full buffer can take photons every cycle; in_ready_o then
//                          depends on stall_i combinationally (never on in_valid_i).
//   lane_*_o               an offer, combinational from registers only (not from any input).
//                          It is taken on every rising edge with stall_i low. While stall_i is
//                          high the state does not advance; a valid lane keeps its content and
//                          lanes above the valid ones may become valid as photons arrive.
//   empty_o                the buffer holds no photon (all taken photons fully dispatched).
// Invalid lanes drive zeros. Latency: a photon taken at edge k is offered from edge k on
// (in the cycle after it was taken).
//
// Parameters: NumPreu >= 1 lanes, BufDepth >= 2 entries, PhotonsPerCycle 1 .. BufDepth photon
// slots, DataW photon data bits, IdW photon id bits, AddrW index-table address bits (ref_addr
// wraps modulo 2^AddrW), CntW bits of N^P. PhotonsPerCycle = 1 is the paper's intake.
`default_nettype none

module pree_aftso_hpuoc #(
  parameter NumPreu    = 4,
  parameter BufDepth   = 4,
  parameter DataW      = 192,
  parameter IdW        = 32,
  parameter AddrW      = 32,
  parameter CntW       = 32,
  parameter EarlyReady = 1,
  parameter PhotonsPerCycle = 1
) (
  input  wire                     clk_i,
  input  wire                     rst_ni,
  // Photon stream.
  input  wire                     in_valid_i,
  output wire                     in_ready_o,
  input  wire [PhotonsPerCycle*DataW-1:0] in_data_i,
  input  wire [PhotonsPerCycle*IdW-1:0]   in_id_i,
  input  wire [PhotonsPerCycle*AddrW-1:0] in_p_addr_i,
  input  wire [PhotonsPerCycle*CntW-1:0]  in_n_i,
  // Operation lanes, lane l in bits [l*W +: W].
  input  wire                     stall_i,
  output wire [NumPreu-1:0]       lane_valid_o,
  output wire [NumPreu*AddrW-1:0] lane_ref_addr_o,
  output wire [NumPreu*DataW-1:0] lane_data_o,
  output wire [NumPreu*IdW-1:0]   lane_id_o,
  output wire [NumPreu-1:0]       lane_last_o,
  // Status.
  output wire                     busy_o,
  output wire                     empty_o
);

  // Width of accuHP: a sum of BufDepth counts below 2^CntW, and at least wide enough for 2 NumPreu.
  localparam ACC_W0 = CntW + $clog2(BufDepth) + 1;
  localparam ACC_W  = ACC_W0 > $clog2(NumPreu) + 2 ? ACC_W0 : $clog2(NumPreu) + 2;
  localparam PPC    = PhotonsPerCycle;
  localparam NF     = NumPreu + 1;   // flags per entry: accuHP_i > l for l = 0 .. NumPreu

  generate
    if (PPC < 1 || PPC > BufDepth) begin : g_bad_ppc
      pree_aftso_hpuoc_photonspercycle_must_be_1_to_bufdepth u_fail ();
    end
  endgenerate

  // Zero-extend or truncate between the widths in use (all truncations are modulo 2^W on
  // purpose: ref_addr wraps). One definition makes the casts: PREE_WIDTH_CAST(name, out width,
  // in width) declares the function `name`, whose temporary is named *_unused, Verilator's
  // default pattern for bits dropped on purpose.
`define PREE_WIDTH_CAST(NAME, OW, IW) \
  function [OW-1:0] NAME; \
    input [IW-1:0] v; \
    reg [OW+IW-1:0] ext_unused; \
    begin \
      ext_unused = {{OW{1'b0}}, v}; \
      NAME = ext_unused[OW-1:0]; \
    end \
  endfunction
  `PREE_WIDTH_CAST(acc_of_32,   ACC_W, 32)
  `PREE_WIDTH_CAST(acc_of_cnt,  ACC_W, CntW)
  `PREE_WIDTH_CAST(addr_of_acc, AddrW, ACC_W)
  `PREE_WIDTH_CAST(addr_of_32,  AddrW, 32)
`undef PREE_WIDTH_CAST

  // above(x, c) = x > c for a constant c < 2^LOW_W, as logic (upper bits not all zero, or the
  // low bits above c, compared bit by bit from the top against the constant) rather than a
  // subtraction: it maps to two LUT levels, not a carry chain. (Written per bit, not as a match
  // of every value above c, so that elaboration stays linear in LOW_W: Yosys takes minutes to
  // inline the 2^LOW_W form at 16 lanes.)
  localparam LOW_W = $clog2(2 * NumPreu + 2);
  function above;
    input [ACC_W-1:0] x;
    input [31:0]      c;
    integer b;
    reg eq;
    begin
      above = (x >> LOW_W) != {ACC_W{1'b0}};
      eq    = c < (1 << LOW_W);      // a larger c: the low bits are never above it
      for (b = LOW_W - 1; b >= 0; b = b - 1) begin
        if (!c[b]) above = above | (eq & x[b]);
        eq = eq & (x[b] == c[b]);
      end
    end
  endfunction
  // thermo(x): the flags of accuHP x, x > l for l = 0 .. NumPreu.
  function [NF-1:0] thermo;
    input [ACC_W-1:0] x;
    integer l;
    begin
      for (l = 0; l < NF; l = l + 1) thermo[l] = above(x, l);
    end
  endfunction

  localparam [31:0] NUM_PREU_32 = NumPreu;
  wire [ACC_W-1:0]  preu_acc  = acc_of_32(NUM_PREU_32);
  wire [AddrW-1:0]  preu_addr = addr_of_32(NUM_PREU_32);

  // ---------------------------------------------------------------------------------------------
  // Buffer registers. The rule needs accuHP_i, not rem_i, so accuHP is what is held: every
  // decision of a cycle is then a comparison of a register with a constant, and the next
  // cycle's accuHP is this cycle's minus NumPreu, shifted, or a new total (docs/controllers.md,
  // "Registered accuHP"). rem_i is accuHP_i - accuHP_{i-1}.
  //   valid_q  a thermometer code (entries 0 .. count-1)
  //   acc_q    accuHP_i; an invalid entry holds the total (it adds zero), so acc_q[BufDepth-1]
  //            is the number of hit points in the buffer
  //   gt_q     gt_q[i*NF + l] = accuHP_i > l, l = 0 .. NumPreu
  //   ref_q    p_addr_i + accuHP_i - 1: the address that lane 0 would take from entry i
  //            (lane l takes ref_q[i] - l)
  // valid, acc and gt are reset (the empty buffer: all totals 0); the payload loads on shift or
  // append and has no reset.
  reg  [BufDepth-1:0]       valid_q;
  reg  [BufDepth*ACC_W-1:0] acc_q;
  reg  [BufDepth*NF-1:0]    gt_q;
  reg  [BufDepth*AddrW-1:0] ref_q;
  reg  [ACC_W-1:0]          tq_q;     // max(total - NumPreu, 0): the total left after a taken offer
  reg  [BufDepth*DataW-1:0] data_q;
  reg  [BufDepth*IdW-1:0]   id_q;

  // whole[i]: entry i leaves whole this cycle if not stalled (valid and accuHP_i <= NumPreu; a
  // prefix of the valid entries, since accuHP grows along the buffer).
  wire [BufDepth-1:0] whole;
  // An entry that stays after a taken offer: accuHP and ref_q drop by NumPreu, and its flags
  // are accuHP_i > l + NumPreu.
  wire [BufDepth*ACC_W-1:0] dn_acc;
  wire [BufDepth*AddrW-1:0] dn_ref;
  wire [BufDepth*NF-1:0]    dn_gt;

  genvar gi, gl, gf, gv;
  generate
    for (gi = 0; gi < BufDepth; gi = gi + 1) begin : g_entry
      assign whole[gi] = valid_q[gi] & ~gt_q[gi*NF + NumPreu];
      assign dn_acc[gi*ACC_W +: ACC_W] = acc_q[gi*ACC_W +: ACC_W] - preu_acc;
      assign dn_ref[gi*AddrW +: AddrW] = ref_q[gi*AddrW +: AddrW] - preu_addr;
      for (gf = 0; gf < NF; gf = gf + 1) begin : g_flag
        assign dn_gt[gi*NF + gf] = above(acc_q[gi*ACC_W +: ACC_W], gf + NumPreu);
      end
    end
  endgenerate

  // ---------------------------------------------------------------------------------------------
  // Lanes. Lane l takes entry e when accuHP_{e-1} <= l < accuHP_e (one-hot over e; none when
  // l >= total, and never an invalid entry, whose accuHP equals the one before it).
  // ref_addr = p_addr_e + rem_e - 1 - (l - accuHP_{e-1}) = ref_q[e] - l.
  generate
    for (gl = 0; gl < NumPreu; gl = gl + 1) begin : g_lane
      localparam [31:0] LANE_32 = gl;
      reg  [BufDepth-1:0] sel;
      reg  [AddrW-1:0]    base;
      reg  [DataW-1:0]    data;
      reg  [IdW-1:0]      id;
      reg                 last;
      integer e;
      always @* begin
        base = {AddrW{1'b0}};
        data = {DataW{1'b0}};
        id   = {IdW{1'b0}};
        last = 1'b0;
        for (e = 0; e < BufDepth; e = e + 1) begin
          sel[e] = gt_q[e*NF + gl] && (e == 0 || !gt_q[((e == 0) ? 0 : e-1)*NF + gl]);
          base = base | ({AddrW{sel[e]}} & ref_q[e*AddrW +: AddrW]);
          data = data | ({DataW{sel[e]}} & data_q[e*DataW +: DataW]);
          id   = id   | ({IdW{sel[e]}}   & id_q[e*IdW +: IdW]);
          last = last | (sel[e] && !gt_q[e*NF + gl + 1]);    // accuHP_e == l + 1
        end
      end
      // Valid: the total exceeds l (the last entry holds the total).
      wire valid = gt_q[(BufDepth-1)*NF + gl];
      assign lane_valid_o[gl]                   = valid;
      assign lane_ref_addr_o[gl*AddrW +: AddrW] = valid ? base - addr_of_32(LANE_32) : {AddrW{1'b0}};
      assign lane_data_o[gl*DataW +: DataW]     = data;
      assign lane_id_o[gl*IdW +: IdW]           = id;
      assign lane_last_o[gl]                    = last;
    end
  endgenerate

  // ---------------------------------------------------------------------------------------------
  // Next state, once for each value of stall_i (g_nx[1]: stalled, g_nx[0]: the offer is taken),
  // so that stall_i, which arrives late (the top's read of the offer), only selects at the end.
  //   in_ready: PPC entries free once the w entries that leave whole in this cycle (EarlyReady,
  //     not stalled) are gone, for some w in 0 .. PPC; with a thermometer valid_q, "BufDepth -
  //     PPC + w entries free" is "entry BufDepth - PPC + w invalid".
  //   taken: shift by the number of whole entries s (one-hot shift_oh[s], s = 0 .. BufDepth);
  //     the entries that stay drop NumPreu (the partial one, if any, becomes entry 0 with
  //     accuHP = its accuHP - NumPreu); the total left is total - NumPreu, or 0 when every
  //     entry left.
  //   then append the accepted slots with N^P > 0, in slot order, each behind the last valid
  //   entry, with accuHP = the total so far; the entries above hold the new total.
  generate
    for (gv = 0; gv < 2; gv = gv + 1) begin : g_nx
      reg  [BufDepth-1:0]       kept, valid_d;
      reg  [BufDepth*ACC_W-1:0] acc_d;
      reg  [BufDepth*NF-1:0]    gt_d;
      reg  [BufDepth*AddrW-1:0] ref_d;
      reg  [BufDepth*DataW-1:0] data_d;
      reg  [BufDepth*IdW-1:0]   id_d;
      reg  [ACC_W-1:0]          tq_d;
      reg                       ready;
      wire [BufDepth-1:0] leave = (gv != 0) ? {BufDepth{1'b0}} : whole;
      wire [BufDepth:0]   shift_oh;
      for (gi = 0; gi <= BufDepth; gi = gi + 1) begin : g_shift
        if (gi == 0) begin : g_none
          assign shift_oh[gi] = ~leave[0];
        end else if (gi == BufDepth) begin : g_all
          assign shift_oh[gi] = leave[BufDepth-1];
        end else begin : g_some
          assign shift_oh[gi] = leave[gi-1] & ~leave[gi];
        end
      end

      always @* begin : next
        integer w, k, s, j;
        reg [ACC_W-1:0] t, t_dn, cum;
        reg [NF-1:0]    t_gt;
        reg placed, accept;
        placed = 1'b0;
        ready  = 1'b0;
        for (w = 0; w <= PPC; w = w + 1)
          if ((w == 0 || (EarlyReady != 0 && leave[(w == 0) ? 0 : w-1])) &&
              (BufDepth - PPC + w >= BufDepth || !valid_q[(BufDepth - PPC + w < BufDepth) ? BufDepth - PPC + w : 0]))
            ready = 1'b1;
        accept = in_valid_i && ready;

        data_d = data_q;
        id_d   = id_q;
        acc_d  = acc_q;
        gt_d   = gt_q;
        ref_d  = ref_q;
        // t: the total left before the append; t_gt its flags; t_dn = max(t - NumPreu, 0).
        if (gv != 0) begin
          kept = valid_q;
          t    = acc_q[(BufDepth-1)*ACC_W +: ACC_W];
          t_gt = gt_q[(BufDepth-1)*NF +: NF];
          t_dn = tq_q;
        end else begin
          kept = {BufDepth{1'b0}};
          for (k = 0; k < BufDepth; k = k + 1)
            for (s = 0; s <= BufDepth; s = s + 1)
              if (shift_oh[s] && k + s < BufDepth) begin
                kept[k]                  = valid_q[(k + s < BufDepth) ? k + s : 0];
                data_d[k*DataW +: DataW] = data_q[((k + s < BufDepth) ? k + s : 0)*DataW +: DataW];
                id_d[k*IdW +: IdW]       = id_q[((k + s < BufDepth) ? k + s : 0)*IdW +: IdW];
                acc_d[k*ACC_W +: ACC_W]  = dn_acc[((k + s < BufDepth) ? k + s : 0)*ACC_W +: ACC_W];
                gt_d[k*NF +: NF]         = dn_gt[((k + s < BufDepth) ? k + s : 0)*NF +: NF];
                ref_d[k*AddrW +: AddrW]  = dn_ref[((k + s < BufDepth) ? k + s : 0)*AddrW +: AddrW];
              end
          t    = tq_q;
          t_gt = dn_gt[(BufDepth-1)*NF +: NF];
          t_dn = above(tq_q, NumPreu) ? tq_q - preu_acc : {ACC_W{1'b0}};
        end

        // The append: slot j's entry has accuHP t + cum_j (cum_j: N^P of the slots up to j, from
        // the inputs alone) and ref_q = (p_addr_j - 1 + cum_j) + t, one adder after t each.
        valid_d = kept;
        cum     = {ACC_W{1'b0}};
        for (j = 0; j < PPC; j = j + 1) begin
          if (in_n_i[j*CntW +: CntW] != {CntW{1'b0}}) begin
            cum    = cum + acc_of_cnt(in_n_i[j*CntW +: CntW]);
            placed = 1'b0;
            for (k = 0; k < BufDepth; k = k + 1) begin
              if (accept && !placed && !valid_d[k] && (k == 0 || valid_d[(k == 0) ? 0 : k-1])) begin
                placed                   = 1'b1;
                valid_d[k]               = 1'b1;
                data_d[k*DataW +: DataW] = in_data_i[j*DataW +: DataW];
                id_d[k*IdW +: IdW]       = in_id_i[j*IdW +: IdW];
                acc_d[k*ACC_W +: ACC_W]  = t + cum;
                gt_d[k*NF +: NF]         = thermo(t + cum);
                ref_d[k*AddrW +: AddrW]  = in_p_addr_i[j*AddrW +: AddrW] - {{(AddrW-1){1'b0}}, 1'b1}
                                           + addr_of_acc(cum) + addr_of_acc(t);
              end
            end
          end
        end
        // The entries above the valid ones hold the new total; the total left next time.
        for (k = 0; k < BufDepth; k = k + 1)
          if (!valid_d[k]) begin
            acc_d[k*ACC_W +: ACC_W] = accept ? t + cum : t;
            gt_d[k*NF +: NF]        = accept ? thermo(t + cum) : t_gt;
          end
        tq_d = !accept ? t_dn : above(t + cum, NumPreu) ? t + cum - preu_acc : {ACC_W{1'b0}};
      end
    end
  endgenerate

  assign in_ready_o = stall_i ? g_nx[1].ready : g_nx[0].ready;
  assign busy_o     = ~in_ready_o;
  assign empty_o    = ~valid_q[0];

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= {BufDepth{1'b0}};
      acc_q   <= {(BufDepth*ACC_W){1'b0}};
      gt_q    <= {(BufDepth*NF){1'b0}};
      tq_q    <= {ACC_W{1'b0}};
    end else begin
      valid_q <= stall_i ? g_nx[1].valid_d : g_nx[0].valid_d;
      acc_q   <= stall_i ? g_nx[1].acc_d   : g_nx[0].acc_d;
      gt_q    <= stall_i ? g_nx[1].gt_d    : g_nx[0].gt_d;
      tq_q    <= stall_i ? g_nx[1].tq_d    : g_nx[0].tq_d;
    end
  end

  always @(posedge clk_i) begin
    ref_q  <= stall_i ? g_nx[1].ref_d  : g_nx[0].ref_d;
    data_q <= stall_i ? g_nx[1].data_d : g_nx[0].data_d;
    id_q   <= stall_i ? g_nx[1].id_d   : g_nx[0].id_d;
  end

`ifdef PREE_ASSERT
  // Simulation-only checks (the benches define PREE_ASSERT): valid_q stays a thermometer code,
  // a valid entry is never empty (accuHP grows), an invalid one holds the total, and the flags
  // are accuHP's.
  integer a, f;
  always @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      for (a = 1; a < BufDepth; a = a + 1) begin
        if (valid_q[a] && !valid_q[a-1]) $fatal(1, "pree_aftso_hpuoc: valid_q not a thermometer");
        if (valid_q[a] != (acc_q[a*ACC_W +: ACC_W] > acc_q[(a-1)*ACC_W +: ACC_W]))
          $fatal(1, "pree_aftso_hpuoc: accuHP of entry %0d", a);
      end
      if (valid_q[0] != (acc_q[0 +: ACC_W] != {ACC_W{1'b0}})) $fatal(1, "pree_aftso_hpuoc: accuHP of entry 0");
      for (a = 0; a < BufDepth; a = a + 1)
        for (f = 0; f < NF; f = f + 1)
          if (gt_q[a*NF + f] != (acc_q[a*ACC_W +: ACC_W] > acc_of_32(f)))
            $fatal(1, "pree_aftso_hpuoc: flag %0d of entry %0d", f, a);
    end
  end
`endif

endmodule

`default_nettype wire
