/* fp32_gen.c: directed and random test cases for the binary32 RTL units (see fp32_gen.h).
 *
 * Directed families: every pair of special classes; exact ties built from odd integers
 * (add, mul, sqr; div ties exist only on the subnormal grid); results straddling the overflow
 * threshold and the underflow thresholds (smallest normal, smallest subnormal and half of it);
 * total and partial cancellation; exact small-integer results; comparator neighbours.
 * Random operands cover the whole exponent range, with extra weight on subnormals, special
 * values, near-equal exponents (alignment and cancellation) and results near the thresholds.
 * The stable datapath's units (wacc, u2f) have their own families, in the last sections.
 */
#include "fp32_gen.h"
#include "fp32_ops.h"
#include "wide_acc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The special classes of the issue plus a few neighbours of interesting boundaries. */
static const uint32_t SPECIALS[] = {
    0x00000000u, 0x80000000u,                 /* +-0 */
    0x00000001u, 0x80000001u,                 /* +-smallest subnormal */
    0x007FFFFFu, 0x807FFFFFu,                 /* +-largest subnormal */
    0x00800000u, 0x80800000u,                 /* +-smallest normal */
    0x7F7FFFFFu, 0xFF7FFFFFu,                 /* +-largest normal */
    0x3F800000u, 0xBF800000u,                 /* +-1 */
    0x7F800000u, 0xFF800000u,                 /* +-inf */
    0x7FC00000u, 0xFFC00000u, 0x7FD55555u, 0xFFE00001u,   /* quiet NaNs */
    0x7F800001u, 0xFFA00000u, 0x7FBFFFFFu, 0xFF812345u,   /* signalling NaNs */
    0x40000000u, 0x3F000000u, 0x40400000u, 0x3FC00000u,   /* 2, 0.5, 3, 1.5 */
    0x3F800001u, 0x3F7FFFFFu, 0x00800001u, 0x00400000u,   /* 1+ulp, 1-ulp/2, ... */
    0x7F000000u, 0x01000000u, 0x33800000u, 0x34000000u,   /* 2^127, 2^-125, 2^-24, 2^-23 */
    0x5F800000u, 0x1F800000u, 0xC0A00000u, 0x00000003u,   /* 2^64, 2^-64, -5, 3 * 2^-149 */
};
#define N_SPECIALS (sizeof SPECIALS / sizeof SPECIALS[0])

uint64_t fp32_rng_next(uint64_t *rng)
{
    /* xorshift64*: small, fast, and good enough to spread operands. */
    uint64_t x = *rng;
    x ^= x >> 12; x ^= x << 25; x ^= x >> 27;
    *rng = x;
    return x * 0x2545F4914F6CDD1DULL;
}

static uint32_t rnd(uint64_t *rng, uint32_t n) { return (uint32_t)(fp32_rng_next(rng) >> 32) % n; }
static int rnd_range(uint64_t *rng, int lo, int hi) { return lo + (int)rnd(rng, (uint32_t)(hi - lo + 1)); }

static const char *const UNIT_NAMES[FP32_N_UNITS] = { "add", "mul", "sqr", "div", "cmp", "wacc", "u2f" };

int fp32_unit_parse(const char *name, fp32_unit_t *unit)
{
    for (int i = 0; i < FP32_N_UNITS; i++)
        if (strcmp(name, UNIT_NAMES[i]) == 0) { *unit = (fp32_unit_t)i; return 0; }
    return -1;
}

const char *fp32_unit_name(fp32_unit_t unit) { return UNIT_NAMES[unit]; }

uint64_t fp32_expect(fp32_unit_t unit, uint64_t a, uint32_t b, uint32_t sub)
{
    const uint32_t a32 = (uint32_t)a;
    switch (unit) {
    case FP32_ADD: return sub ? fp32_sub(a32, b) : fp32_add(a32, b);
    case FP32_MUL: return fp32_mul(a32, b);
    case FP32_SQR: return fp32_sqr(a32);
    case FP32_DIV: return fp32_div(a32, b);
    case FP32_CMP: {
        fp32_cmp_t c = fp32_cmp(a32, b);
        return (uint32_t)(c.unordered << 3 | c.eq << 2 | c.le << 1 | c.lt);
    }
    case FP32_WACC: return wide_add(a, b);
    case FP32_U2F:  return u64_to_f32(a);
    }
    return 0;
}

