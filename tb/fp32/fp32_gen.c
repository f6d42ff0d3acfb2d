// SPDX-License-Identifier: Apache-2.0
/* fp32_gen.c: directed and random test cases for the binary32 RTL units (see fp32_gen.h).
 *
 * Directed families: every pair of special classes; exact ties built from odd integers
 * (add, mul, sqr; div ties exist only on the subnormal grid); results straddling the overflow
 * threshold and the underflow thresholds (smallest normal, smallest subnormal and half of it);
 * total and partial cancellation; exact small-integer results; comparator neighbours.
 * Random operands cover the whole exponent range, with extra weight on subnormals, special
 * values, near-equal exponents (alignment and cancellation) and results near the thresholds.
 * The stable datapath's units (wacc, u2f) have their own families, in fp32_gen_wide.c.
 */
#include "fp32_gen.h"
#include "fp32_gen_cases.h"
#include "fp32_ops.h"
#include "wide_acc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The special classes of the issue plus a few neighbours of interesting boundaries. */
const uint32_t gen_specials[] = {
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
#define N_SPECIALS (sizeof gen_specials / sizeof gen_specials[0])
const size_t gen_n_specials = N_SPECIALS;

uint64_t fp32_rng_next(uint64_t *rng)
{
    /* xorshift64*: small, fast, and good enough to spread operands. */
    uint64_t x = *rng;
    x ^= x >> 12; x ^= x << 25; x ^= x >> 27;
    *rng = x;
    return x * 0x2545F4914F6CDD1DULL;
}

uint32_t gen_rnd(uint64_t *rng, uint32_t n) { return (uint32_t)(fp32_rng_next(rng) >> 32) % n; }
int gen_range(uint64_t *rng, int lo, int hi) { return lo + (int)gen_rnd(rng, (uint32_t)(hi - lo + 1)); }

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

uint32_t gen_pack(uint32_t sign, uint32_t exp, uint32_t man)
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
uint32_t gen_mantissa(uint64_t *rng)
{
    uint32_t m = 0;
    switch (gen_rnd(rng, 8)) {
    case 4: for (int i = gen_range(rng, 1, 3); i > 0; i--) m |= 1u << gen_rnd(rng, 23); return m;
    case 5: m = 0x7FFFFFu;
            for (int i = gen_range(rng, 0, 3); i > 0; i--) m &= ~(1u << gen_rnd(rng, 23));
            return m;
    case 6: { int lo = (int)gen_rnd(rng, 23), len = gen_range(rng, 1, 23 - lo);
              return (uint32_t)(((1ull << len) - 1) << lo) & 0x7FFFFFu; }
    case 7: return gen_rnd(rng, 4) == 0 ? 0 : gen_rnd(rng, 8);
    default: return (uint32_t)fp32_rng_next(rng) & 0x7FFFFFu;
    }
}

/* A random operand over the whole encoding space, weighted towards the interesting parts. */
uint32_t gen_operand(uint64_t *rng)
{
    uint32_t r = gen_rnd(rng, 64);
    if (r < 4) return gen_specials[gen_rnd(rng, N_SPECIALS)];
    if (r < 8) return (uint32_t)fp32_rng_next(rng);
    uint32_t e = gen_rnd(rng, 12) == 0 ? 0 : gen_rnd(rng, 64) == 0 ? 255 : 1 + gen_rnd(rng, 254);
    return gen_pack(gen_rnd(rng, 2), e, gen_mantissa(rng));
}

/* Set the exponent field of x to e when 1 <= e <= 254; otherwise return a fresh operand. */
static uint32_t with_exp(uint64_t *rng, uint32_t x, int e)
{
    if (e < 1 || e > 254) return gen_operand(rng);
    return (x & 0x807FFFFFu) | (uint32_t)e << 23;
}

/* A normal operand with a random sign, significand and exponent field in [lo, hi]. */
static uint32_t rand_normal(uint64_t *rng, int lo, int hi)
{
    return gen_pack(gen_rnd(rng, 2), (uint32_t)gen_range(rng, lo, hi), gen_mantissa(rng));
}

/* ------------------------------------------------------------------ directed families */

void gen_put(list_t *l, uint64_t a, uint32_t b, uint32_t sub)
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
        if (l->unit == FP32_SQR) { gen_put(l, gen_specials[i], 0, 0); continue; }
        for (size_t j = 0; j < N_SPECIALS; j++) {
            gen_put(l, gen_specials[i], gen_specials[j], 0);
            if (l->unit == FP32_ADD) gen_put(l, gen_specials[i], gen_specials[j], 1);
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
            int e = gen_range(rng, 2, 254);
            a = gen_pack(gen_rnd(rng, 2), (uint32_t)e, gen_mantissa(rng));
            int k = e - 151;                                  /* log2(half an ulp of a) */
            double h = ldexp(gen_rnd(rng, 2) ? 1.0 : 3.0, k);
            b = bits_of(gen_rnd(rng, 2) ? h : -h);
            if (fp32_is_nan(b) || (b & 0x7FFFFFFFu) == 0) continue;
            gen_put(l, a, b, gen_rnd(rng, 2));
            break;
        }
        case FP32_MUL: {
            /* Odd A, B with A * B in [2^24, 2^25): 25 significant bits, the last one a half ulp. */
            uint32_t A = (uint32_t)gen_range(rng, 4096, 8191) | 1u;
            uint32_t lo = (uint32_t)((16777216ull + A - 1) / A), hi = (uint32_t)((33554431ull) / A);
            uint32_t B = (lo + gen_rnd(rng, hi - lo + 1)) | 1u;
            if ((uint64_t)A * B >= 33554432ull) B -= 2;
            int t = gen_range(rng, -175, 102);              /* result near 2^(t + 24) */
            int ka = gen_range(rng, -130, 110);
            if (scaled(A, ka, &a) || scaled(B, t - ka, &b)) continue;
            a |= gen_rnd(rng, 2) << 31; b |= gen_rnd(rng, 2) << 31;
            gen_put(l, a, b, 0);
            break;
        }
        case FP32_SQR: {
            uint32_t m = (uint32_t)gen_range(rng, 4097, 5792) | 1u;
            if (scaled(m, gen_range(rng, -90, 50), &a)) continue;
            gen_put(l, a | gen_rnd(rng, 2) << 31, 0, 0);
            break;
        }
        case FP32_DIV: {
            /* Odd A divided by a power of two landing it on the subnormal grid with a half. */
            uint32_t A = (uint32_t)gen_range(rng, 1, 16777215) | 1u;
            int k = gen_range(rng, 1, 126);                  /* b = 2^k */
            if (scaled(A, k - 150, &a) || scaled(1.0, k, &b)) continue;
            gen_put(l, a | gen_rnd(rng, 2) << 31, b | gen_rnd(rng, 2) << 31, 0);
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
                gen_put(l, 0x7F7FFFFFu | s << 31, near_half[i] | s << 31, 0);
                gen_put(l, 0x7F7FFFFEu | s << 31, near_half[i] | s << 31, 0);
                gen_put(l, 0x7F7FFFFFu | s << 31, near_half[i] | (s ^ 1) << 31, 1);
            }
        /* Sums and differences around the smallest normal. */
        for (uint32_t m = 0; m < 8; m++) {
            gen_put(l, 0x00800000u + m, 0x80000001u + m, 0);
            gen_put(l, 0x007FFFFFu - m, 0x00000001u + m, 0);
            gen_put(l, 0x00800000u, 0x00000001u + m, 1);
        }
        return;
    }
    for (size_t t = 0; t < sizeof targets_log2 / sizeof targets_log2[0]; t++) {
        double target = ldexp(1.0, (int)targets_log2[t]);
        for (int n = 0; n < 60; n++) {
            double scale = gen_rnd(rng, 2) ? 1.0 : (1.0 - ldexp(1.0, -24)) ;
            uint32_t a = rand_normal(rng, 40, 214), b;
            double av = fp32_from_bits(a) < 0 ? -fp32_from_bits(a) : fp32_from_bits(a);
            double want = target * scale;
            if (l->unit == FP32_SQR) {
                if (targets_log2[t] < -126) continue;   /* subnormal squares of normals: none */
                b = bits_of(sqrt(want));
                for (int d = -2; d <= 2; d++) gen_put(l, (uint32_t)((int)b + d), 0, 0);
                continue;
            }
            b = bits_of(l->unit == FP32_MUL ? want / av : av / want);
            if (fp32_is_nan(b) || (b & 0x7F800000u) == 0x7F800000u || (b & 0x7F800000u) == 0) continue;
            for (int d = -2; d <= 2; d++) {
                uint32_t bb = (uint32_t)((int)b + d) | (gen_rnd(rng, 2) << 31);
                gen_put(l, a, bb, 0);
            }
        }
    }
}

