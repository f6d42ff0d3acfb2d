// pree_u64_to_f32: an unsigned 64-bit integer rounded once to binary32, round to nearest even,
// 2 pipeline stages.
//
// Bit-exact with u64_to_f32() of model/wide_acc.h (the same as the C conversion (float)k):
// exact up to 2^24, 0 -> +0, never negative, never infinite (2^64 - 1 rounds to 2^64 =
// 0x5F800000, far below the overflow threshold), no NaN.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// Stage 1 (input -> s1 registers): the leading-zero count lz (pree_fp32_lzc, 64 bits).
// Stage 2 (s1 -> s2 registers): the normalising left shift by lz (the leading one moves to
//   bit 63; exponent 63 - lz + 127), the top 27 bits and the OR of the 37 below (sticky) in the
//   input format of pree_fp32_round, which rounds to nearest even and packs (Denorm = 0: the
//   exponent is at least 127, so no subnormal and no overflow can occur). Zero needs no special
//   case: its normalised word is 0, which packs as +0.
// Why the shift is in stage 2: the 64-bit count alone is 9 LUT levels after Yosys mapping;
//   count and shift in stage 1 measured 14 LUT levels there and 3 in stage 2, this split 9 / 9
//   (docs/fp32_units.md).
`default_nettype none

module pree_u64_to_f32 (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [63:0] a_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam LATENCY = 2;

  // ---------------------------------------------------------------- stage 1: leading zeros
  wire [6:0] lz;    // 0..64; 64 only for a_i = 0

  pree_fp32_lzc #(.Width(64), .CntWidth(7)) u_lzc (
    .x_i   (a_i),
    .cnt_o (lz)
  );

  // Valid pipeline: valid_q[k] is the valid bit of the stage-(k+1) registers.
  reg [LATENCY-1:0] valid_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {LATENCY{1'b0}};
    else         valid_q <= {valid_q[LATENCY-2:0], valid_i};
  end

  reg [63:0] s1_a_q;
  reg [6:0]  s1_lz_q;

  always @(posedge clk_i) begin
    if (valid_i) begin
      s1_a_q  <= a_i;
      s1_lz_q <= lz;
    end
  end

  // ---------------------------------------------------------------- stage 2: normalise, round
  wire [63:0] norm   = s1_a_q << s1_lz_q[5:0];          // a = 0: lz[5:0] = 0, norm = 0
  wire [9:0]  exp    = 10'd190 - {3'd0, s1_lz_q};       // 63 - lz + 127 (a = 0: 126, unused)
  wire [26:0] man    = norm[63:37];                     // 24 bits, guard, 2 more
  wire        sticky = (norm[36:0] != 37'd0);
  wire [31:0] y_d;

  pree_fp32_round #(.Denorm(0)) u_round (
    .sign_i   (1'b0),
    .exp_i    (exp),
    .man_i    (man),
    .sticky_i (sticky),
    .y_o      (y_d)
  );

  reg [31:0] s2_y_q;

  always @(posedge clk_i) begin
    if (valid_q[0]) s2_y_q <= y_d;
  end

  assign valid_o = valid_q[LATENCY-1];
  assign y_o     = s2_y_q;

endmodule
