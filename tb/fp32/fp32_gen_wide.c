// SPDX-License-Identifier: Apache-2.0
/* fp32_gen_wide.c: the directed and random test cases of the stable datapath's two units (see
 * fp32_gen.h): pree_wacc (a wide accumulator word plus a binary32 term) and pree_u64_to_f32 (an
 * unsigned 64-bit integer). The binary32 units' cases and the shared helpers are in fp32_gen.c.
 */
#include "fp32_gen.h"
#include "fp32_gen_cases.h"
#include "fp32_ops.h"
#include "wide_acc.h"

/* ------------------------------------------------------------------ the stable datapath's units
 *
 * wacc: a is a wide accumulator word (model/pree/wide_acc.h: e = bits 63..56, M = bits 55..0), b the
 * binary32 term t; the effective exponents max(e, 1) of both share one scale, so their
 * difference is the alignment shift. u2f: a is an unsigned 64-bit integer. */

/* A random n-bit pattern (1 <= n <= 64): uniform, sparse, dense, a run of ones, nearly empty
 * or all ones. */
static uint64_t rand_bits(uint64_t *rng, int n)
{
    const uint64_t mask = n >= 64 ? ~0ull : (1ull << n) - 1;
    uint64_t m = 0;
    switch (gen_rnd(rng, 8)) {
    case 4: for (int i = gen_range(rng, 1, 3); i > 0; i--) m |= 1ull << gen_rnd(rng, (uint32_t)n);
            return m;
    case 5: m = mask;
            for (int i = gen_range(rng, 0, 3); i > 0; i--) m &= ~(1ull << gen_rnd(rng, (uint32_t)n));
            return m;
    case 6: { int lo = (int)gen_rnd(rng, (uint32_t)n), len = gen_range(rng, 1, n - lo);
              return (len >= 64 ? ~0ull : ((1ull << len) - 1) << lo) & mask; }
    case 7: return gen_rnd(rng, 4) == 0 ? 0 : gen_rnd(rng, 4) == 0 ? mask : fp32_rng_next(rng) & 7u & mask;
    default: return fp32_rng_next(rng) & mask;
    }
}

static uint64_t wide(uint32_t e, uint64_t m) { return (uint64_t)(e & 0xFFu) << 56 | (m & WIDE_M_MASK); }

/* A wide word with effective exponent x (1..254): normal with M[55] = 1, or for x = 1 now and
 * then an "e = 0" word (M[55] = 0: zero or subnormal). */
static uint64_t wide_at(uint64_t *rng, int x)
{
    if (x == 1 && gen_rnd(rng, 4) == 0) return wide(0, rand_bits(rng, 55));
    return wide((uint32_t)x, WIDE_LEAD | rand_bits(rng, 55));
}

/* A positive binary32 term with effective exponent x (1..254), subnormal now and then at x = 1. */
static uint32_t term_at(uint64_t *rng, int x)
{
    if (x == 1 && gen_rnd(rng, 4) == 0) return gen_pack(0, 0, gen_mantissa(rng));
    return gen_pack(0, (uint32_t)x, gen_mantissa(rng));
}

/* Wide words that matter: zero, subnormals, the smallest normal, 1 and 2 and their neighbours,
 * the top binade and WIDE_MAX, infinity, NaNs, and words whose M[55] disagrees with e. */
static const uint64_t WIDE_SPECIALS[] = {
    0x0000000000000000ull, 0x0000000000000001ull, 0x007FFFFFFFFFFFFFull,   /* 0, subnormals */
    0x0000000100000000ull, 0x0040000000000000ull,
    0x0180000000000000ull, 0x0180000000000001ull, 0x01FFFFFFFFFFFFFFull,   /* smallest normals */
    0x7F80000000000000ull, 0x7FFFFFFFFFFFFFFFull, 0x8080000000000000ull,   /* 1, 2 - ulp, 2 */
    0x7F80000080000000ull, 0x9E80000000000000ull,                         /* 1 + 2^-24, 2^31 */
    0xFE80000000000000ull, 0xFDFFFFFFFFFFFFFFull, 0xFEFFFFFFFFFFFFFEull,   /* top binades */
    WIDE_MAX,
    WIDE_INF, WIDE_NAN, 0xFF00000000000001ull, 0xFFFFFFFFFFFFFFFFull,      /* inf, NaNs */
    0x0500000000000001ull, 0x7F00000012345678ull, 0xFE7FFFFFFFFFFFFFull,   /* M[55] = 0, e >= 1 */
};
#define N_WIDE_SPECIALS (sizeof WIDE_SPECIALS / sizeof WIDE_SPECIALS[0])