/* ------------------------------------------------------------------ operand helpers */

static uint32_t pack(uint32_t sign, uint32_t exp, uint32_t man)
{
    return sign << 31 | (exp & 0xFFu) << 23 | (man & 0x7FFFFFu);
}

/* The binary32 bits of x (a double that must be exactly representable, or it is rounded). */
static uint32_t bits_of(double x) { return fp32_to_bits((float)x); }

/* Bits of integer m * 2^k when that is a finite binary32 number exactly; 0 and -1 otherwise. */
static int scaled(double m, int k, uint32_t *out)
{
    double v = ldexp(m, k);
    float f = (float)v;
    if (isinf(f) || (double)f != v || f == 0.0f) return -1;
    *out = fp32_to_bits(f);
    return 0;
}

/* A random significand pattern: uniform, sparse, dense, a run of ones, or nearly empty. */
static uint32_t rand_mantissa(uint64_t *rng)
{
    uint32_t m = 0;
    switch (rnd(rng, 8)) {
    case 4: for (int i = rnd_range(rng, 1, 3); i > 0; i--) m |= 1u << rnd(rng, 23); return m;
    case 5: m = 0x7FFFFFu;
            for (int i = rnd_range(rng, 0, 3); i > 0; i--) m &= ~(1u << rnd(rng, 23));
            return m;
    case 6: { int lo = (int)rnd(rng, 23), len = rnd_range(rng, 1, 23 - lo);
              return (uint32_t)(((1ull << len) - 1) << lo) & 0x7FFFFFu; }
    case 7: return rnd(rng, 4) == 0 ? 0 : rnd(rng, 8);
    default: return (uint32_t)fp32_rng_next(rng) & 0x7FFFFFu;
    }
}

/* A random operand over the whole encoding space, weighted towards the interesting parts. */
static uint32_t rand_operand(uint64_t *rng)
{
    uint32_t r = rnd(rng, 64);
    if (r < 4) return SPECIALS[rnd(rng, N_SPECIALS)];
    if (r < 8) return (uint32_t)fp32_rng_next(rng);
    uint32_t e = rnd(rng, 12) == 0 ? 0 : rnd(rng, 64) == 0 ? 255 : 1 + rnd(rng, 254);
    return pack(rnd(rng, 2), e, rand_mantissa(rng));
}

/* Set the exponent field of x to e when 1 <= e <= 254; otherwise return a fresh operand. */
static uint32_t with_exp(uint64_t *rng, uint32_t x, int e)
{
    if (e < 1 || e > 254) return rand_operand(rng);
    return (x & 0x807FFFFFu) | (uint32_t)e << 23;
}

/* A normal operand with a random sign, significand and exponent field in [lo, hi]. */
static uint32_t rand_normal(uint64_t *rng, int lo, int hi)
{
    return pack(rnd(rng, 2), (uint32_t)rnd_range(rng, lo, hi), rand_mantissa(rng));
}

/* ------------------------------------------------------------------ directed families */

typedef struct { fp32_case_t *out; size_t n; fp32_unit_t unit; } list_t;

static void put(list_t *l, uint64_t a, uint32_t b, uint32_t sub)
{
    if (l->unit == FP32_SQR || l->unit == FP32_U2F) b = 0;
    if (l->out) {
        fp32_case_t *c = &l->out[l->n];
        c->a = a; c->b = b; c->sub = sub;
        c->y = fp32_expect(l->unit, a, b, sub);
    }
    l->n++;
}

