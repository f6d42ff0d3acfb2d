// pree_fp32_unpack: classify a binary32 operand and normalise its significand.
//
// Combinational helper of the multiplier and divider. A subnormal operand is shifted left
// until its leading one sits in man_o[23]; its exponent goes down by the same amount, so
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

  wire [7:0]  exp_field = x_i[30:23];
  wire [22:0] frac      = x_i[22:0];
  wire        exp_zero  = (exp_field == 8'd0);
  wire        exp_ones  = (exp_field == 8'hFF);
  wire        frac_zero = (frac == 23'd0);

  // Hidden bit, then the leading-zero count that normalises a subnormal (0 for a normal).
  wire [23:0] man_raw = {~exp_zero, frac};
  wire [4:0]  lz;

  pree_fp32_lzc #(.Width(24), .CntWidth(5)) u_lzc (
    .x_i   (man_raw),
    .cnt_o (lz)
  );

  assign sign_o = x_i[31];
  assign man_o  = man_raw << lz;
  assign exp_o  = exp_zero ? (10'd1 - {5'd0, lz}) : {2'b00, exp_field};
  assign zero_o = exp_zero & frac_zero;
  assign inf_o  = exp_ones & frac_zero;
  assign nan_o  = exp_ones & ~frac_zero;

endmodule
