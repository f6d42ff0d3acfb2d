// pree_fp32_unpack: classify a binary32 operand and normalise its significand.
//
// Combinational helper of the multiplier and divider: pree_fp32_unpack_lz (classification and
// leading-zero count) followed by pree_fp32_unpack_norm (the normalising shift), which the
// deep pipelines use separately with a register between them. A subnormal operand is shifted
// left until its leading one sits in man_o[23]; its exponent goes down by the same amount, so
// exp_o (biased, two's complement, 10 bits) may be zero or negative (down to -22).
// The value of a finite non-zero operand is (-1)^sign_o * man_o / 2^23 * 2^(exp_o - 127).
// For zero, man_o is zero; for inf and NaN, exp_o and man_o are don't-cares of the caller.
`default_nettype none

module pree_fp32_unpack (
  input  wire [31:0] x_i,
  output wire        sign_o,
  output wire [9:0]  exp_o,
  output wire [23:0] man_o,
  output wire        zero_o,
  output wire        inf_o,
  output wire        nan_o
);

  wire [4:0] lz;

  pree_fp32_unpack_lz u_lz (
    .x_i (x_i[30:0]), .lz_o (lz), .zero_o (zero_o), .inf_o (inf_o), .nan_o (nan_o)
  );
  pree_fp32_unpack_norm u_norm (
    .x_i (x_i[30:0]), .lz_i (lz), .exp_o (exp_o), .man_o (man_o)
  );

  assign sign_o = x_i[31];

endmodule
