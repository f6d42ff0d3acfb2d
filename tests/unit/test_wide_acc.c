// SPDX-License-Identifier: Apache-2.0
/* test_wide_acc.c: the stable datapath's wide accumulator model (model/pree/wide_acc.h) against
 * independent references: wide_add against the exact sum in 128-bit integer arithmetic,
 * truncated to the 56-bit significand of its own binade; u64_to_f32 against the C conversion
 * (float)k; wide_from_double / wide_to_double as an exact round trip for every double the
 * format holds; and hand-worked special cases in wide_add's priority order. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "fp32_ops.h"
#include "wide_acc.h"

typedef unsigned __int128 u128;

static uint64_t rng_next(uint64_t *s)
{
    uint64_t x = *s;                        /* xorshift64* */
    x ^= x >> 12; x ^= x << 25; x ^= x >> 27;
    *s = x;
    return x * 0x2545F4914F6CDD1DULL;
}

static int bit_length(u128 s)
{
    int n = 0;
    while (s) { n++; s >>= 1; }
    return n;
}

/* The reference: A (canonical: e >= 1 with M[55] = 1, or e = 0) plus a positive finite t, as the
 * exact sum S * 2^(m - 182) over the smaller effective exponent m, truncated to 56 bits at the
 * smallest exponent E >= max(1, m) that makes it fit; WIDE_MAX when E reaches 255. Only for
 * effective exponents at most 70 apart (S then fits 128 bits). */
static uint64_t truncated_exact_sum(uint64_t a, uint32_t t)
{
    const unsigned ea = wide_exp(a), et = (t >> 23) & 0xFFu;
    const int xa = ea ? (int)ea : 1, xt = et ? (int)et : 1;
    const uint64_t ma = wide_sig(a), mt = (uint64_t)((et ? 0x800000u : 0u) | (t & 0x7FFFFFu)) << 32;
    const int m = xa < xt ? xa : xt;
    const u128 s = ((u128)ma << (xa - m)) + ((u128)mt << (xt - m));
    const int len = bit_length(s);
    const int e = m + (len > 56 ? len - 56 : 0);
    if (e >= 255) return WIDE_MAX;
    const uint64_t sig = (uint64_t)(s >> (e - m));
    return ((uint64_t)((sig & WIDE_LEAD) ? e : 0) << 56) | sig;
}

/* A canonical finite wide word with exponent field e (0: M[55] = 0; else M[55] = 1). */
static uint64_t wide_word(unsigned e, uint64_t bits)
{
    const uint64_t m = e ? (WIDE_LEAD | (bits & (WIDE_LEAD - 1))) : (bits & (WIDE_LEAD - 1));
    return ((uint64_t)e << 56) | m;
}

/* Random significand bits: uniform, or sparse, or dense (carries and truncation both). */
static uint64_t rand_sig(uint64_t *s)
{
    const uint64_t r = rng_next(s);
    switch (r & 3) {
    case 0: return rng_next(s) & rng_next(s);
    case 1: return rng_next(s) | rng_next(s);
    default: return rng_next(s);
    }
}

/* Random normal and subnormal pairs with every exponent difference up to 70 equal the truncated
 * exact sum; beyond 56 the smaller one contributes nothing. */
static void test_add_truncated_exact(void **state)
{
    (void)state;
    uint64_t s = 0x57AB1E;
    long carries = 0, saturated = 0, dropped = 0;
    for (int i = 0; i < 400000; i++) {
        const int d = (int)(rng_next(&s) % 141) - 70;           /* xa - xt */
        int lo = d > 0 ? 1 + d : 1, hi = d < 0 ? 254 + d : 254;
        if ((i & 7) == 0) lo = hi > 240 ? 240 : lo;             /* weight the top of the range */
        int xa = lo + (int)(rng_next(&s) % (uint64_t)(hi - lo + 1)), xt = xa - d;
        unsigned ea = (unsigned)xa, et = (unsigned)xt;
        if (xa == 1 && (rng_next(&s) & 1)) ea = 0;              /* e = 0 words and subnormal t */
        if (xt == 1 && (rng_next(&s) & 1)) et = 0;
        const uint64_t a = wide_word(ea, rand_sig(&s));
        const uint32_t t = et << 23 | ((uint32_t)rand_sig(&s) & 0x7FFFFFu);
        const uint64_t want = truncated_exact_sum(a, t), got = wide_add(a, t);
        if (got != want) fail_msg("wide_add(%016llx, %08x) = %016llx, exact truncated %016llx",
                                  (unsigned long long)a, t, (unsigned long long)got,
                                  (unsigned long long)want);
        if (want == WIDE_MAX) saturated++;
        else if ((int)wide_exp(want) > (xa > xt ? xa : xt)) carries++;
        if (d >= 56 || d <= -56) dropped++;
    }
    /* The cases that matter occurred. */
    assert_true(carries > 10000);
    assert_true(saturated > 100);
    assert_true(dropped > 10000);
}

