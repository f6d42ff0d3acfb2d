// SPDX-License-Identifier: Apache-2.0
// pree_fp32_div_steps: Steps iterations of restoring radix-2 significand division, combinational.
//
// One slice of the divider's array; pree_fp32_div places one slice in each pipeline stage.
// Invariant on entry and exit: 0 <= rem < 2 * den (den normalised, den[23] = 1), so each
// iteration produces one quotient bit q = (rem >= den), subtracts den when q is 1 and doubles
// the partial remainder. Quotient bits are shifted into quo from the right.
`default_nettype none

module pree_fp32_div_steps #(
  parameter Steps = 8
) (
  input  wire [24:0] rem_i,
  input  wire [23:0] den_i,
  input  wire [25:0] quo_i,
  output reg  [24:0] rem_o,
  output reg  [25:0] quo_o
);

  // diff[24] is never read: whenever the difference is kept (no borrow) it is below den < 2^24.
  /* verilator lint_off UNUSEDSIGNAL */
  reg [25:0] diff;
  /* verilator lint_on UNUSEDSIGNAL */
  integer    k;

  always @* begin
    rem_o = rem_i;
    quo_o = quo_i;
    diff  = 26'd0;
    for (k = 0; k < Steps; k = k + 1) begin
      diff  = {1'b0, rem_o} - {2'b00, den_i};
      // diff is non-negative exactly when rem >= den; the kept remainder is below den < 2^24.
      quo_o = {quo_o[24:0], ~diff[25]};
      rem_o = {(diff[25] ? rem_o[23:0] : diff[23:0]), 1'b0};
    end
  end

endmodule