/* Every pair of special classes (for add, both a + b and a - b). */
static void fam_specials(list_t *l)
{
    for (size_t i = 0; i < N_SPECIALS; i++) {
        if (l->unit == FP32_SQR) { put(l, SPECIALS[i], 0, 0); continue; }
        for (size_t j = 0; j < N_SPECIALS; j++) {
            put(l, SPECIALS[i], SPECIALS[j], 0);
            if (l->unit == FP32_ADD) put(l, SPECIALS[i], SPECIALS[j], 1);
        }
    }
}

/* Exact ties: the exact result lies half-way between two neighbours, LSB odd or even. */
static void fam_ties(list_t *l, uint64_t *rng)
{
    for (int n = 0; n < 400; n++) {
        uint32_t a, b;
        switch (l->unit) {
        case FP32_ADD: {
            /* a plus (or minus) half an ulp of a, or one and a half ulps. */
            int e = rnd_range(rng, 2, 254);
            a = pack(rnd(rng, 2), (uint32_t)e, rand_mantissa(rng));
            int k = e - 151;                                  /* log2(half an ulp of a) */
            double h = ldexp(rnd(rng, 2) ? 1.0 : 3.0, k);
            b = bits_of(rnd(rng, 2) ? h : -h);
            if (fp32_is_nan(b) || (b & 0x7FFFFFFFu) == 0) continue;
            put(l, a, b, rnd(rng, 2));
            break;
        }
        case FP32_MUL: {
            /* Odd A, B with A * B in [2^24, 2^25): 25 significant bits, the last one a half ulp. */
            uint32_t A = (uint32_t)rnd_range(rng, 4096, 8191) | 1u;
            uint32_t lo = (uint32_t)((16777216ull + A - 1) / A), hi = (uint32_t)((33554431ull) / A);
            uint32_t B = (lo + rnd(rng, hi - lo + 1)) | 1u;
            if ((uint64_t)A * B >= 33554432ull) B -= 2;
            int t = rnd_range(rng, -175, 102);              /* result near 2^(t + 24) */
            int ka = rnd_range(rng, -130, 110);
            if (scaled(A, ka, &a) || scaled(B, t - ka, &b)) continue;
            a |= rnd(rng, 2) << 31; b |= rnd(rng, 2) << 31;
            put(l, a, b, 0);
            break;
        }
        case FP32_SQR: {
            uint32_t m = (uint32_t)rnd_range(rng, 4097, 5792) | 1u;
            if (scaled(m, rnd_range(rng, -90, 50), &a)) continue;
            put(l, a | rnd(rng, 2) << 31, 0, 0);
            break;
        }
        case FP32_DIV: {
            /* Odd A divided by a power of two landing it on the subnormal grid with a half. */
            uint32_t A = (uint32_t)rnd_range(rng, 1, 16777215) | 1u;
            int k = rnd_range(rng, 1, 126);                  /* b = 2^k */
            if (scaled(A, k - 150, &a) || scaled(1.0, k, &b)) continue;
            put(l, a | rnd(rng, 2) << 31, b | rnd(rng, 2) << 31, 0);
            break;
        }
        default: return;   /* cmp, and the units with families of their own */
        }
    }
}

