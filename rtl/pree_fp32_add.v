// pree_fp32_add: IEEE-754 binary32 adder/subtractor, round to nearest even, 2 pipeline stages.
//
// y = a + b, or a - b when sub_i. Subnormal inputs and outputs in full, x - x = +0,
// (-0) + (-0) = -0, overflow to a signed infinity. NaN result (x86-64 SSE rule): a NaN -> a
// quieted; else b NaN -> b quieted, its sign not flipped by sub_i; else inf - inf -> 0xFFC00000.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// Stage 1 (input -> s1 registers): classify, order the operands by magnitude, align the smaller
//   significand (3 extra bits plus a sticky bit), add or subtract: an unnormalised 28-bit sum.
//   Special results (NaN, infinity) are decided here and carried beside the datapath.
// Stage 2 (s1 -> s2 registers): normalise the sum (one right shift on carry-out, or a left shift
//   by its leading-zero count, limited so the exponent does not fall below 1: an exact
//   subnormal), round to nearest even (pree_fp32_round), final mux with the special result.
// Why 3 extra bits suffice: with an exponent difference of 0 or 1 the aligned sum is exact; with
// 2 or more, cancellation removes at most one leading bit, so guard and sticky survive.
`default_nettype none

module pree_fp32_add (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  input  wire        sub_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam LATENCY = 2;

  // ---------------------------------------------------------------- stage 1: align and add
  wire       sign_a = a_i[31];
  wire       sign_b = b_i[31] ^ sub_i;          // effective sign of the second operand
  wire [7:0] exp_a  = a_i[30:23];
  wire [7:0] exp_b  = b_i[30:23];
  wire       nan_a  = (exp_a == 8'hFF) && (a_i[22:0] != 23'd0);
  wire       nan_b  = (exp_b == 8'hFF) && (b_i[22:0] != 23'd0);
  wire       inf_a  = (exp_a == 8'hFF) && (a_i[22:0] == 23'd0);
  wire       inf_b  = (exp_b == 8'hFF) && (b_i[22:0] == 23'd0);

  // Special result: NaN rule first, then infinities.
  reg        special_d;
  reg [31:0] special_y_d;
  always @* begin
    special_d   = 1'b1;
    special_y_d = {sign_a, 8'hFF, 23'd0};
    if (nan_a)                          special_y_d = a_i | 32'h0040_0000;
    else if (nan_b)                     special_y_d = b_i | 32'h0040_0000;
    else if (inf_a && inf_b && (sign_a != sign_b)) special_y_d = 32'hFFC0_0000;
    else if (inf_a)                     special_y_d = {sign_a, 8'hFF, 23'd0};
    else if (inf_b)                     special_y_d = {sign_b, 8'hFF, 23'd0};
    else                                special_d   = 1'b0;
  end

  // Order by magnitude: L is the larger (or equal) operand, S the smaller.
  wire        swap    = (b_i[30:0] > a_i[30:0]);
  wire [7:0]  exp_a1  = (exp_a == 8'd0) ? 8'd1 : exp_a;   // subnormal: exponent 1, no hidden bit
  wire [7:0]  exp_b1  = (exp_b == 8'd0) ? 8'd1 : exp_b;
  wire [23:0] man_a   = {exp_a != 8'd0, a_i[22:0]};
  wire [23:0] man_b   = {exp_b != 8'd0, b_i[22:0]};
  wire        sign_l  = swap ? sign_b : sign_a;
  wire        sign_s  = swap ? sign_a : sign_b;
  wire [7:0]  exp_l   = swap ? exp_b1 : exp_a1;
  wire [7:0]  exp_s   = swap ? exp_a1 : exp_b1;
  wire [23:0] man_l   = swap ? man_b  : man_a;
  wire [23:0] man_s   = swap ? man_a  : man_b;

  // Align the smaller significand; everything shifted past the 3 extra bits becomes sticky.
  wire [7:0]  diff    = exp_l - exp_s;
  wire [4:0]  sh      = (diff[7:5] != 3'd0) ? 5'd31 : diff[4:0];
  wire [58:0] aligned = {man_s, 3'd0, 32'd0} >> sh;
  wire [26:0] al_small   = {aligned[58:33], aligned[32] | (aligned[31:0] != 32'd0)};
  wire [26:0] al_large   = {man_l, 3'd0};
  wire        eff_sub = (sign_l != sign_s);
  wire [27:0] sum_d   = eff_sub ? ({1'b0, al_large} - {1'b0, al_small})
                                : ({1'b0, al_large} + {1'b0, al_small});

  // Valid pipeline: valid_q[k] is the valid bit of the stage-(k+1) registers.
  reg [LATENCY-1:0] valid_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= {LATENCY{1'b0}};
    else         valid_q <= {valid_q[LATENCY-2:0], valid_i};
  end

  reg [27:0] s1_sum_q;
  reg [7:0]  s1_exp_q;
  reg        s1_sign_q;
  reg        s1_zero_sign_q;   // sign of an exact zero sum: negative only for (-x) + (-x) = -0
  reg        s1_special_q;
  reg [31:0] s1_special_y_q;

  always @(posedge clk_i) begin
    if (valid_i) begin
      s1_sum_q       <= sum_d;
      s1_exp_q       <= exp_l;
      s1_sign_q      <= sign_l;
      s1_zero_sign_q <= sign_l & sign_s;
      s1_special_q   <= special_d;
      s1_special_y_q <= special_y_d;
    end
  end

  // ---------------------------------------------------------------- stage 2: normalise, round
  wire [4:0] lz;
  pree_fp32_lzc #(.Width(27), .CntWidth(5)) u_lzc (
    .x_i   (s1_sum_q[26:0]),
    .cnt_o (lz)
  );

  // Left shift by the leading-zero count, but never below exponent 1 (then the result is an
  // exact subnormal, which pree_fp32_round packs with exponent field 0).
  wire [7:0]  exp_m1   = s1_exp_q - 8'd1;
  wire [7:0]  lshift   = ({3'd0, lz} > exp_m1) ? exp_m1 : {3'd0, lz};
  wire [26:0] man_left = s1_sum_q[26:0] << lshift;
  wire        carry    = s1_sum_q[27];

  wire [26:0] norm_man    = carry ? s1_sum_q[27:1] : man_left;
  wire        norm_sticky = carry & s1_sum_q[0];
  wire [9:0]  norm_exp    = carry ? ({2'b00, s1_exp_q} + 10'd1)
                                  : ({2'b00, s1_exp_q} - {2'b00, lshift});
  wire [31:0] rounded;

  pree_fp32_round #(.Denorm(0)) u_round (
    .sign_i   (s1_sign_q),
    .exp_i    (norm_exp),
    .man_i    (norm_man),
    .sticky_i (norm_sticky),
    .y_o      (rounded)
  );

  wire        sum_zero = (s1_sum_q == 28'd0);
  wire [31:0] y_d      = s1_special_q ? s1_special_y_q
                       : sum_zero     ? {s1_zero_sign_q, 31'd0}
                       :                rounded;

  reg [31:0] s2_y_q;

  always @(posedge clk_i) begin
    if (valid_q[0]) s2_y_q <= y_d;
  end

  assign valid_o = valid_q[LATENCY-1];
  assign y_o     = s2_y_q;

endmodule
