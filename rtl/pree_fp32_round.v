// SPDX-License-Identifier: Apache-2.0
// pree_fp32_round: round to nearest (ties to even) and pack a binary32 result.
//
// Combinational helper shared by the adder, multiplier, squarer and divider.
// Input: the exact result as  (-1)^sign_i * (man_i + sticky) / 2^26 * 2^(exp_i - 127),
// where man_i[26] is the leading one, man_i[25:3] the fraction, man_i[2] the guard bit and
// man_i[1:0] plus sticky_i everything below it (sticky_i = some bit below man_i[0] is one).
// exp_i is biased and two's complement (10 bits), so it may lie below 1 or above 254.
//
// Parameter Denorm:
//   1: exp_i may be <= 0: the significand is first shifted right by 1 - exp_i, the shifted-out
//      bits joining the sticky bit, so a subnormal result is rounded exactly once.
//      (A shift by 27 .. 31 leaves 0 and makes the sticky bit the OR of all of man_i, as
//      the capped shift of the original 59-bit formulation did.)
//   0: the caller guarantees exp_i >= 1 and may pass man_i[26] = 0 together with exp_i = 1 for
//      an (exact) subnormal or zero result; no right shift is built. The output of
//      pree_fp32_denorm (a shifted significand, man_i[26] = 0, with exp_i <= 0) is also valid
//      input: Denorm = 1 is exactly pree_fp32_denorm_amt and pree_fp32_denorm followed by
//      Denorm = 0, which is how the deep pipelines place registers between the shift amount,
//      the shift and the rounding.
// In both cases the exponent field is exp_i when man_i[26] is one and 0 otherwise, and the
// rounding increment is added to {exponent field, fraction}, so a carry out of the fraction
// moves the result to the next binade (largest subnormal -> smallest normal, 1.11..1 -> 2.0,
// largest finite -> infinity) without a separate normalisation step.
// Overflow (exp_i >= 255 with a normalised significand) gives a signed infinity.
//
// Rounding decision (L = result LSB man[3], G = guard man[2], S = man[1] | man[0] | sticky):
//   G S L | increment
//   0 x x |   0        below half an ulp: truncate
//   1 1 x |   1        above half: round up
//   1 0 0 |   0        exact tie, LSB even: stay
//   1 0 1 |   1        exact tie, LSB odd: round up to even
`default_nettype none

module pree_fp32_round #(
  parameter Denorm = 1
) (
  input  wire        sign_i,
  input  wire [9:0]  exp_i,
  input  wire [26:0] man_i,
  input  wire        sticky_i,
  output wire [31:0] y_o
);

  // Denormalise (pree_fp32_denorm_amt, pree_fp32_denorm): shift right by 1 - exp_i when
  // exp_i <= 0.
  wire [26:0] man;
  wire        sticky;

  generate
    if (Denorm != 0) begin : g_denorm
      wire       tiny;
      wire [4:0] sh;
      pree_fp32_denorm_amt u_amt (.exp_i (exp_i), .tiny_o (tiny), .sh_o (sh));
      pree_fp32_denorm u_denorm (
        .tiny_i (tiny), .sh_i (sh), .man_i (man_i), .sticky_i (sticky_i),
        .man_o (man), .sticky_o (sticky)
      );
    end else begin : g_plain
      assign man    = man_i;
      assign sticky = sticky_i;
    end
  endgenerate

  // Round to nearest, ties to even (table above).
  wire lsb   = man[3];
  wire guard = man[2];
  wire rest  = man[1] | man[0] | sticky;
  wire inc   = guard & (rest | lsb);

  // Pack, letting the increment carry into the exponent field.
  wire [7:0]  exp_field = man[26] ? exp_i[7:0] : 8'd0;
  wire [30:0] mag       = {exp_field, man[25:3]} + {30'd0, inc};
  wire        overflow  = ~exp_i[9] & (exp_i[8:0] >= 9'd255) & man[26];

  assign y_o = overflow ? {sign_i, 8'hFF, 23'd0} : {sign_i, mag};

endmodule
