// pree_fp32_unpack_lz: the first half of pree_fp32_unpack, combinational: classify a binary32
// operand and count the leading zeros that normalise its significand.
//
// lz_o is the leading-zero count of {hidden bit, fraction} (0 for a normal operand, 1 .. 23
// for a subnormal, 24 for zero). pree_fp32_unpack_norm finishes the unpacking from x_i and
// lz_o; the two are separate modules so that a deep pipeline can put a register between them.
`default_nettype none

module pree_fp32_unpack_lz (
  input  wire [30:0] x_i,        // the operand without its sign bit
  output wire [4:0]  lz_o,
  output wire        zero_o,
  output wire        inf_o,
  output wire        nan_o
);

  wire [7:0]  exp_field = x_i[30:23];
  wire [22:0] frac      = x_i[22:0];
  wire        exp_zero  = (exp_field == 8'd0);
  wire        exp_ones  = (exp_field == 8'hFF);
  wire        frac_zero = (frac == 23'd0);

  pree_fp32_lzc #(.Width(24), .CntWidth(5)) u_lzc (
    .x_i   ({~exp_zero, frac}),
    .cnt_o (lz_o)
  );

  assign zero_o = exp_zero & frac_zero;
  assign inf_o  = exp_ones & frac_zero;
  assign nan_o  = exp_ones & ~frac_zero;

endmodule
