// SPDX-License-Identifier: Apache-2.0
// pree_fp32_special: the special-case result of a binary32 operation, combinational.
//
// One priority rule for every arithmetic unit (x86-64 SSE): a NaN operand a -> a quieted (sign
// and payload kept); else a NaN b -> b quieted; else an invalid operation -> the default NaN
// 0xFFC00000; else an infinite result -> infinity of sign sign_i; else a zero result -> zero of
// sign sign_i; else the result is not special (special_o = 0, y_o a don't-care).
// The unit states what is invalid, infinite or zero for its operation from the operands'
// classes (pree_fp32_class), for example the multiplier: invalid = 0 * inf, inf = either
// operand infinite, zero = either operand zero. special_o and y_o are decided at the unit's
// first stage and carried beside the datapath to pree_fp32_final.
`default_nettype none

module pree_fp32_special (
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  input  wire        nan_a_i,
  input  wire        nan_b_i,
  input  wire        invalid_i,
  input  wire        inf_i,
  input  wire        zero_i,
  input  wire        sign_i,
  output wire        special_o,
  output wire [31:0] y_o
);

  localparam [31:0] QUIET_BIT   = 32'h0040_0000;
  localparam [31:0] DEFAULT_NAN = 32'hFFC0_0000;

  assign special_o = nan_a_i | nan_b_i | invalid_i | inf_i | zero_i;
  assign y_o       = nan_a_i   ? (a_i | QUIET_BIT)
                   : nan_b_i   ? (b_i | QUIET_BIT)
                   : invalid_i ? DEFAULT_NAN
                   : inf_i     ? {sign_i, 8'hFF, 23'd0}
                   :             {sign_i, 31'd0};

endmodule