/* Far apart (71 to 253 binades): the result is the larger operand. */
static void test_add_far_apart(void **state)
{
    (void)state;
    uint64_t s = 0xFA7;
    for (int i = 0; i < 100000; i++) {
        const int d = 71 + (int)(rng_next(&s) % 183);
        const int big = d + 1 + (int)(rng_next(&s) % (uint64_t)(254 - d)), small = big - d;
        const uint64_t a_big = wide_word((unsigned)big, rng_next(&s));
        const uint32_t t_small = (uint32_t)small << 23 | ((uint32_t)rng_next(&s) & 0x7FFFFFu);
        assert_true(wide_add(a_big, t_small) == a_big);
        const uint64_t a_small = wide_word((unsigned)small, rng_next(&s));
        const uint32_t t_big = (uint32_t)big << 23 | ((uint32_t)rng_next(&s) & 0x7FFFFFu);
        const uint64_t t_wide = ((uint64_t)big << 56) | ((uint64_t)(0x800000u | (t_big & 0x7FFFFFu)) << 32);
        assert_true(wide_add(a_small, t_big) == t_wide);
    }
}

/* Special cases in wide_add's priority order, and a few sums worked by hand. */
static void test_add_special(void **state)
{
    (void)state;
    const uint64_t one = UINT64_C(0x7F80000000000000);        /* M = 2^55, e = 127: 1.0 */
    const uint64_t a_nan = UINT64_C(0xFF00000000000001);
    assert_true(wide_add(a_nan, 0x7FC00000u) == a_nan);        /* A NaN first */
    assert_true(wide_add(a_nan, 0xBF800000u) == a_nan);
    assert_true(wide_add(WIDE_INF, 0x7F800001u) == WIDE_NAN);  /* then t NaN */
    assert_true(wide_add(one, 0xFFC00000u) == WIDE_NAN);
    assert_true(wide_add(WIDE_INF, 0x3F800000u) == WIDE_INF);  /* then A infinite */
    assert_true(wide_add(WIDE_INF, 0x7F800000u) == WIDE_INF);
    assert_true(wide_add(one, 0xBF800000u) == one);            /* then t negative: dropped */
    assert_true(wide_add(one, 0xFF800000u) == one);
    assert_true(wide_add(one, 0x80000000u) == one);            /* -0 too */
    /* Dropped means untouched: a word whose M[55] disagrees with e stays as it is with -0, but
     * adding +0 re-encodes it (sum bit 55 is 0: e field 0). */
    assert_true(wide_add(UINT64_C(0x0500000000000001), 0x80000000u) == UINT64_C(0x0500000000000001));
    assert_true(wide_add(UINT64_C(0x0500000000000001), 0x00000000u) == UINT64_C(0x0000000000000001));
    assert_true(wide_add(one, 0x7F800000u) == WIDE_MAX);       /* then t = +inf */
    assert_true(wide_add(WIDE_ZERO, 0x7F800000u) == WIDE_MAX);

    assert_true(wide_add(one, 0x3F800000u) == UINT64_C(0x8080000000000000));   /* 1 + 1 = 2 */
    assert_true(wide_add(WIDE_ZERO, 0x3F800000u) == one);
    assert_true(wide_add(one, 0x00000000u) == one);
    assert_true(wide_add(WIDE_ZERO, 0x7F7FFFFFu) == UINT64_C(0xFEFFFFFF00000000)); /* FLT_MAX */
    assert_true(wide_add(WIDE_MAX, 0x3F800000u) == WIDE_MAX);
    assert_true(wide_add(UINT64_C(0xFE80000000000000), 0x7F000000u) == WIDE_MAX); /* 2^127 * 2 */
    /* 1 + 2^-56 (t = 2^-56 aligned 56 places down) is dropped; 1 + 2^-55 is the last bit. */
    assert_true(wide_add(one, 0x23800000u) == one);
    assert_true(wide_add(one, 0x24000000u) == one + 1);
    /* The largest e = 0 word plus the smallest subnormal reaches bit 55: e field 1. */
    assert_true(wide_add(UINT64_C(0x007FFFFFFFFFFFFF), 0x00000001u) == UINT64_C(0x01800000FFFFFFFF));
    assert_true(wide_f32(WIDE_MAX) == fp32_to_bits(FLT_MAX));
    assert_true(wide_f32(WIDE_INF) == 0x7F800000u);
    assert_true(fp32_is_nan(wide_f32(WIDE_NAN)));
}

