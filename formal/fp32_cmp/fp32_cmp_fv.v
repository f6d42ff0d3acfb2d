// SPDX-License-Identifier: Apache-2.0
// fp32_cmp_fv: formal check of pree_fp32_cmp (combinational) against an independent
// statement of IEEE-754 binary32 comparison. pree_fp32_cmp has no deep configuration (latency
// 0 in every PREU plan; the PREU registers its outputs around it), so instead of a miter it is
// proven equal to the reference ordering written here another way: each non-NaN value mapped
// to a signed integer key that orders like the reals (+x -> |x|, -x -> -|x|, both zeros -> 0),
// then lt/le/eq are the key comparisons; a NaN operand (exponent all ones, fraction not zero)
// makes the pair unordered and all three false. For all 2^64 operand pairs.
`default_nettype none

module fp32_cmp_fv (
  input wire [31:0] a_i,
  input wire [31:0] b_i
);

  wire lt, le, eq, unordered;
  pree_fp32_cmp dut (
    .a_i(a_i), .b_i(b_i), .lt_o(lt), .le_o(le), .eq_o(eq), .unordered_o(unordered)
  );

  function signed [32:0] key;
    input [31:0] x;
    key = x[31] ? -$signed({2'b00, x[30:0]}) : $signed({2'b00, x[30:0]});
  endfunction

  function is_nan;
    input [31:0] x;
    is_nan = (x[30:23] == 8'hff) && (x[22:0] != 23'd0);
  endfunction

  wire signed [32:0] ka = key(a_i);
  wire signed [32:0] kb = key(b_i);
  wire               un = is_nan(a_i) || is_nan(b_i);

  always @* begin
    assert (unordered == un);
    assert (lt == (!un && ka <  kb));
    assert (le == (!un && ka <= kb));
    assert (eq == (!un && ka == kb));
    // Covers: each outcome, and -0 == +0.
    cover (lt);
    cover (!lt && le);
    cover (!le && !unordered);
    cover (unordered);
    cover (eq && a_i != b_i);
  end

endmodule

`default_nettype wire