/* A random wide word over the whole encoding space, weighted towards the interesting parts. */
static uint64_t rand_wide(uint64_t *rng)
{
    uint32_t r = gen_rnd(rng, 64);
    if (r < 6) return WIDE_SPECIALS[gen_rnd(rng, N_WIDE_SPECIALS)];
    if (r < 10) return fp32_rng_next(rng);                      /* any word, non-canonical too */
    if (r < 12) return wide(255, rand_bits(rng, 56));           /* infinity or a NaN */
    if (r < 20) return wide(0, rand_bits(rng, 55));             /* e = 0 */
    if (r < 26) return wide_at(rng, gen_range(rng, 240, 254));  /* near saturation */
    return wide_at(rng, gen_range(rng, 1, 254));
}

/* wacc: every wide special against every binary32 special. */
static void fam_wacc_specials(list_t *l)
{
    for (size_t i = 0; i < N_WIDE_SPECIALS; i++)
        for (size_t j = 0; j < gen_n_specials; j++) gen_put(l, WIDE_SPECIALS[i], gen_specials[j], 0);
}

/* wacc: every exponent difference xa - xt from -72 to 72 (shifts of 56 and more drop the
 * smaller operand), both operands random, and the larger one's significand all ones. */
static void fam_wacc_align(list_t *l, uint64_t *rng)
{
    for (int d = -72; d <= 72; d++)
        for (int n = 0; n < 6; n++) {
            int xa = gen_range(rng, d > 0 ? 1 + d : 1, d < 0 ? 254 + d : 254), xt = xa - d;
            uint64_t a = wide_at(rng, xa);
            uint32_t t = term_at(rng, xt);
            if (n == 0) a |= WIDE_M_MASK >> 1;                  /* M = all ones: carries */
            if (n == 1) t |= 0x7FFFFFu;
            gen_put(l, a, t, 0);
        }
}

/* wacc: carries out of bit 55 (dense significands, small differences) at the bottom, middle
 * and top of the exponent range; at the top (xa = 254) every carry saturates. */
static void fam_wacc_carry(list_t *l, uint64_t *rng)
{
    static const int exps[] = { 1, 2, 3, 100, 127, 200, 252, 253, 254 };
    for (size_t i = 0; i < sizeof exps / sizeof exps[0]; i++)
        for (int d = 0; d <= 33; d++) {
            int x = exps[i];
            uint64_t dense = WIDE_M_MASK ^ (fp32_rng_next(rng) & 0xFFFFull);
            if (x - d >= 1) {                                   /* A big, t aligned */
                gen_put(l, wide((uint32_t)x, dense), gen_pack(0, (uint32_t)(x - d), 0x7FFFFFu), 0);
                gen_put(l, wide((uint32_t)x, WIDE_M_MASK), gen_pack(0, (uint32_t)(x - d), gen_mantissa(rng)), 0);
            }
            if (x + d <= 254)                                   /* t big, A aligned */
                gen_put(l, wide((uint32_t)x, dense), gen_pack(0, (uint32_t)(x + d), 0x7FFFFFu - gen_rnd(rng, 4)), 0);
        }
}

/* wacc: near WIDE_MAX: the largest words plus terms from 2^127 down by 0..60 binades, and
 * sums that just reach or just miss the top binade. */
