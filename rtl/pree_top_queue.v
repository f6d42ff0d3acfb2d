// SPDX-License-Identifier: Apache-2.0
// pree_top_queue: pree_top's stage-B queue (PipeFast 1; docs/pree_top.md, "Pipeline, memories
// and hazards"). What A read (R, the lanes at the RAM outputs) moves into one of two slots, and B
// issues from the older slot (the head) only, so every input of the issue is a flip-flop: the
// lanes' keys, banks and records, and their hazard, precomputed a cycle ahead.
//
// Flow: R moves into the head slot when it is empty, else into the other slot when that is empty,
// else it waits (its RAMs hold their outputs: A does not read). A reads when R is empty or moves
// (go_o: from registers only). The head passes to the other slot once its lanes have all issued.
//
// Hazard (the issue's in-flight test, pree_top_issue's window inf_*_i of keys issued in the last
// WinUpd cycles, slot 0 the newest): for each lane a slot holds, P[s] (s = 1 .. WinUpd-1) says
// whether its key was issued s + 1 cycles ago, and E[m] whether it equals the key of the head's
// lane m in the last cycle. In the issue cycle, hazard = the OR of P within the window (kept as
// a few group ORs) OR (E[m] and lane m issued last cycle). Each cycle P shifts by one with the
// last cycle's match entering at P[1]; a lane that moves in from R gets P from a comparison of
// its key with the whole window. The radiance window is the first WinRad slots.
// Slots = 0 passes R through (PipeFast 0: B issues from R and compares in pree_top_issue).
`default_nettype none

module pree_top_queue #(
  parameter Slots   = 1,    // 1 the two slots, 0 none
  parameter NumPreu = 4,    // lanes
  parameter KeyW    = 18,   // hazard key: hit point (update) or pixel (radiance)
  parameter BankW   = 4,    // a lane's bank number
  parameter RecW    = 400,  // a lane's record (update: index entry, photon; radiance: hit point)
  parameter WinUpd  = 11,   // the update window (cycles)
  parameter WinRad  = 3     // the radiance window (<= WinUpd)
) (
  input  wire                            clk_i,
  input  wire                            rst_ni,
  input  wire                            mode_i,   // 0 update, 1 radiance
  // R: the lanes A read last.
  input  wire [NumPreu-1:0]              r_pend_i,
  input  wire                            r_short_i,
  input  wire [NumPreu*KeyW-1:0]         r_key_i,
  input  wire [NumPreu*BankW-1:0]        r_bank_i,
  input  wire [NumPreu*RecW-1:0]         r_rec_i,
  // The issue of this cycle and the in-flight window (pree_top_issue).
  input  wire [NumPreu-1:0]              iss_i,
  input  wire [WinUpd*NumPreu-1:0]       inf_v_i,
  input  wire [WinUpd*NumPreu*KeyW-1:0]  inf_k_i,
  output wire                            go_o,     // A may read (Slots = 1)
  // The lanes B issues from: the head slot's (Slots = 0: R's).
  output wire [NumPreu-1:0]              pend_o,
  output wire                            short_o,
  output wire [NumPreu*KeyW-1:0]         key_o,
  output wire [NumPreu*BankW-1:0]        bank_o,
  output wire [NumPreu*RecW-1:0]         rec_o,
  output wire [NumPreu-1:0]              haz_o,    // precomputed hazard (Slots = 1)
  output wire [NumPreu*NumPreu-1:0]      keq_o,    // [m*NumPreu + l]: lanes m and l, same key
  output wire [NumPreu*NumPreu-1:0]      beq_o     // ... same bank
);

  localparam PW = WinUpd - 1;                              // P[1 .. WinUpd-1]
  localparam GS = (36 / NumPreu) > 0 ? 36 / NumPreu : 1;   // window slots per group OR
  localparam NG = (PW + GS - 1) / GS;                      // group ORs per lane

  generate
    if (Slots != 0) begin : g_slots
      // Slot k's fields are [k*W +: W] of each vector.
      reg  [2*NumPreu-1:0]         pend_q;
      reg  [1:0]                   short_q;
      reg  [2*NumPreu*KeyW-1:0]    key_q;
      reg  [2*NumPreu*BankW-1:0]   bank_q;
      reg  [2*NumPreu*RecW-1:0]    rec_q;
      reg  [2*NumPreu*NumPreu-1:0] keq_q, beq_q, e_q;
      reg  [2*NumPreu*PW-1:0]      p_q;
      reg  [2*NumPreu*NG-1:0]      g_q;
      reg                          head_q;
      wire [2*NumPreu-1:0]         haz;

      wire [NumPreu-1:0]      live_pend = head_q ? pend_q[NumPreu +: NumPreu]
                                                 : pend_q[0 +: NumPreu];
      wire [NumPreu*KeyW-1:0] live_key  = head_q ? key_q[NumPreu*KeyW +: NumPreu*KeyW]
                                                 : key_q[0 +: NumPreu*KeyW];
      wire head_free  = ~|live_pend;
      wire other_free = ~|(head_q ? pend_q[0 +: NumPreu] : pend_q[NumPreu +: NumPreu]);
      wire r_valid    = |r_pend_i;
      wire [1:0] load;   // R moves into slot k
      assign load[0] = r_valid && (head_q ? (!head_free && other_free) : head_free);
      assign load[1] = r_valid && (head_q ? head_free : (!head_free && other_free));
      assign go_o = !r_valid || head_free || other_free;

      // R's lanes, for a lane that moves in: P[s] = its key was issued in window slot s - 1 now;
      // E[m] = it equals the head's lane m; the pairs among R's lanes.
      reg [NumPreu*PW-1:0]      r_p;
      reg [NumPreu*NumPreu-1:0] r_e, r_keq, r_beq;
      always @* begin : r_cmp
        integer l, m, s;
        for (l = 0; l < NumPreu; l = l + 1) begin
          for (s = 1; s <= PW; s = s + 1) begin
            r_p[l*PW + s - 1] = 1'b0;
            for (m = 0; m < NumPreu; m = m + 1)
              if (inf_v_i[(s-1)*NumPreu + m] &&
                  inf_k_i[((s-1)*NumPreu + m)*KeyW +: KeyW] == r_key_i[l*KeyW +: KeyW])
                r_p[l*PW + s - 1] = 1'b1;
          end
          for (m = 0; m < NumPreu; m = m + 1) begin
            r_e[l*NumPreu + m]   = live_key[m*KeyW +: KeyW] == r_key_i[l*KeyW +: KeyW];
            r_keq[m*NumPreu + l] = r_key_i[m*KeyW +: KeyW] == r_key_i[l*KeyW +: KeyW];
            r_beq[m*NumPreu + l] = r_bank_i[m*BankW +: BankW] == r_bank_i[l*BankW +: BankW];
          end
        end
      end

      // Each slot: its lanes' hazard in this cycle, and their terms for the next one.
      genvar gk;
      for (gk = 0; gk < 2; gk = gk + 1) begin : g_slot
        localparam HEAD = (gk != 0) ? 1'b1 : 1'b0;
        wire [NumPreu*KeyW-1:0]    key = key_q[gk*NumPreu*KeyW +: NumPreu*KeyW];
        wire [NumPreu*PW-1:0]      p   = p_q[gk*NumPreu*PW +: NumPreu*PW];
        wire [NumPreu*NG-1:0]      g   = g_q[gk*NumPreu*NG +: NumPreu*NG];
        wire [NumPreu*NumPreu-1:0] e   = e_q[gk*NumPreu*NumPreu +: NumPreu*NumPreu];
        reg  [NumPreu-1:0]         cmp0;    // the key was issued in the last cycle
        reg  [NumPreu-1:0]         h;
        reg  [NumPreu*PW-1:0]      p_nx;
        reg  [NumPreu*NG-1:0]      g_nx;
        reg  [NumPreu*NumPreu-1:0] e_nx;
        always @* begin : terms
          integer l, m, s;
          for (l = 0; l < NumPreu; l = l + 1) begin
            cmp0[l] = 1'b0;
            for (m = 0; m < NumPreu; m = m + 1)
              if (inf_v_i[m] && e[l*NumPreu + m]) cmp0[l] = 1'b1;
            h[l] = cmp0[l] | (|g[l*NG +: NG]);
            // Next cycle's P: R's comparison for a lane that moves in, else shifted by one.
            for (s = 1; s <= PW; s = s + 1)
              if (load[gk])    p_nx[l*PW + s - 1] = r_p[l*PW + s - 1];
              else if (s == 1) p_nx[l*PW]         = cmp0[l];
              else             p_nx[l*PW + s - 1] = p[l*PW + s - 2];
            for (s = 0; s < NG; s = s + 1)
              g_nx[l*NG + s] = 1'b0;
            for (s = 1; s <= PW; s = s + 1)
              if ((!mode_i || s < WinRad) && p_nx[l*PW + s - 1]) g_nx[l*NG + (s - 1) / GS] = 1'b1;
            for (m = 0; m < NumPreu; m = m + 1)
              e_nx[l*NumPreu + m] = load[gk] ? r_e[l*NumPreu + m]
                                             : live_key[m*KeyW +: KeyW] == key[l*KeyW +: KeyW];
          end
        end
        assign haz[gk*NumPreu +: NumPreu] = h;

        always @(posedge clk_i or negedge rst_ni) begin
          if (!rst_ni)            pend_q[gk*NumPreu +: NumPreu] <= {NumPreu{1'b0}};
          else if (load[gk])      pend_q[gk*NumPreu +: NumPreu] <= r_pend_i;
          else if (head_q == HEAD) pend_q[gk*NumPreu +: NumPreu] <= pend_q[gk*NumPreu +: NumPreu]
                                                                    & ~iss_i;
        end
        always @(posedge clk_i) begin
          if (load[gk]) begin
            short_q[gk]                              <= r_short_i;
            key_q[gk*NumPreu*KeyW +: NumPreu*KeyW]   <= r_key_i;
            bank_q[gk*NumPreu*BankW +: NumPreu*BankW] <= r_bank_i;
            rec_q[gk*NumPreu*RecW +: NumPreu*RecW]   <= r_rec_i;
            keq_q[gk*NumPreu*NumPreu +: NumPreu*NumPreu] <= r_keq;
            beq_q[gk*NumPreu*NumPreu +: NumPreu*NumPreu] <= r_beq;
          end
          p_q[gk*NumPreu*PW +: NumPreu*PW]           <= p_nx;
          g_q[gk*NumPreu*NG +: NumPreu*NG]           <= g_nx;
          e_q[gk*NumPreu*NumPreu +: NumPreu*NumPreu] <= e_nx;
        end
      end

      // The head passes on once its lanes have all issued.
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) head_q <= 1'b0;
        else if (!head_free && (live_pend & ~iss_i) == {NumPreu{1'b0}}) head_q <= ~head_q;
      end

      assign pend_o  = live_pend;
      assign short_o = head_q ? short_q[1] : short_q[0];
      assign key_o   = live_key;
      assign bank_o  = head_q ? bank_q[NumPreu*BankW +: NumPreu*BankW] : bank_q[0 +: NumPreu*BankW];
      assign rec_o   = head_q ? rec_q[NumPreu*RecW +: NumPreu*RecW] : rec_q[0 +: NumPreu*RecW];
      assign haz_o   = head_q ? haz[NumPreu +: NumPreu] : haz[0 +: NumPreu];
      assign keq_o   = head_q ? keq_q[NumPreu*NumPreu +: NumPreu*NumPreu]
                              : keq_q[0 +: NumPreu*NumPreu];
      assign beq_o   = head_q ? beq_q[NumPreu*NumPreu +: NumPreu*NumPreu]
                              : beq_q[0 +: NumPreu*NumPreu];
    end else begin : g_pass
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused = &{1'b0, clk_i, rst_ni, mode_i, iss_i, inf_v_i, inf_k_i};
      /* verilator lint_on UNUSEDSIGNAL */
      assign go_o    = 1'b1;
      assign pend_o  = r_pend_i;
      assign short_o = r_short_i;
      assign key_o   = r_key_i;
      assign bank_o  = r_bank_i;
      assign rec_o   = r_rec_i;
      assign haz_o   = {NumPreu{1'b0}};
      assign keq_o   = {NumPreu*NumPreu{1'b0}};
      assign beq_o   = {NumPreu*NumPreu{1'b0}};
    end
  endgenerate

endmodule

`default_nettype wire
