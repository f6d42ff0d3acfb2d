// SPDX-License-Identifier: Apache-2.0
// pree_top_read: pree_top's stage A (docs/pree_top.md, "Pipeline, memories and hazards"). The
// controller's offer is read in lane order, one lane per bank a cycle: a lane whose bank an
// earlier unread lane of the offer uses waits (a bank conflict), and so does every later lane.
// It keeps which lanes of the current offer are read (the controller moves on once all are),
// and counts the photons whose last index entry has been read (photons_done_o, wrapping).
`default_nettype none

module pree_top_read #(
  parameter NumPreu = 4,   // lanes
  parameter BankW   = 4,   // bits of a lane's bank number
  parameter CountW  = 32   // bits of photons_done_o (it wraps)
) (
  input  wire                     clk_i,
  input  wire                     rst_ni,
  input  wire                     go_i,          // A may read in this cycle
  input  wire [NumPreu-1:0]       valid_i,       // the offer's lanes
  input  wire [NumPreu*BankW-1:0] bank_i,        // each lane's bank
  input  wire [NumPreu-1:0]       last_i,        // the lane is its photon's last index entry
  input  wire                     count_last_i,  // count last_i (update mode)
  output reg  [NumPreu-1:0]       rd_o,          // lanes read in this cycle
  output wire                     all_o,         // every lane of the offer is read by now
  output wire                     short_o,       // A read, but left lanes (a bank conflict)
  output wire [CountW-1:0]        photons_done_o
);

  reg  [NumPreu-1:0] done_q;   // lanes of the current offer read in earlier cycles
  wire [NumPreu-1:0] pend = valid_i & ~done_q;
  reg  [NumPreu-1:0] conf;
  reg                pre;

  always @* begin : lanes
    integer l, m;
    pre = 1'b1;
    for (l = 0; l < NumPreu; l = l + 1) begin
      conf[l] = 1'b0;
      for (m = 0; m < l; m = m + 1)
        if (pend[m] && bank_i[m*BankW +: BankW] == bank_i[l*BankW +: BankW])
          conf[l] = 1'b1;
      rd_o[l] = go_i && pend[l] && !conf[l] && pre;
      pre     = pre && (!pend[l] || rd_o[l]);
    end
  end

  assign all_o   = &(~valid_i | done_q | rd_o);
  assign short_o = go_i && |(pend & ~rd_o);

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni)    done_q <= {NumPreu{1'b0}};
    else if (all_o) done_q <= {NumPreu{1'b0}};
    else            done_q <= done_q | rd_o;
  end

  // Photons whose last index entry has been read.
  reg [CountW-1:0] photons_done_q;
  reg [CountW-1:0] last_rd;
  always @* begin : last_count
    integer l;
    last_rd = {CountW{1'b0}};
    for (l = 0; l < NumPreu; l = l + 1)
      if (rd_o[l] && last_i[l] && count_last_i) last_rd = last_rd + 1'b1;
  end
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) photons_done_q <= {CountW{1'b0}};
    else         photons_done_q <= photons_done_q + last_rd;
  end
  assign photons_done_o = photons_done_q;

endmodule

`default_nettype wire
