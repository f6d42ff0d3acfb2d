// SPDX-License-Identifier: Apache-2.0
// pree_reset_sync: reset synchroniser, asynchronous assertion and synchronous de-assertion.
//
// rst_no goes low as soon as arst_ni goes low (no clock needed) and goes high on the Stages-th
// rising edge of clk_i after arst_ni has gone high, so the de-assertion of every flop reset by
// rst_no meets recovery and removal timing in clk_i's domain. Use one per clock domain, with the
// domain's clock; feed the raw reset (a button, a PLL's locked output, an AXI aresetn from
// another domain) into arst_ni.
//
// The flops carry ASYNC_REG (Vivado: placed together, no SRL extraction, treated as a
// synchroniser in CDC reports); constraints/pree_axi.xdc adds a false path into their clear pin.
// Parameters: Stages >= 2 synchronising flops (2 is enough below about 500 MHz in 7-series and
// UltraScale parts; 3 for faster clocks or a lower MTBF target).
`default_nettype none

module pree_reset_sync #(
  parameter Stages = 2
) (
  input  wire clk_i,
  input  wire arst_ni,    // asynchronous, active low
  output wire rst_no      // active low: asserted asynchronously, released on clk_i
);

  (* ASYNC_REG = "TRUE" *) reg [Stages-1:0] sync_q;

  generate
    if (Stages < 2) begin : g_bad_stages
      pree_reset_sync_needs_two_stages u_fail ();
    end
  endgenerate

  always @(posedge clk_i or negedge arst_ni) begin
    if (!arst_ni) sync_q <= {Stages{1'b0}};
    else          sync_q <= {sync_q[Stages-2:0], 1'b1};
  end

  assign rst_no = sync_q[Stages-1];

endmodule

`default_nettype wire
