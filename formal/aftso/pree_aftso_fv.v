// SPDX-License-Identifier: Apache-2.0
// pree_aftso_fv: the formal harness of pree_aftso_hpuoc (jobs formal/aftso*; docs/formal.md).
//
// A shadow of the photons the dispatcher holds, in arrival order, each with its data, id, p_addr
// and N^P, and the number of the oldest one's operations already dispatched. Photon k's
// operations are, in order, ref_addr p + N - 1, p + N - 2, ..., p (the last marked lane_last);
// the photons' operations one after the other form one sequence. In every cycle the lanes must
// offer the next min(total, NumPreu) operations of that sequence, lane 0 first (lane_valid a
// thermometer), with their address, data, id and last flag, zeros on invalid lanes; when the
// offer is taken (stall_i low) they leave the shadow. So no operation is lost, duplicated or
// reordered, and each is correct. empty_o is high exactly when the shadow is empty; the intake
// never takes more photons than the buffer holds.
// For the induction, the buffer's registers are mapped onto the shadow (taps.ys connects the
// f_t_* wires to them): entry e valid exactly for the shadow's first entries, its accuHP the
// operations left up to and including it, its flags accuHP's, ref_q the address lane 0 would
// take from it, its data and id the shadow's.
`default_nettype none

module pree_aftso_fv #(
  parameter NumPreu  = 4,
  parameter BufDepth = 4,
  parameter DataW    = 2,
  parameter IdW      = 2,
  parameter AddrW    = 4,
  parameter CntW     = 3,
  parameter PhotonsPerCycle = 1
) (
  input wire clk_i,
  input wire rst_ni,
  input wire in_valid_i,
  input wire [PhotonsPerCycle*DataW-1:0] in_data_i,
  input wire [PhotonsPerCycle*IdW-1:0]   in_id_i,
  input wire [PhotonsPerCycle*AddrW-1:0] in_p_addr_i,
  input wire [PhotonsPerCycle*CntW-1:0]  in_n_i,
  input wire stall_i
);

  localparam PPC   = PhotonsPerCycle;
  localparam ACC_W0 = CntW + $clog2(BufDepth) + 1;
  localparam ACC_W  = ACC_W0 > $clog2(NumPreu) + 2 ? ACC_W0 : $clog2(NumPreu) + 2;
  localparam NF    = NumPreu + 1;
  localparam SW    = ACC_W + 1;        // shadow sums

  wire                     in_ready, busy, empty;
  wire [NumPreu-1:0]       lane_valid, lane_last;
  wire [NumPreu*AddrW-1:0] lane_ref;
  wire [NumPreu*DataW-1:0] lane_data;
  wire [NumPreu*IdW-1:0]   lane_id;

  pree_aftso_hpuoc #(
    .NumPreu(NumPreu), .BufDepth(BufDepth), .DataW(DataW), .IdW(IdW), .AddrW(AddrW),
    .CntW(CntW), .EarlyReady(1), .PhotonsPerCycle(PPC)
  ) u_dut (
    .clk_i(clk_i), .rst_ni(rst_ni), .in_valid_i(in_valid_i), .in_ready_o(in_ready),
    .in_data_i(in_data_i), .in_id_i(in_id_i), .in_p_addr_i(in_p_addr_i), .in_n_i(in_n_i),
    .stall_i(stall_i), .lane_valid_o(lane_valid), .lane_ref_addr_o(lane_ref),
    .lane_data_o(lane_data), .lane_id_o(lane_id), .lane_last_o(lane_last),
    .busy_o(busy), .empty_o(empty));

  initial assume (!rst_ni);

  // Taps (taps.ys): the buffer's registers.
  (* keep *) wire [BufDepth-1:0]       f_t_valid;
  (* keep *) wire [BufDepth*ACC_W-1:0] f_t_acc;
  (* keep *) wire [BufDepth*NF-1:0]    f_t_gt;
  (* keep *) wire [BufDepth*AddrW-1:0] f_t_ref;
  (* keep *) wire [ACC_W-1:0]          f_t_tq;
  (* keep *) wire [BufDepth*DataW-1:0] f_t_data;
  (* keep *) wire [BufDepth*IdW-1:0]   f_t_id;

  // ---------------------------------------------------------------------------------------------
  // The shadow: s_n photons; entry e: data, id, p_addr, N^P; s_head operations of entry 0 gone.
  reg [BufDepth*DataW-1:0] s_data;
  reg [BufDepth*IdW-1:0]   s_id;
  reg [BufDepth*AddrW-1:0] s_p;
  reg [BufDepth*CntW-1:0]  s_cnt;
  reg [3:0]       s_n;
  reg [CntW-1:0]  s_head;

  // The operations left up to and including entry e (cum, SW bits an entry); the total.
  reg [BufDepth*SW-1:0] cum;
  reg [SW-1:0] total;
  always @* begin : sums
    integer e;
    total = {SW{1'b0}};
    for (e = 0; e < BufDepth; e = e + 1) begin
      if (e < s_n) total = total + s_cnt[e*CntW +: CntW] - (e == 0 ? s_head : {CntW{1'b0}});
      cum[e*SW +: SW] = total;
    end
  end

  // The expected offer: lane l carries operation number l of the sequence.
  reg [NumPreu-1:0]       x_valid, x_last;
  reg [NumPreu*AddrW-1:0] x_ref;
  reg [NumPreu*DataW-1:0] x_data;
  reg [NumPreu*IdW-1:0]   x_id;
  always @* begin : expect
    integer l, e;
    reg [SW-1:0] before, k;
    x_valid = {NumPreu{1'b0}}; x_last = {NumPreu{1'b0}};
    x_ref = {(NumPreu*AddrW){1'b0}}; x_data = {(NumPreu*DataW){1'b0}}; x_id = {(NumPreu*IdW){1'b0}};
    for (l = 0; l < NumPreu; l = l + 1)
      for (e = 0; e < BufDepth; e = e + 1) begin
        before = (e == 0) ? {SW{1'b0}} : cum[((e == 0) ? 0 : e - 1)*SW +: SW];
        if (e < s_n && l >= before && l < cum[e*SW +: SW]) begin
          k = l - before + (e == 0 ? s_head : {CntW{1'b0}});     // operation k of photon e
          x_valid[l] = 1'b1;
          x_last[l]  = k == s_cnt[e*CntW +: CntW] - 1;
          x_ref[l*AddrW +: AddrW] = s_p[e*AddrW +: AddrW] + s_cnt[e*CntW +: CntW] - 1 - k;
          x_data[l*DataW +: DataW] = s_data[e*DataW +: DataW];
          x_id[l*IdW +: IdW] = s_id[e*IdW +: IdW];
        end
      end
  end

  // The offer is the expected one; empty_o is exact.
  always @* if (rst_ni) begin
    assert (lane_valid == x_valid);
    assert (lane_last == x_last);
    assert (lane_ref == x_ref);
    assert (lane_data == x_data);
    assert (lane_id == x_id);
    assert (empty == (s_n == 4'd0));
    assert (busy == !in_ready);
  end

  // The shadow's next state: the taken offer leaves, then the accepted photons (N^P > 0) arrive.
  always @(posedge clk_i) begin : step
    integer e, j, gone;
    reg [3:0] n;
    reg [SW-1:0] before;
    if (!rst_ni) begin
      s_n <= 4'd0; s_head <= {CntW{1'b0}};
    end else begin
      n = s_n;
      if (!stall_i) begin
        // Whole photons leave; the first one not whole keeps its remaining operations.
        gone = 0;
        for (e = 0; e < BufDepth; e = e + 1)
          if (e < s_n && gone == e && cum[e*SW +: SW] <= NumPreu) gone = e + 1;
        for (e = 0; e < BufDepth; e = e + 1) begin
          if (e + gone < BufDepth) begin
            s_data[e*DataW +: DataW] <= s_data[(e + gone)*DataW +: DataW]; s_id[e*IdW +: IdW] <= s_id[(e + gone)*IdW +: IdW];
            s_p[e*AddrW +: AddrW] <= s_p[(e + gone)*AddrW +: AddrW]; s_cnt[e*CntW +: CntW] <= s_cnt[(e + gone)*CntW +: CntW];
          end
        end
        n = s_n - gone;
        before = (gone == 0) ? {SW{1'b0}} : cum[((gone == 0) ? 0 : gone - 1)*SW +: SW];
        if (n == 0)         s_head <= {CntW{1'b0}};
        else if (gone == 0) s_head <= s_head + NumPreu;
        else                s_head <= NumPreu - before;
      end
      if (in_valid_i && in_ready)
        for (j = 0; j < PPC; j = j + 1)
          if (in_n_i[j*CntW +: CntW] != {CntW{1'b0}}) begin
            assert (n < BufDepth);        // the intake never overfills the buffer
            s_data[n*DataW +: DataW] <= in_data_i[j*DataW +: DataW]; s_id[n*IdW +: IdW] <= in_id_i[j*IdW +: IdW];
            s_p[n*AddrW +: AddrW] <= in_p_addr_i[j*AddrW +: AddrW]; s_cnt[n*CntW +: CntW] <= in_n_i[j*CntW +: CntW];
            n = n + 1;
          end
      s_n <= n;
    end
  end

  // ---------------------------------------------------------------------------------------------
  // The buffer mapped onto the shadow (induction strengthening).
  always @* if (rst_ni) begin : map
    integer e, f;
    reg [AddrW-1:0] r;
    assert (s_n <= BufDepth);
    if (s_n != 0) assert (s_head < s_cnt[0 +: CntW]);
    else          assert (s_head == {CntW{1'b0}});
    assert (f_t_tq == (total > NumPreu ? total - NumPreu : 0));
    for (e = 0; e < BufDepth; e = e + 1) begin
      assert (f_t_valid[e] == (e < s_n));
      assert (f_t_acc[e*ACC_W +: ACC_W] == cum[e*SW +: SW]);
      for (f = 0; f < NF; f = f + 1) assert (f_t_gt[e*NF + f] == (cum[e*SW +: SW] > f));
      if (e < s_n) begin
        assert (s_cnt[e*CntW +: CntW] != {CntW{1'b0}});
        r = s_p[e*AddrW +: AddrW] + cum[e*SW +: SW] - 1;     // modulo 2^AddrW
        assert (f_t_ref[e*AddrW +: AddrW] == r);
        assert (f_t_data[e*DataW +: DataW] == s_data[e*DataW +: DataW]);
        assert (f_t_id[e*IdW +: IdW] == s_id[e*IdW +: IdW]);
      end
    end
  end

  // ---------------------------------------------------------------------------------------------
  // Covers: a full buffer, a photon split across offers, a full offer, a stalled offer, the
  // intake taking a photon in the cycle a full buffer drains (EarlyReady), a lane_last on a
  // lane above 0, and an empty buffer again after work.
  reg f_worked = 1'b0;
  always @(posedge clk_i) if (rst_ni && !empty) f_worked <= 1'b1;
  always @* if (rst_ni) begin
    cover (s_n == BufDepth);
    cover (s_n != 0 && s_head != 0);
    cover (&lane_valid && !stall_i);
    cover (|lane_valid && stall_i);
    cover (s_n == BufDepth && in_valid_i && in_ready);
    cover (lane_last[NumPreu-1] && lane_last[0]);
    cover (f_worked && empty);
  end

endmodule

`default_nettype wire
