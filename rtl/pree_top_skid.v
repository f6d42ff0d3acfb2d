// pree_top_skid: pree_top's stage-B skid slot (PipeFast 1; docs/fpga.md, "B's skid slot").
// What B leaves after a cycle's issue moves, with the lanes' records, into the slot, which issues
// first: so A reads when the slot is empty, a register, instead of when B empties in this cycle.
// The records are those of R, the lanes at the RAM outputs: update, the index entry and the
// photon; radiance, the hit-point data {const, state}. Skid = 0 gives an empty slot and no logic.
`default_nettype none

module pree_top_skid #(
  parameter Skid    = 1,    // 1 the slot, 0 none
  parameter NumPreu = 4,    // lanes
  parameter HpAW    = 18,   // index entry (hit-point address) bits
  parameter PhW     = 192,  // photon bits
  parameter ConstW  = 209,  // hit-point constant part {pixel, f, pos}
  parameter StateW  = 160   // hit-point state
) (
  input  wire                      clk_i,
  input  wire                      rst_ni,
  input  wire                      mode_i,   // 0 update, 1 radiance
  input  wire [NumPreu-1:0]        r_pend_i, // R's pending lanes and short flag
  input  wire                      r_short_i,
  input  wire [NumPreu*HpAW-1:0]   r_hp_i,   // R's records: update
  input  wire [NumPreu*PhW-1:0]    r_ph_i,
  input  wire [NumPreu*ConstW-1:0] r_hc_i,   // radiance
  input  wire [NumPreu*StateW-1:0] r_hs_i,
  input  wire [NumPreu-1:0]        iss_i,    // B's issue in this cycle
  output wire                      full_o,   // the slot holds lanes: B's live lanes are its own
  output wire [NumPreu-1:0]        pend_o,
  output wire                      short_o,
  output reg  [NumPreu*HpAW-1:0]   hp_o,     // the slot's records, unpacked as R's
  output reg  [NumPreu*PhW-1:0]    ph_o,
  output reg  [NumPreu*ConstW-1:0] hc_o,
  output reg  [NumPreu*StateW-1:0] hs_o
);

  // A lane's record in the slot: the update or the radiance fields, whichever is wider.
  localparam REC_W = (HpAW + PhW > ConstW + StateW) ? HpAW + PhW : ConstW + StateW;

  wire [NumPreu*REC_W-1:0] rec;

  always @* begin : unpack
    integer l;
    for (l = 0; l < NumPreu; l = l + 1) begin
      {hp_o[l*HpAW +: HpAW], ph_o[l*PhW +: PhW]}             = rec[l*REC_W +: HpAW + PhW];
      {hc_o[l*ConstW +: ConstW], hs_o[l*StateW +: StateW]} = rec[l*REC_W +: ConstW + StateW];
    end
  end

  generate
    if (Skid != 0) begin : g_skid
      reg                       full_q, short_q;
      reg  [NumPreu-1:0]        pend_q;
      reg  [NumPreu*REC_W-1:0]  rec_q;
      // What B leaves after this cycle's issue: the slot's own lanes, or R's (then copied).
      wire [NumPreu-1:0]        left = (full_q ? pend_q : r_pend_i) & ~iss_i;
      reg  [NumPreu*REC_W-1:0]  r_rec;
      always @* begin : r_lanes
        integer l;
        for (l = 0; l < NumPreu; l = l + 1) begin
          r_rec[l*REC_W +: REC_W] = {REC_W{1'b0}};
          if (mode_i)
            r_rec[l*REC_W +: ConstW + StateW] = {r_hc_i[l*ConstW +: ConstW], r_hs_i[l*StateW +: StateW]};
          else
            r_rec[l*REC_W +: HpAW + PhW]      = {r_hp_i[l*HpAW +: HpAW], r_ph_i[l*PhW +: PhW]};
        end
      end
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          full_q <= 1'b0;
          pend_q <= {NumPreu{1'b0}};
        end else begin
          full_q <= |left;
          pend_q <= left;
        end
      end
      always @(posedge clk_i) begin
        if (!full_q) begin
          rec_q   <= r_rec;
          short_q <= r_short_i;
        end
      end
      assign full_o  = full_q;
      assign pend_o  = pend_q;
      assign short_o = short_q;
      assign rec     = rec_q;
    end else begin : g_no_skid
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused = &{1'b0, clk_i, rst_ni, mode_i, r_pend_i, r_short_i, r_hp_i, r_ph_i, r_hc_i,
                      r_hs_i, iss_i};
      /* verilator lint_on UNUSEDSIGNAL */
      assign full_o  = 1'b0;
      assign pend_o  = {NumPreu{1'b0}};
      assign short_o = 1'b0;
      genvar gl;
      for (gl = 0; gl < NumPreu; gl = gl + 1) begin : g_rec   // (lane by lane: under 8k bits)
        assign rec[gl*REC_W +: REC_W] = {REC_W{1'b0}};
      end
    end
  endgenerate

endmodule

`default_nettype wire