/* Results on and next to the overflow and underflow thresholds. */
static void fam_thresholds(list_t *l, uint64_t *rng)
{
    static const double targets_log2[] = { 128, -126, -149, -150 };
    if (l->unit == FP32_CMP) return;
    if (l->unit == FP32_ADD) {
        /* Largest normal plus amounts around its half ulp (2^103), both signs. */
        static const uint32_t near_half[] = { 0x73000000u, 0x72FFFFFFu, 0x73000001u, 0x73800000u,
                                              0x72800000u, 0x73400000u };
        for (size_t i = 0; i < sizeof near_half / sizeof near_half[0]; i++)
            for (uint32_t s = 0; s < 2; s++) {
                put(l, 0x7F7FFFFFu | s << 31, near_half[i] | s << 31, 0);
                put(l, 0x7F7FFFFEu | s << 31, near_half[i] | s << 31, 0);
                put(l, 0x7F7FFFFFu | s << 31, near_half[i] | (s ^ 1) << 31, 1);
            }
        /* Sums and differences around the smallest normal. */
        for (uint32_t m = 0; m < 8; m++) {
            put(l, 0x00800000u + m, 0x80000001u + m, 0);
            put(l, 0x007FFFFFu - m, 0x00000001u + m, 0);
            put(l, 0x00800000u, 0x00000001u + m, 1);
        }
        return;
    }
    for (size_t t = 0; t < sizeof targets_log2 / sizeof targets_log2[0]; t++) {
        double target = ldexp(1.0, (int)targets_log2[t]);
        for (int n = 0; n < 60; n++) {
            double scale = rnd(rng, 2) ? 1.0 : (1.0 - ldexp(1.0, -24)) ;
            uint32_t a = rand_normal(rng, 40, 214), b;
            double av = fp32_from_bits(a) < 0 ? -fp32_from_bits(a) : fp32_from_bits(a);
            double want = target * scale;
            if (l->unit == FP32_SQR) {
                if (targets_log2[t] < -126) continue;   /* subnormal squares of normals: none */
                b = bits_of(sqrt(want));
                for (int d = -2; d <= 2; d++) put(l, (uint32_t)((int)b + d), 0, 0);
                continue;
            }
            b = bits_of(l->unit == FP32_MUL ? want / av : av / want);
            if (fp32_is_nan(b) || (b & 0x7F800000u) == 0x7F800000u || (b & 0x7F800000u) == 0) continue;
            for (int d = -2; d <= 2; d++) {
                uint32_t bb = (uint32_t)((int)b + d) | (rnd(rng, 2) << 31);
                put(l, a, bb, 0);
            }
        }
    }
}

/* Total and partial cancellation, and operands one ulp apart across binades. */
static void fam_cancel(list_t *l, uint64_t *rng)
{
    if (l->unit != FP32_ADD) return;
    for (int n = 0; n < 300; n++) {
        uint32_t a = rnd(rng, 4) == 0 ? pack(rnd(rng, 2), 0, rand_mantissa(rng))
                                      : rand_normal(rng, 1, 254);
        uint32_t s = a & 0x80000000u;
        put(l, a, a, 1);                                      /* x - x = +0 */
        put(l, a, a ^ 0x80000000u, 0);                        /* x + (-x) = +0 */
        put(l, a ^ 0x80000000u, a, 0);
        put(l, a, a + 1, 1);                                  /* one ulp apart */
        put(l, a, (a & 0x7FFFFFFFu) ? a - 1 : a, 1);
        /* Next binade down: 1.000..x - 0.111..y, a difference of one exponent. */
        uint32_t below = s | (((a & 0x7F800000u) - (1u << 23)) & 0x7F800000u) | 0x7FFFFFu;
        if ((a & 0x7F800000u) > (1u << 23)) put(l, a, below ^ (rnd(rng, 4) << 0), 1);
    }
    put(l, 0x80000000u, 0x00000000u, 1);                      /* -0 - +0 = -0 */
    put(l, 0x80000000u, 0x80000000u, 0);                      /* -0 + -0 = -0 */
    put(l, 0x00000000u, 0x80000000u, 0);                      /* +0 + -0 = +0 */
}

/* Small integers: exact results (and exact quotients for div). */
static void fam_exact(list_t *l)
{
    for (int i = -8; i <= 16; i++)
        for (int j = -8; j <= 16; j++) {
            if (j == 0 || i == 0) continue;
            uint32_t a = bits_of(i), b = bits_of(j);
            switch (l->unit) {
            case FP32_ADD: put(l, a, b, (uint32_t)(i + j) & 1u); break;
            case FP32_MUL: put(l, a, b, 0); break;
            case FP32_SQR: if (j == 1) put(l, a, 0, 0); break;
            case FP32_DIV: put(l, bits_of((double)i * j), b, 0); break;
            case FP32_CMP: put(l, a, b, 0); break;
            default: return;
            }
        }
}

