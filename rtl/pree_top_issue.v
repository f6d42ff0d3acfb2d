// SPDX-License-Identifier: Apache-2.0
// pree_top_issue: pree_top's stage-B issue (docs/pree_top.md, "Pipeline, memories and hazards").
// Each cycle a prefix of the pending lanes issues, each free of a hazard (its key issued in the
// last WinUpd cycles, update mode, or WinRad, radiance), of an earlier pending lane with the same
// key (dup) and of one with the same bank (bank conflict). The in-flight window, the keys issued
// in each of the last WinUpd cycles, is held here. Pre = 1 (PipeFast 1): the hazard and the lane
// pairs' key and bank equality come precomputed from registers (pree_top_queue, which reads the
// window), so that the issue starts from flip-flops.
`default_nettype none

module pree_top_issue #(
  parameter NumPreu = 4,   // lanes
  parameter KeyW    = 18,  // hazard key: hit point (update) or pixel (radiance)
  parameter BankW   = 4,   // bits of a lane's bank number
  parameter WinUpd  = 11,  // cycles a key stays in flight, update mode
  parameter WinRad  = 3,   // the same, radiance (<= WinUpd)
  parameter Pre     = 0    // 1: the hazard and the pairs from haz_i, keq_i, beq_i
) (
  input  wire                     clk_i,
  input  wire                     rst_ni,
  input  wire                     mode_i,   // 0 update, 1 radiance
  input  wire [NumPreu-1:0]       pend_i,   // the pending lanes
  input  wire [NumPreu*KeyW-1:0]  key_i,
  input  wire [NumPreu*BankW-1:0] bank_i,
  input  wire [NumPreu-1:0]       haz_i,    // Pre: the lane's key is in flight
  input  wire [NumPreu*NumPreu-1:0] keq_i,  // Pre: [m*NumPreu + l]: lanes m < l have the same key
  input  wire [NumPreu*NumPreu-1:0] beq_i,  // Pre: ... the same bank
  output wire [WinUpd*NumPreu-1:0]      inf_v_o,  // the window (for pree_top_queue)
  output wire [WinUpd*NumPreu*KeyW-1:0] inf_k_o,
  output reg  [NumPreu-1:0]       iss_o,    // lanes that issue in this cycle
  output reg  [NumPreu-1:0]       haz_o,    // why a lane waits: a hazard, an earlier lane with
  output reg  [NumPreu-1:0]       dup_o     // the same key (else bcf: with the same bank)
);

  // In-flight window: the keys issued in each of the last WinUpd cycles (newest first).
  reg [WinUpd*NumPreu-1:0]      inf_v_q;
  reg [WinUpd*NumPreu*KeyW-1:0] inf_k_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) inf_v_q <= {WinUpd*NumPreu{1'b0}};
    else         inf_v_q <= {inf_v_q[0 +: (WinUpd-1)*NumPreu], iss_o};
  end
  always @(posedge clk_i) begin
    inf_k_q <= {inf_k_q[0 +: (WinUpd-1)*NumPreu*KeyW], key_i};
  end

  assign inf_v_o = inf_v_q;
  assign inf_k_o = inf_k_q;

  reg [NumPreu-1:0] bcf;
  reg               pre, keq, beq;
  always @* begin : issue
    integer l, m, s;
    pre = 1'b1;
    for (l = 0; l < NumPreu; l = l + 1) begin
      haz_o[l] = Pre != 0 && haz_i[l];
      dup_o[l] = 1'b0;
      bcf[l]   = 1'b0;
      if (Pre == 0)
        for (s = 0; s < WinUpd; s = s + 1)
          for (m = 0; m < NumPreu; m = m + 1)
            if ((s < WinRad || !mode_i) && inf_v_q[s*NumPreu + m] &&
                inf_k_q[(s*NumPreu + m)*KeyW +: KeyW] == key_i[l*KeyW +: KeyW])
              haz_o[l] = 1'b1;
      for (m = 0; m < l; m = m + 1) begin
        keq = (Pre != 0) ? keq_i[m*NumPreu + l]
                         : key_i[m*KeyW +: KeyW] == key_i[l*KeyW +: KeyW];
        beq = (Pre != 0) ? beq_i[m*NumPreu + l]
                         : bank_i[m*BankW +: BankW] == bank_i[l*BankW +: BankW];
        if (pend_i[m]) begin
          if (keq) dup_o[l] = 1'b1;
          else if (beq) bcf[l] = 1'b1;
        end
      end
      iss_o[l] = pend_i[l] && pre && !haz_o[l] && !dup_o[l] && !bcf[l];
      pre      = pre && (!pend_i[l] || iss_o[l]);
    end
  end

endmodule

`default_nettype wire
