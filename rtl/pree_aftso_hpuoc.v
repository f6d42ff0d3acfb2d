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
// arrival (photon) order. The rule is model/pree/aftso_rule.c's (the same in C).
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

  // Width of accuHP: a sum of BufDepth counts below 2^CntW, and at least wide enough for NumPreu.
  localparam ACC_W0 = CntW + $clog2(BufDepth) + 1;
  localparam ACC_W  = ACC_W0 > $clog2(NumPreu) + 2 ? ACC_W0 : $clog2(NumPreu) + 2;
  localparam PPC    = PhotonsPerCycle;

  generate
    if (PPC < 1 || PPC > BufDepth) begin : g_bad_ppc
      pree_aftso_hpuoc_photonspercycle_must_be_1_to_bufdepth u_fail ();
    end
  endgenerate

  // ---------------------------------------------------------------------------------------------
  // Buffer registers: valid is a thermometer code (entries 0 .. count-1); the payload loads on
  // shift or append and has no reset.
  reg  [BufDepth-1:0]       valid_q,  valid_d;
  reg  [BufDepth*DataW-1:0] data_q,   data_d;
  reg  [BufDepth*IdW-1:0]   id_q,     id_d;
  reg  [BufDepth*AddrW-1:0] paddr_q,  paddr_d;
  reg  [BufDepth*CntW-1:0]  rem_q,    rem_d;

  // ---------------------------------------------------------------------------------------------
  // accuHP and the whole-dispatch flags.
  //   accu[i]  accuHP_i (invalid entries add zero)
  //   whole[i] entry i leaves whole this cycle if not stalled: valid and accuHP_i <= NumPreu
  //            (a prefix of the valid entries, since accuHP grows along the buffer)
  reg  [BufDepth*ACC_W-1:0] accu;
  reg  [BufDepth-1:0]       whole;
  localparam [31:0]         NUM_PREU_32 = NumPreu;
  wire [ACC_W-1:0]          preu_acc = acc_of_32(NUM_PREU_32);

  // Zero-extend or truncate between the widths in use (all truncations are modulo 2^W on
  // purpose: ref_addr wraps, and a trimmed rem always fits in CntW bits). One definition makes
  // the four casts: PREE_WIDTH_CAST(name, out width, in width) declares the function `name`,
  // whose temporary is named *_unused, Verilator's default pattern for bits dropped on purpose.
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
  `PREE_WIDTH_CAST(addr_of_acc, AddrW, ACC_W)
  `PREE_WIDTH_CAST(addr_of_cnt, AddrW, CntW)
  `PREE_WIDTH_CAST(cnt_of_acc,  CntW,  ACC_W)
`undef PREE_WIDTH_CAST

  integer i;
  reg [ACC_W-1:0] sum;
  always @* begin
    sum = {ACC_W{1'b0}};
    for (i = 0; i < BufDepth; i = i + 1) begin
      if (valid_q[i]) sum = sum + {{(ACC_W-CntW){1'b0}}, rem_q[i*CntW +: CntW]};
      accu[i*ACC_W +: ACC_W] = sum;
      whole[i] = valid_q[i] && (sum <= preu_acc);
    end
  end

  genvar gi, gl, gs;

  // ---------------------------------------------------------------------------------------------
  // Lanes. Lane l takes entry e when accuHP_{e-1} <= l < accuHP_e (one-hot over e; none when
  // l >= total). ref_addr = p_addr_e + rem_e - 1 - (l - accuHP_{e-1}) = refbase_e - l.
  wire [BufDepth*AddrW-1:0] refbase;

  generate
    for (gi = 0; gi < BufDepth; gi = gi + 1) begin : g_refbase
      wire [ACC_W-1:0] prev_acc;
      if (gi == 0) begin : g_first
        assign prev_acc = {ACC_W{1'b0}};
      end else begin : g_next
        assign prev_acc = accu[(gi-1)*ACC_W +: ACC_W];
      end
      assign refbase[gi*AddrW +: AddrW] = paddr_q[gi*AddrW +: AddrW]
                                          + addr_of_cnt(rem_q[gi*CntW +: CntW])
                                          + addr_of_acc(prev_acc) - {{(AddrW-1){1'b0}}, 1'b1};
    end

    for (gl = 0; gl < NumPreu; gl = gl + 1) begin : g_lane
      localparam [31:0] LANE_32  = gl;
      localparam [31:0] LANE1_32 = gl + 1;
      wire [ACC_W-1:0] lane_idx  = acc_of_32(LANE_32);
      wire [ACC_W-1:0] lane_idx1 = acc_of_32(LANE1_32);
      reg  [BufDepth-1:0] sel;
      reg  [AddrW-1:0]    base;
      reg  [DataW-1:0]    data;
      reg  [IdW-1:0]      id;
      reg                 last;
      integer e;
      always @* begin
        sel  = {BufDepth{1'b0}};
        base = {AddrW{1'b0}};
        data = {DataW{1'b0}};
        id   = {IdW{1'b0}};
        last = 1'b0;
        for (e = 0; e < BufDepth; e = e + 1) begin
          // accuHP_{e-1} <= l is the same as "not below the previous prefix"; invalid entries
          // never match because their accuHP equals the previous one.
          sel[e] = (lane_idx < accu[e*ACC_W +: ACC_W]) &&
                   (e == 0 || accu[((e == 0) ? 0 : e-1)*ACC_W +: ACC_W] <= lane_idx);
          base = base | ({AddrW{sel[e]}} & refbase[e*AddrW +: AddrW]);
          data = data | ({DataW{sel[e]}} & data_q[e*DataW +: DataW]);
          id   = id   | ({IdW{sel[e]}}   & id_q[e*IdW +: IdW]);
          last = last | (sel[e] && accu[e*ACC_W +: ACC_W] == lane_idx1);
        end
      end
      assign lane_valid_o[gl]                 = |sel;
      assign lane_ref_addr_o[gl*AddrW +: AddrW] = |sel ? base - addr_of_acc(lane_idx) : {AddrW{1'b0}};
      assign lane_data_o[gl*DataW +: DataW]   = data;
      assign lane_id_o[gl*IdW +: IdW]         = id;
      assign lane_last_o[gl]                  = last;
    end
  endgenerate

  // ---------------------------------------------------------------------------------------------
  // Back-pressure and input acceptance: PPC entries free once the w entries that leave whole
  // in this cycle (EarlyReady, not stalled) are gone, for some w in 0 .. PPC; with a thermometer
  // valid_q, "BufDepth - PPC + w entries free" is "entry BufDepth - PPC + w invalid".
  wire [BufDepth-1:0] early_leave = (EarlyReady != 0 && !stall_i) ? whole : {BufDepth{1'b0}};
  reg  ready;
  integer w;
  always @* begin
    ready = 1'b0;
    for (w = 0; w <= PPC; w = w + 1)
      if ((w == 0 || early_leave[(w == 0) ? 0 : w-1]) &&
          (BufDepth - PPC + w >= BufDepth || !valid_q[(BufDepth - PPC + w < BufDepth) ? BufDepth - PPC + w : 0]))
        ready = 1'b1;
  end
  wire accept   = in_valid_i && ready;

  assign in_ready_o = ready;
  assign busy_o     = ~ready;
  assign empty_o    = ~valid_q[0];

  // ---------------------------------------------------------------------------------------------
  // Next state: shift by the number of whole entries (one-hot shift_oh[s], s = 0 .. BufDepth),
  // trim the partial entry (it lands in entry 0), append the new photon behind the rest.
  wire [BufDepth-1:0] leave = stall_i ? {BufDepth{1'b0}} : whole;
  wire [BufDepth:0]   shift_oh;

  generate
    for (gs = 0; gs <= BufDepth; gs = gs + 1) begin : g_shift
      if (gs == 0) begin : g_none
        assign shift_oh[gs] = ~leave[0];
      end else if (gs == BufDepth) begin : g_all
        assign shift_oh[gs] = leave[BufDepth-1];
      end else begin : g_some
        assign shift_oh[gs] = leave[gs-1] & ~leave[gs];
      end
    end
  endgenerate

  // rem of the entry that becomes entry 0 when it was dispatched in part: accuHP - NumPreu.
  reg [ACC_W-1:0] trimmed;
  integer s, k, j;
  reg     placed;
  always @* begin
    trimmed = {ACC_W{1'b0}};
    for (s = 0; s < BufDepth; s = s + 1)
      if (shift_oh[s]) trimmed = accu[s*ACC_W +: ACC_W] - preu_acc;
  end

  reg [BufDepth-1:0] valid_sh;
  always @* begin
    valid_sh = {BufDepth{1'b0}};
    data_d   = data_q;
    id_d     = id_q;
    paddr_d  = paddr_q;
    rem_d    = rem_q;
    // Shift: entry k takes entry k + shift.
    for (k = 0; k < BufDepth; k = k + 1) begin
      for (s = 0; s <= BufDepth; s = s + 1) begin
        if (shift_oh[s] && k + s < BufDepth) begin
          valid_sh[k]                = valid_q[(k + s < BufDepth) ? k + s : 0];
          data_d[k*DataW +: DataW]   = data_q[((k + s < BufDepth) ? k + s : 0)*DataW +: DataW];
          id_d[k*IdW +: IdW]         = id_q[((k + s < BufDepth) ? k + s : 0)*IdW +: IdW];
          paddr_d[k*AddrW +: AddrW]  = paddr_q[((k + s < BufDepth) ? k + s : 0)*AddrW +: AddrW];
          rem_d[k*CntW +: CntW]      = rem_q[((k + s < BufDepth) ? k + s : 0)*CntW +: CntW];
        end
      end
    end
    // The partial entry (not stalled, entry 0 after the shift still valid) loses what left.
    if (!stall_i && valid_sh[0]) rem_d[0 +: CntW] = cnt_of_acc(trimmed);
    // Append the slots with N^P > 0, in slot order, each behind the last valid entry.
    valid_d = valid_sh;
    for (j = 0; j < PPC; j = j + 1) begin
      placed = 1'b0;
      for (k = 0; k < BufDepth; k = k + 1) begin
        if (accept && in_n_i[j*CntW +: CntW] != {CntW{1'b0}} && !placed && !valid_d[k] &&
            (k == 0 || valid_d[(k == 0) ? 0 : k-1])) begin
          placed                    = 1'b1;
          valid_d[k]                = 1'b1;
          data_d[k*DataW +: DataW]  = in_data_i[j*DataW +: DataW];
          id_d[k*IdW +: IdW]        = in_id_i[j*IdW +: IdW];
          paddr_d[k*AddrW +: AddrW] = in_p_addr_i[j*AddrW +: AddrW];
          rem_d[k*CntW +: CntW]     = in_n_i[j*CntW +: CntW];
        end
      end
    end
  end

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {BufDepth{1'b0}};
    else         valid_q <= valid_d;
  end

  always @(posedge clk_i) begin
    data_q  <= data_d;
    id_q    <= id_d;
    paddr_q <= paddr_d;
    rem_q   <= rem_d;
  end

`ifdef PREE_ASSERT
  // Simulation-only checks (the benches define PREE_ASSERT): valid_q stays a thermometer code
  // and a valid entry never has rem = 0.
  integer a;
  always @(posedge clk_i or negedge rst_ni) begin
    if (rst_ni) begin
      for (a = 1; a < BufDepth; a = a + 1)
        if (valid_q[a] && !valid_q[a-1]) $fatal(1, "pree_aftso_hpuoc: valid_q not a thermometer");
      for (a = 0; a < BufDepth; a = a + 1)
        if (valid_q[a] && rem_q[a*CntW +: CntW] == {CntW{1'b0}}) $fatal(1, "pree_aftso_hpuoc: empty entry");
    end
  end
`endif

endmodule

`default_nettype wire