/* Comparator: equal, neighbouring and sign-flipped pairs of every special class. */
static void fam_cmp(list_t *l)
{
    if (l->unit != FP32_CMP) return;
    for (size_t i = 0; i < N_SPECIALS; i++) {
        uint32_t a = SPECIALS[i];
        put(l, a, a, 0); put(l, a, a + 1, 0); put(l, a + 1, a, 0);
        put(l, a, a - 1, 0); put(l, a, a ^ 0x80000000u, 0);
    }
}

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
    switch (rnd(rng, 8)) {
    case 4: for (int i = rnd_range(rng, 1, 3); i > 0; i--) m |= 1ull << rnd(rng, (uint32_t)n);
            return m;
    case 5: m = mask;
            for (int i = rnd_range(rng, 0, 3); i > 0; i--) m &= ~(1ull << rnd(rng, (uint32_t)n));
            return m;
    case 6: { int lo = (int)rnd(rng, (uint32_t)n), len = rnd_range(rng, 1, n - lo);
              return (len >= 64 ? ~0ull : ((1ull << len) - 1) << lo) & mask; }
    case 7: return rnd(rng, 4) == 0 ? 0 : rnd(rng, 4) == 0 ? mask : fp32_rng_next(rng) & 7u & mask;
    default: return fp32_rng_next(rng) & mask;
    }
}

static uint64_t wide(uint32_t e, uint64_t m) { return (uint64_t)(e & 0xFFu) << 56 | (m & WIDE_M_MASK); }

/* A wide word with effective exponent x (1..254): normal with M[55] = 1, or for x = 1 now and
 * then an "e = 0" word (M[55] = 0: zero or subnormal). */
static uint64_t wide_at(uint64_t *rng, int x)
{
    if (x == 1 && rnd(rng, 4) == 0) return wide(0, rand_bits(rng, 55));
    return wide((uint32_t)x, WIDE_LEAD | rand_bits(rng, 55));
}

/* A positive binary32 term with effective exponent x (1..254), subnormal now and then at x = 1. */
static uint32_t term_at(uint64_t *rng, int x)
{
    if (x == 1 && rnd(rng, 4) == 0) return pack(0, 0, rand_mantissa(rng));
    return pack(0, (uint32_t)x, rand_mantissa(rng));
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
    uint32_t r = rnd(rng, 64);
    if (r < 6) return WIDE_SPECIALS[rnd(rng, N_WIDE_SPECIALS)];
    if (r < 10) return fp32_rng_next(rng);                      /* any word, non-canonical too */
    if (r < 12) return wide(255, rand_bits(rng, 56));           /* infinity or a NaN */
    if (r < 20) return wide(0, rand_bits(rng, 55));             /* e = 0 */
    if (r < 26) return wide_at(rng, rnd_range(rng, 240, 254));  /* near saturation */
    return wide_at(rng, rnd_range(rng, 1, 254));
}

/* wacc: every wide special against every binary32 special. */
static void fam_wacc_specials(list_t *l)
{
    for (size_t i = 0; i < N_WIDE_SPECIALS; i++)
        for (size_t j = 0; j < N_SPECIALS; j++) put(l, WIDE_SPECIALS[i], SPECIALS[j], 0);
}

/* wacc: every exponent difference xa - xt from -72 to 72 (shifts of 56 and more drop the
 * smaller operand), both operands random, and the larger one's significand all ones. */