/* Total and partial cancellation, and operands one ulp apart across binades. */
static void fam_cancel(list_t *l, uint64_t *rng)
{
    if (l->unit != FP32_ADD) return;
    for (int n = 0; n < 300; n++) {
        uint32_t a = gen_rnd(rng, 4) == 0 ? gen_pack(gen_rnd(rng, 2), 0, gen_mantissa(rng))
                                      : rand_normal(rng, 1, 254);
        uint32_t s = a & 0x80000000u;
        gen_put(l, a, a, 1);                                      /* x - x = +0 */
        gen_put(l, a, a ^ 0x80000000u, 0);                        /* x + (-x) = +0 */
        gen_put(l, a ^ 0x80000000u, a, 0);
        gen_put(l, a, a + 1, 1);                                  /* one ulp apart */
        gen_put(l, a, (a & 0x7FFFFFFFu) ? a - 1 : a, 1);
        /* Next binade down: 1.000..x - 0.111..y, a difference of one exponent. */
        uint32_t below = s | (((a & 0x7F800000u) - (1u << 23)) & 0x7F800000u) | 0x7FFFFFu;
        if ((a & 0x7F800000u) > (1u << 23)) gen_put(l, a, below ^ (gen_rnd(rng, 4) << 0), 1);
    }
    gen_put(l, 0x80000000u, 0x00000000u, 1);                      /* -0 - +0 = -0 */
    gen_put(l, 0x80000000u, 0x80000000u, 0);                      /* -0 + -0 = -0 */
    gen_put(l, 0x00000000u, 0x80000000u, 0);                      /* +0 + -0 = +0 */
}