static void fam_wacc_saturate(list_t *l, uint64_t *rng)
{
    static const uint64_t tops[] = { WIDE_MAX, WIDE_MAX - 1, 0xFEFFFFFF00000000ull,
                                     0xFE80000000000000ull, 0xFDFFFFFFFFFFFFFFull,
                                     0xFEC0000000000000ull };
    for (size_t i = 0; i < sizeof tops / sizeof tops[0]; i++)
        for (int d = 0; d <= 60; d++) {
            gen_put(l, tops[i], gen_pack(0, (uint32_t)(254 - d), 0x7FFFFFu), 0);
            gen_put(l, tops[i], gen_pack(0, (uint32_t)(254 - d), gen_mantissa(rng)), 0);
        }
    gen_put(l, WIDE_ZERO, 0x7F7FFFFFu, 0);                          /* FLT_MAX: exactly e = 254 */
    gen_put(l, 0xFD80000000000000ull, 0x7F000000u, 0);              /* 2^126 + 2^127: no carry */
    gen_put(l, 0xFE80000000000000ull, 0x7F000000u, 0);              /* 2^127 + 2^127: saturates */
    gen_put(l, 0xFDFFFFFFFFFFFFFFull, 0x7E800000u, 0);              /* carry into e = 254 */
}

/* wacc: e = 0 words and subnormal terms: sums that stay below bit 55 (e field 0) and sums that
 * reach it (e field 1). */
static void fam_wacc_subnormal(list_t *l, uint64_t *rng)
{
    gen_put(l, 0x007FFFFFFFFFFFFFull, 0x00000001u, 0);              /* largest e = 0 + smallest t */
    gen_put(l, 0x007FFFFF00000000ull, 0x00000001u, 0);
    gen_put(l, 0x0000000000000000ull, 0x007FFFFFu, 0);
    gen_put(l, 0x0040000000000000ull, 0x00400000u, 0);              /* 2^54 + 2^54 = 2^55: e 1 */
    for (int n = 0; n < 300; n++) {
        uint64_t a = wide(0, rand_bits(rng, 55));
        uint32_t t = gen_rnd(rng, 3) ? gen_pack(0, 0, gen_mantissa(rng)) : gen_pack(0, 1 + gen_rnd(rng, 3), gen_mantissa(rng));
        if (gen_rnd(rng, 5) == 0) a = wide_at(rng, gen_range(rng, 1, 3));
        gen_put(l, a, t, 0);
    }
}

static void wacc_random(uint64_t *rng, fp32_case_t *c)
{
    uint64_t a;
    uint32_t t;
    int d, xa;
    switch (gen_rnd(rng, 8)) {
    case 0:                                  /* anything: special words, negative, NaN, inf t */
        a = rand_wide(rng); t = gen_operand(rng);
        break;
    case 1: case 2: case 3: case 4:          /* exponent difference -72..72, or anywhere */
        d = gen_rnd(rng, 4) ? gen_range(rng, -72, 72) : gen_range(rng, -253, 253);
        xa = gen_range(rng, d > 0 ? 1 + d : 1, d < 0 ? 254 + d : 254);
        a = gen_rnd(rng, 16) ? wide_at(rng, xa) : rand_wide(rng);
        t = term_at(rng, xa - d);
        break;
    case 5:                                  /* carries: dense significands, small differences */
        d = gen_range(rng, -24, 33);
        xa = gen_range(rng, d > 0 ? 1 + d : 1, d < 0 ? 254 + d : 254);
        a = wide((uint32_t)xa, WIDE_M_MASK ^ rand_bits(rng, gen_range(rng, 1, 55)) ^ (fp32_rng_next(rng) & 1u));
        t = gen_pack(0, (uint32_t)(xa - d), 0x7FFFFFu ^ (gen_rnd(rng, 2) ? 0 : gen_mantissa(rng)));
        break;
    case 6:                                  /* near saturation */
        xa = gen_range(rng, 250, 254);
        a = wide((uint32_t)xa, WIDE_M_MASK ^ (gen_rnd(rng, 2) ? 0 : rand_bits(rng, 56)));
        a |= WIDE_LEAD;
        t = gen_pack(0, (uint32_t)gen_range(rng, 190, 254), gen_rnd(rng, 2) ? 0x7FFFFFu : gen_mantissa(rng));
        break;
    default:                                 /* e = 0 words, subnormal and tiny terms */
        a = gen_rnd(rng, 4) ? wide(0, rand_bits(rng, 55)) : wide_at(rng, gen_range(rng, 1, 4));
        t = gen_rnd(rng, 2) ? gen_pack(0, 0, gen_mantissa(rng)) : gen_pack(0, (uint32_t)gen_range(rng, 1, 4), gen_mantissa(rng));
        break;
    }
    c->a = a; c->b = t; c->sub = 0;
    c->y = fp32_expect(FP32_WACC, a, t, 0);
}