static void fam_wacc_align(list_t *l, uint64_t *rng)
{
    for (int d = -72; d <= 72; d++)
        for (int n = 0; n < 6; n++) {
            int xa = rnd_range(rng, d > 0 ? 1 + d : 1, d < 0 ? 254 + d : 254), xt = xa - d;
            uint64_t a = wide_at(rng, xa);
            uint32_t t = term_at(rng, xt);
            if (n == 0) a |= WIDE_M_MASK >> 1;                  /* M = all ones: carries */
            if (n == 1) t |= 0x7FFFFFu;
            put(l, a, t, 0);
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
                put(l, wide((uint32_t)x, dense), pack(0, (uint32_t)(x - d), 0x7FFFFFu), 0);
                put(l, wide((uint32_t)x, WIDE_M_MASK), pack(0, (uint32_t)(x - d), rand_mantissa(rng)), 0);
            }
            if (x + d <= 254)                                   /* t big, A aligned */
                put(l, wide((uint32_t)x, dense), pack(0, (uint32_t)(x + d), 0x7FFFFFu - rnd(rng, 4)), 0);
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
            put(l, tops[i], pack(0, (uint32_t)(254 - d), 0x7FFFFFu), 0);
            put(l, tops[i], pack(0, (uint32_t)(254 - d), rand_mantissa(rng)), 0);
        }
    put(l, WIDE_ZERO, 0x7F7FFFFFu, 0);                          /* FLT_MAX: exactly e = 254 */
    put(l, 0xFD80000000000000ull, 0x7F000000u, 0);              /* 2^126 + 2^127: no carry */
    put(l, 0xFE80000000000000ull, 0x7F000000u, 0);              /* 2^127 + 2^127: saturates */
    put(l, 0xFDFFFFFFFFFFFFFFull, 0x7E800000u, 0);              /* carry into e = 254 */
}

/* wacc: e = 0 words and subnormal terms: sums that stay below bit 55 (e field 0) and sums that
 * reach it (e field 1). */
static void fam_wacc_subnormal(list_t *l, uint64_t *rng)
{
    put(l, 0x007FFFFFFFFFFFFFull, 0x00000001u, 0);              /* largest e = 0 + smallest t */
    put(l, 0x007FFFFF00000000ull, 0x00000001u, 0);
    put(l, 0x0000000000000000ull, 0x007FFFFFu, 0);
    put(l, 0x0040000000000000ull, 0x00400000u, 0);              /* 2^54 + 2^54 = 2^55: e 1 */
    for (int n = 0; n < 300; n++) {
        uint64_t a = wide(0, rand_bits(rng, 55));
        uint32_t t = rnd(rng, 3) ? pack(0, 0, rand_mantissa(rng)) : pack(0, 1 + rnd(rng, 3), rand_mantissa(rng));
        if (rnd(rng, 5) == 0) a = wide_at(rng, rnd_range(rng, 1, 3));
        put(l, a, t, 0);
    }
}