/* Small integers: exact results (and exact quotients for div). */
static void fam_exact(list_t *l)
{
    for (int i = -8; i <= 16; i++)
        for (int j = -8; j <= 16; j++) {
            if (j == 0 || i == 0) continue;
            uint32_t a = bits_of(i), b = bits_of(j);
            switch (l->unit) {
            case FP32_ADD: gen_put(l, a, b, (uint32_t)(i + j) & 1u); break;
            case FP32_MUL: gen_put(l, a, b, 0); break;
            case FP32_SQR: if (j == 1) gen_put(l, a, 0, 0); break;
            case FP32_DIV: gen_put(l, bits_of((double)i * j), b, 0); break;
            case FP32_CMP: gen_put(l, a, b, 0); break;
            default: return;
            }
        }
}

/* Comparator: equal, neighbouring and sign-flipped pairs of every special class. */
static void fam_cmp(list_t *l)
{
    if (l->unit != FP32_CMP) return;
    for (size_t i = 0; i < N_SPECIALS; i++) {
        uint32_t a = gen_specials[i];
        gen_put(l, a, a, 0); gen_put(l, a, a + 1, 0); gen_put(l, a + 1, a, 0);
        gen_put(l, a, a - 1, 0); gen_put(l, a, a ^ 0x80000000u, 0);
    }
}

static size_t build(fp32_unit_t unit, fp32_case_t *out)
{
    list_t l = { out, 0, unit };
    uint64_t rng = 0x5EED0F32ull + (uint64_t)unit;   /* directed lists are fixed */
    if (unit == FP32_WACC || unit == FP32_U2F) {
        gen_wide_directed(&l, &rng);
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
    if (unit == FP32_WACC || unit == FP32_U2F) { gen_wide_random(unit, rng, c); return; }
    uint32_t a = gen_operand(rng), b = gen_operand(rng);
    int ea = (int)(a >> 23 & 0xFFu);
    uint32_t mode = gen_rnd(rng, 8);
    switch (unit) {
    case FP32_ADD:
        if (mode == 1) b = with_exp(rng, b, ea + gen_range(rng, -3, 3));          /* cancellation */
        else if (mode == 2) b = with_exp(rng, b, ea + gen_range(rng, -30, 30));   /* alignment */
        else if (mode == 3) b = (a ^ (gen_rnd(rng, 2) << 31)) + gen_rnd(rng, 16) - 8;     /* near-equal */
        break;
    case FP32_MUL:   /* exponent sum near underflow (result 2^-160 .. 2^-120) or overflow */
        if (mode == 1 || mode == 2) b = with_exp(rng, b, gen_range(rng, -160, -120) + 254 - ea);
        else if (mode == 3) b = with_exp(rng, b, gen_range(rng, 122, 130) + 254 - ea);
        break;
    case FP32_SQR:
        if (mode == 1) a = with_exp(rng, a, gen_range(rng, 40, 70));   /* square near underflow */
        else if (mode == 2) a = with_exp(rng, a, gen_range(rng, 187, 192)); /* near overflow */
        b = 0;
        break;
    case FP32_DIV:   /* exponent difference near underflow or overflow */
        if (mode == 1 || mode == 2) b = with_exp(rng, b, ea - gen_range(rng, -160, -120));
        else if (mode == 3) b = with_exp(rng, b, ea - gen_range(rng, 122, 130));
        break;
    case FP32_CMP:
        if (mode == 1) b = a;
        else if (mode == 2) b = a ^ 0x80000000u;
        else if (mode == 3) b = a + gen_rnd(rng, 5) - 2;
        break;
    default:
        break;
    }
    c->a = a; c->b = b;
    c->sub = unit == FP32_ADD ? gen_rnd(rng, 2) : 0;
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
    c->a = gen_pack((man >> 7) & 1u, SWEEP_EXPS[(i >> 23) % N_SWEEP_EXPS], man);
    c->b = 0; c->sub = 0;
    c->y = fp32_expect(unit, c->a, c->b, c->sub);
}
