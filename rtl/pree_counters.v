// SPDX-License-Identifier: Apache-2.0
// pree_counters: pree_top's performance counters (its cnt_o; docs/pree_top.md), CtrW bits each,
// counting only while en_i is high, in order: 0 update cycles, 1 radiance cycles, then the cycles
// in which fewer than NumPreu operations issued, by cause: 2 haz, 3 dup, 4 bank (the first
// pending lane of stage B that did not issue, by its reason), else 5 abank (stage A left lanes
// for a bank conflict, short_i) or 6 starve (the controller offered fewer); then 7 + l: the
// operations into PREU l. Reset: asynchronous, active low, clears every counter. InReg = 1
// (PipeFast 1): the inputs are registered first, so a cycle counts one clock later.
`default_nettype none

module pree_counters #(
  parameter NumPreu = 4,
  parameter CtrW    = 48,
  parameter InReg   = 0    // 1: register the inputs (a cycle counts one clock later)
) (
  input  wire                         clk_i,
  input  wire                         rst_ni,
  input  wire                         en_i,
  input  wire                         mode_i,    // 0 update, 1 radiance
  input  wire [NumPreu-1:0]           pend_i,    // stage B's pending lanes
  input  wire [NumPreu-1:0]           iss_i,     // the lanes that issue this cycle
  input  wire [NumPreu-1:0]           haz_i,     // a lane's key is in flight
  input  wire [NumPreu-1:0]           dup_i,     // an earlier pending lane has the same key
  input  wire                         short_i,   // stage A left lanes for a bank conflict
  input  wire [NumPreu-1:0]           op_i,      // an operation enters PREU l
  output wire [(7+NumPreu)*CtrW-1:0]  cnt_o
);

  localparam [CtrW-1:0] ONE = 1;
  localparam IN_W = 3 + 5 * NumPreu;   // the inputs but the clock and reset

  // The inputs as counted: as they come (InReg = 0) or a clock later.
  wire                en, mode, short;
  wire [NumPreu-1:0]  pend, iss, haz, dup, op;
  generate
    if (InReg != 0) begin : g_in_reg
      reg [IN_W-1:0] in_q;
      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) in_q <= {IN_W{1'b0}};
        else         in_q <= {en_i, mode_i, short_i, pend_i, iss_i, haz_i, dup_i, op_i};
      end
      assign {en, mode, short, pend, iss, haz, dup, op} = in_q;
    end else begin : g_in
      assign {en, mode, short, pend, iss, haz, dup, op} =
             {en_i, mode_i, short_i, pend_i, iss_i, haz_i, dup_i, op_i};
    end
  endgenerate

  reg [(7+NumPreu)*CtrW-1:0] cnt_q;
  reg [2:0]                  cause;    // 0 none, 2 haz, 3 dup, 4 bank, 5 abank, 6 starve
  reg                        found;
  always @* begin : stall_cause
    integer l;
    cause = 3'd0;
    found = 1'b0;
    for (l = 0; l < NumPreu; l = l + 1)
      if (!found && pend[l] && !iss[l]) begin
        found = 1'b1;
        cause = haz[l] ? 3'd2 : dup[l] ? 3'd3 : 3'd4;
      end
    if (iss != {NumPreu{1'b1}} && !found) cause = short ? 3'd5 : 3'd6;
  end

  always @(posedge clk_i or negedge rst_ni) begin : counters
    integer l;
    if (!rst_ni) begin
      cnt_q <= {(7+NumPreu)*CtrW{1'b0}};
    end else if (en) begin
      if (mode) cnt_q[1*CtrW +: CtrW] <= cnt_q[1*CtrW +: CtrW] + ONE;
      else        cnt_q[0 +: CtrW]       <= cnt_q[0 +: CtrW] + ONE;
      for (l = 2; l < 7; l = l + 1)
        if (cause == l[2:0]) cnt_q[l*CtrW +: CtrW] <= cnt_q[l*CtrW +: CtrW] + ONE;
      for (l = 0; l < NumPreu; l = l + 1)
        if (op[l]) cnt_q[(7+l)*CtrW +: CtrW] <= cnt_q[(7+l)*CtrW +: CtrW] + ONE;
    end
  end
  assign cnt_o = cnt_q;

endmodule