static void wacc_random(uint64_t *rng, fp32_case_t *c)
{
    uint64_t a;
    uint32_t t;
    int d, xa;
    switch (rnd(rng, 8)) {
    case 0:                                  /* anything: special words, negative, NaN, inf t */
        a = rand_wide(rng); t = rand_operand(rng);
        break;
    case 1: case 2: case 3: case 4:          /* exponent difference -72..72, or anywhere */
        d = rnd(rng, 4) ? rnd_range(rng, -72, 72) : rnd_range(rng, -253, 253);
        xa = rnd_range(rng, d > 0 ? 1 + d : 1, d < 0 ? 254 + d : 254);
        a = rnd(rng, 16) ? wide_at(rng, xa) : rand_wide(rng);
        t = term_at(rng, xa - d);
        break;
    case 5:                                  /* carries: dense significands, small differences */
        d = rnd_range(rng, -24, 33);
        xa = rnd_range(rng, d > 0 ? 1 + d : 1, d < 0 ? 254 + d : 254);
        a = wide((uint32_t)xa, WIDE_M_MASK ^ rand_bits(rng, rnd_range(rng, 1, 55)) ^ (fp32_rng_next(rng) & 1u));
        t = pack(0, (uint32_t)(xa - d), 0x7FFFFFu ^ (rnd(rng, 2) ? 0 : rand_mantissa(rng)));
        break;
    case 6:                                  /* near saturation */
        xa = rnd_range(rng, 250, 254);
        a = wide((uint32_t)xa, WIDE_M_MASK ^ (rnd(rng, 2) ? 0 : rand_bits(rng, 56)));
        a |= WIDE_LEAD;
        t = pack(0, (uint32_t)rnd_range(rng, 190, 254), rnd(rng, 2) ? 0x7FFFFFu : rand_mantissa(rng));
        break;
    default:                                 /* e = 0 words, subnormal and tiny terms */
        a = rnd(rng, 4) ? wide(0, rand_bits(rng, 55)) : wide_at(rng, rnd_range(rng, 1, 4));
        t = rnd(rng, 2) ? pack(0, 0, rand_mantissa(rng)) : pack(0, (uint32_t)rnd_range(rng, 1, 4), rand_mantissa(rng));
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
        for (int delta = -3; delta <= 3; delta++) put(l, (1ull << n) + (uint64_t)(int64_t)delta, 0, 0);
    for (uint64_t k = 0; k <= 64; k++) put(l, ~0ull - k, 0, 0);
    for (int s = 0; s < 64; s++) { put(l, ~0ull << s, 0, 0); put(l, ~0ull >> s, 0, 0); }
    for (int s = 1; s <= 40; s++) {                        /* the LSB has weight 2^s */
        static const uint64_t fixed[] = { 0x800000u, 0x800001u, 0xFFFFFEu, 0xFFFFFFu };
        for (int n = 0; n < 12; n++) {
            uint64_t m = n < 4 ? fixed[n] : (0x800000u | (fp32_rng_next(rng) & 0x7FFFFFu));
            uint64_t tie = m << s | 1ull << (s - 1);
            put(l, tie, 0, 0);
            put(l, tie - 1, 0, 0);
            put(l, tie + 1, 0, 0);
            if (s >= 2) put(l, tie | rand_bits(rng, s - 1), 0, 0);
        }
    }
}

static void u2f_random(uint64_t *rng, fp32_case_t *c)
{
    uint64_t k;
    int w, s;
    switch (rnd(rng, 4)) {
    case 0:                                  /* uniform */
        k = fp32_rng_next(rng);
        break;
    case 1:                                  /* a random bit width, varied patterns */
        w = rnd_range(rng, 1, 64);
        k = rand_bits(rng, w) | (rnd(rng, 8) ? 1ull << (w - 1) : 0);
        break;
    case 2:                                  /* ties and their neighbours */
        s = rnd_range(rng, 1, 40);
        k = (0x800000u | (fp32_rng_next(rng) & 0x7FFFFFu)) << s | 1ull << (s - 1);
        k += (uint64_t)(int64_t)rnd_range(rng, -1, 1);
        break;
    default:                                 /* near powers of two and near 2^64 - 1 */
        k = rnd(rng, 2) ? (1ull << rnd(rng, 64)) + (uint64_t)(int64_t)rnd_range(rng, -300, 300)
                        : ~0ull - rand_bits(rng, rnd_range(rng, 1, 40));
        break;
    }
    c->a = k; c->b = 0; c->sub = 0;
    c->y = fp32_expect(FP32_U2F, k, 0, 0);
}

static size_t build(fp32_unit_t unit, fp32_case_t *out)
{
    list_t l = { out, 0, unit };
    uint64_t rng = 0x5EED0F32ull + (uint64_t)unit;   /* directed lists are fixed */
    if (unit == FP32_WACC) {
        fam_wacc_specials(&l);
        fam_wacc_align(&l, &rng);
        fam_wacc_carry(&l, &rng);
        fam_wacc_saturate(&l, &rng);
        fam_wacc_subnormal(&l, &rng);
        return l.n;
    }
    if (unit == FP32_U2F) {
        fam_u2f(&l, &rng);
        return l.n;
    }
    fam_specials(&l);
    fam_ties(&l, &rng);
    fam_thresholds(&l, &rng);
    fam_cancel(&l, &rng);
    fam_exact(&l);
    fam_cmp(&l);
    return l.n;
}

static fp32_case_t *directed_list[FP32_N_UNITS];
static size_t directed_n[FP32_N_UNITS];

static void ensure(fp32_unit_t unit)
{
    if (directed_list[unit]) return;
    size_t n = build(unit, NULL);
    directed_list[unit] = malloc(n * sizeof(fp32_case_t));
    if (!directed_list[unit]) abort();
    directed_n[unit] = build(unit, directed_list[unit]);
}

size_t fp32_directed_count(fp32_unit_t unit) { ensure(unit); return directed_n[unit]; }

void fp32_directed(fp32_unit_t unit, size_t i, fp32_case_t *c)
{
    ensure(unit);
    *c = directed_list[unit][i];
}

/* ------------------------------------------------------------------ random cases */

void fp32_random(fp32_unit_t unit, uint64_t *rng, fp32_case_t *c)
{
    if (unit == FP32_WACC) { wacc_random(rng, c); return; }
    if (unit == FP32_U2F) { u2f_random(rng, c); return; }
    uint32_t a = rand_operand(rng), b = rand_operand(rng);
    int ea = (int)(a >> 23 & 0xFFu);
    uint32_t mode = rnd(rng, 8);
    switch (unit) {
    case FP32_ADD:
        if (mode == 1) b = with_exp(rng, b, ea + rnd_range(rng, -3, 3));          /* cancellation */
        else if (mode == 2) b = with_exp(rng, b, ea + rnd_range(rng, -30, 30));   /* alignment */
        else if (mode == 3) b = (a ^ (rnd(rng, 2) << 31)) + rnd(rng, 16) - 8;     /* near-equal */
        break;
    case FP32_MUL:   /* exponent sum near underflow (result 2^-160 .. 2^-120) or overflow */
        if (mode == 1 || mode == 2) b = with_exp(rng, b, rnd_range(rng, -160, -120) + 254 - ea);
        else if (mode == 3) b = with_exp(rng, b, rnd_range(rng, 122, 130) + 254 - ea);
        break;
    case FP32_SQR:
        if (mode == 1) a = with_exp(rng, a, rnd_range(rng, 40, 70));   /* square near underflow */
        else if (mode == 2) a = with_exp(rng, a, rnd_range(rng, 187, 192)); /* near overflow */
        b = 0;
        break;
    case FP32_DIV:   /* exponent difference near underflow or overflow */
        if (mode == 1 || mode == 2) b = with_exp(rng, b, ea - rnd_range(rng, -160, -120));
        else if (mode == 3) b = with_exp(rng, b, ea - rnd_range(rng, 122, 130));
        break;
    case FP32_CMP:
        if (mode == 1) b = a;
        else if (mode == 2) b = a ^ 0x80000000u;
        else if (mode == 3) b = a + rnd(rng, 5) - 2;
        break;
    default:
        break;
    }
    c->a = a; c->b = b;
    c->sub = unit == FP32_ADD ? rnd(rng, 2) : 0;
    c->y = fp32_expect(unit, a, b, c->sub);
}

/* ------------------------------------------------------------------ exhaustive sweep */

/* Squarer: every significand at exponent fields whose squares land around 2^-150 (52, 53:
 * smallest subnormal and half of it), in the subnormal range and across the smallest normal
 * (63, 64), in [1, 4) (127) and across the overflow threshold (190). The sign varies with the
 * significand; it must not matter. */
static const uint32_t SWEEP_EXPS[] = { 52, 53, 63, 64, 127, 190 };
#define N_SWEEP_EXPS (sizeof SWEEP_EXPS / sizeof SWEEP_EXPS[0])

size_t fp32_sweep_count(fp32_unit_t unit)
{
    return unit == FP32_SQR ? N_SWEEP_EXPS << 23 : 0;
}

void fp32_sweep(fp32_unit_t unit, size_t i, fp32_case_t *c)
{
    uint32_t man = (uint32_t)i & 0x7FFFFFu;
    c->a = pack((man >> 7) & 1u, SWEEP_EXPS[(i >> 23) % N_SWEEP_EXPS], man);
    c->b = 0; c->sub = 0;
    c->y = fp32_expect(unit, c->a, c->b, c->sub);
}