/* u2f: 0, 1, every power of two and its neighbours (2^24 +- 1 included), the values near
 * 2^64 - 1, ones-runs from the top and bottom, and at every rounding position exact ties with
 * both LSB parities and their neighbours. */
static void fam_u2f(list_t *l, uint64_t *rng)
{
    for (int n = 0; n < 64; n++)
        for (int delta = -3; delta <= 3; delta++) gen_put(l, (1ull << n) + (uint64_t)(int64_t)delta, 0, 0);
    for (uint64_t k = 0; k <= 64; k++) gen_put(l, ~0ull - k, 0, 0);
    for (int s = 0; s < 64; s++) { gen_put(l, ~0ull << s, 0, 0); gen_put(l, ~0ull >> s, 0, 0); }
    for (int s = 1; s <= 40; s++) {                        /* the LSB has weight 2^s */
        static const uint64_t fixed[] = { 0x800000u, 0x800001u, 0xFFFFFEu, 0xFFFFFFu };
        for (int n = 0; n < 12; n++) {
            uint64_t m = n < 4 ? fixed[n] : (0x800000u | (fp32_rng_next(rng) & 0x7FFFFFu));
            uint64_t tie = m << s | 1ull << (s - 1);
            gen_put(l, tie, 0, 0);
            gen_put(l, tie - 1, 0, 0);
            gen_put(l, tie + 1, 0, 0);
            if (s >= 2) gen_put(l, tie | rand_bits(rng, s - 1), 0, 0);
        }
    }
}

static void u2f_random(uint64_t *rng, fp32_case_t *c)
{
    uint64_t k;
    int w, s;
    switch (gen_rnd(rng, 4)) {
    case 0:                                  /* uniform */
        k = fp32_rng_next(rng);
        break;
    case 1:                                  /* a random bit width, varied patterns */
        w = gen_range(rng, 1, 64);
        k = rand_bits(rng, w) | (gen_rnd(rng, 8) ? 1ull << (w - 1) : 0);
        break;
    case 2:                                  /* ties and their neighbours */
        s = gen_range(rng, 1, 40);
        k = (0x800000u | (fp32_rng_next(rng) & 0x7FFFFFu)) << s | 1ull << (s - 1);
        k += (uint64_t)(int64_t)gen_range(rng, -1, 1);
        break;
    default:                                 /* near powers of two and near 2^64 - 1 */
        k = gen_rnd(rng, 2) ? (1ull << gen_rnd(rng, 64)) + (uint64_t)(int64_t)gen_range(rng, -300, 300)
                        : ~0ull - rand_bits(rng, gen_range(rng, 1, 40));
        break;
    }
    c->a = k; c->b = 0; c->sub = 0;
    c->y = fp32_expect(FP32_U2F, k, 0, 0);
}

void gen_wide_directed(list_t *l, uint64_t *rng)
{
    if (l->unit == FP32_WACC) {
        fam_wacc_specials(l);
        fam_wacc_align(l, rng);
        fam_wacc_carry(l, rng);
        fam_wacc_saturate(l, rng);
        fam_wacc_subnormal(l, rng);
    } else {
        fam_u2f(l, rng);
    }
}

void gen_wide_random(fp32_unit_t unit, uint64_t *rng, fp32_case_t *c)
{
    if (unit == FP32_WACC) wacc_random(rng, c);
    else u2f_random(rng, c);
}
