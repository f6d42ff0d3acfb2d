// SPDX-License-Identifier: Apache-2.0
// pree_faxis: the AXI4-Stream rules (ARM IHI 0051A, Sec. 2.2 and 2.7) as a property module for
// SymbiYosys, instantiated beside a stream port in a formal harness (formal/*/).
//
// Source rules: TVALID low while ARESETn is low and in the first cycle after it rises; once
// TVALID is high it stays high until the beat is taken (TVALID && TREADY at a rising edge), and
// TDATA, TLAST, TKEEP and TUSER hold their values while the beat waits. The sink has no rule:
// TREADY may wait for TVALID and may fall at any time.
// SrcIsDut 1: the design drives the source side, so its rules are asserted; MaxStall > 0 then
// assumes a fair sink, which takes a waiting beat within MaxStall cycles. SrcIsDut 0: the
// environment is the source and its rules are assumed (the design is the sink).
// f_stall_o counts the cycles the present beat has waited (0 when no beat waits), for the
// harness's bounded-response properties and induction invariants. Ports absent from a stream
// are tied to a constant by the harness (width 1).
`default_nettype none

module pree_faxis #(
  parameter DataW    = 8,
  parameter KeepW    = 1,
  parameter UserW    = 1,
  parameter SrcIsDut = 1,
  parameter MaxStall = 0,
  parameter CntW     = 8
) (
  input  wire             clk_i,
  input  wire             rst_ni,
  input  wire             tvalid,
  input  wire             tready,
  input  wire [DataW-1:0] tdata,
  input  wire             tlast,
  input  wire [KeepW-1:0] tkeep,
  input  wire [UserW-1:0] tuser,
  output reg  [CntW-1:0]  f_stall_o
);

  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;

  // A source rule: asserted when the design is the source, else assumed.
`define PREE_FAXIS_SRC(x) if (SrcIsDut != 0) assert (x); else assume (x)

  // Reset: no beat while in reset or in the first cycle after it.
  always @* if (!f_past_valid || !rst_ni) `PREE_FAXIS_SRC(!tvalid);
  always @(posedge clk_i)
    if (f_past_valid && !$past(rst_ni)) `PREE_FAXIS_SRC(!tvalid);

  // A waiting beat stays, unchanged, until it is taken.
  always @(posedge clk_i)
    if (f_past_valid && $past(rst_ni) && rst_ni && $past(tvalid && !tready)) begin
      `PREE_FAXIS_SRC(tvalid);
      `PREE_FAXIS_SRC(tdata == $past(tdata));
      `PREE_FAXIS_SRC(tlast == $past(tlast));
      `PREE_FAXIS_SRC(tkeep == $past(tkeep));
      `PREE_FAXIS_SRC(tuser == $past(tuser));
    end
`undef PREE_FAXIS_SRC

  // Cycles the present beat has waited; a fair sink bounds them.
  initial f_stall_o = {CntW{1'b0}};
  always @(posedge clk_i)
    if (!rst_ni || !tvalid || tready) f_stall_o <= {CntW{1'b0}};
    else if (f_stall_o != {CntW{1'b1}}) f_stall_o <= f_stall_o + 1'b1;
  generate
    if (SrcIsDut != 0 && MaxStall > 0) begin : g_fair_sink
      always @* assume (f_stall_o < MaxStall);
    end
  endgenerate

endmodule

`default_nettype wire