/* u64_to_f32 is the C conversion: random values of every bit width, ties (both parities) and
 * their neighbours at every rounding position, powers of two and their neighbours. */
static void test_u64_to_f32_is_cast(void **state)
{
    (void)state;
    uint64_t s = 0xC0117;
    for (int i = 0; i < 1000000; i++) {
        uint64_t k;
        const int w = 1 + (int)(rng_next(&s) % 64);
        switch (i % 4) {
        case 0: k = rng_next(&s) >> (64 - w); break;
        case 1: k = (rng_next(&s) >> (64 - w)) | UINT64_C(1) << (w - 1); break;
        case 2: {                                               /* a tie, +- 1 */
            const int sh = 1 + (int)(rng_next(&s) % 40);
            k = ((UINT64_C(0x800000) | (rng_next(&s) & 0x7FFFFF)) << sh) | UINT64_C(1) << (sh - 1);
            k += (rng_next(&s) % 3) - 1;
            break;
        }
        default: k = (UINT64_C(1) << (w - 1)) + (rng_next(&s) % 7) - 3; break;
        }
        const uint32_t want = fp32_to_bits((float)k), got = u64_to_f32(k);
        if (got != want) fail_msg("u64_to_f32(%016llx) = %08x, (float)k = %08x",
                                  (unsigned long long)k, got, want);
    }
    assert_true(u64_to_f32(0) == 0);
    assert_true(u64_to_f32(1) == 0x3F800000u);
    assert_true(u64_to_f32((UINT64_C(1) << 24) + 1) == 0x4B800000u);    /* tie, even: down */
    assert_true(u64_to_f32((UINT64_C(1) << 24) + 3) == 0x4B800002u);    /* tie, odd: up */
    assert_true(u64_to_f32(UINT64_MAX) == 0x5F800000u);                 /* 2^64 */
}

/* Every double in the wide range with at most 53 significant bits survives the trip through a
 * wide word; in range the word is canonical and its binary32 slice truncates. */
static void test_double_round_trip(void **state)
{
    (void)state;
    uint64_t s = 0xD0B1E;
    for (int i = 0; i < 200000; i++) {
        /* Exponents from the e = 0 range (value >= 2^-181 * 2^52 keeps 53 bits) to 2^127. */
        const int ex = -129 + (int)(rng_next(&s) % 257);
        const double x = ldexp(1.0 + (double)(rng_next(&s) >> 12) * 0x1p-52, ex);
        const uint64_t w = wide_from_double(x);
        if (wide_to_double(w) != x) fail_msg("round trip of %a: %016llx -> %a", x,
                                             (unsigned long long)w, wide_to_double(w));
        const unsigned e = wide_exp(w);
        assert_true(e < 255 && (e == 0) == ((w & WIDE_LEAD) == 0));
        if (x >= 0x1p-126) {                     /* normal: the binary32 slice truncates */
            float tr = (float)x;
            if ((double)tr > x) tr = nextafterf(tr, 0.0f);
            assert_true(wide_f32(w) == fp32_to_bits(tr));
        }
    }
    /* e = 0 words: the value M * 2^-181 for any M below 2^53. */
    for (int i = 0; i < 100000; i++) {
        const uint64_t m = rng_next(&s) >> 11;
        assert_true(wide_from_double(ldexp((double)m, -181)) == m);
        assert_true(wide_to_double(m) == ldexp((double)m, -181));
    }
    assert_true(wide_from_double(0.0) == WIDE_ZERO);
    assert_true(wide_from_double(1.0) == UINT64_C(0x7F80000000000000));
    assert_true(wide_from_double(0x1p128) == WIDE_INF);
    assert_true(wide_from_double(INFINITY) == WIDE_INF);
    assert_true(wide_from_double(-1.0) == WIDE_NAN);
    assert_true(wide_from_double(NAN) == WIDE_NAN);
    assert_true(wide_from_double(0x1p-240) == WIDE_ZERO);
    assert_true(wide_to_double(WIDE_MAX) == ldexp(1.0, 128) - ldexp(1.0, 72));  /* rounded to 53 bits */
    assert_true(isinf(wide_to_double(WIDE_INF)) && isnan(wide_to_double(WIDE_NAN)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_add_truncated_exact),
        cmocka_unit_test(test_add_far_apart),
        cmocka_unit_test(test_add_special),
        cmocka_unit_test(test_u64_to_f32_is_cast),
        cmocka_unit_test(test_double_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
