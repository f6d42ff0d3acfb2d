// SPDX-License-Identifier: Apache-2.0
/* test_preu_stable.c: the stable PREU datapath model (model/pree/preu_stable.c, model/pree/wide_acc.h):
 * its basic arithmetic by hand-worked and exactly representable cases, the trace against the
 * update on random inputs (every field, special values included), the screening radius as a
 * true and monotone bound, the wide accumulator's truncation bound, the count through 2^32, and
 * the radiance on special state (the special update inputs: test_preu_stable_special.c). */
#include <stdarg.h>
#include <float.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>

#include "preu_stable.h"
#include "preu_stable_fixtures.h"

/* The value of a wide word as a long double (exact: 56 bits fit in 64). */
static long double wide_ld(uint64_t a)
{
    const unsigned e = wide_exp(a);
    return ldexpl((long double)wide_sig(a), (e ? (int)e : 1) - 182);
}

/* xorshift64*: a fixed, portable random sequence. */
static uint64_t rng = 0x9E3779B97F4A7C15ull;
static uint64_t rnd64(void)
{
    rng ^= rng >> 12; rng ^= rng << 25; rng ^= rng >> 27;
    return rng * 0x2545F4914F6CDD1Dull;
}
static uint32_t rnd32(void) { return (uint32_t)(rnd64() >> 32); }

/* Any binary32 pattern, biased towards special values. */
static uint32_t rnd_word(void)
{
    static const uint32_t sp[] = {0, 0x80000000u, 0x7f800000u, 0xff800000u, 0x7fc00000u, 0x7f800001u,
                                  0xffc00123u, 0x00000001u, 0x007fffffu, 0x3f800000u, 0x7f7fffffu,
                                  0x00800000u, 0xbf800000u};
    uint32_t r = rnd32();
    if ((r & 7) == 0) return sp[(r >> 3) % (sizeof sp / sizeof sp[0])];
    return rnd32();
}

/* A well-formed finite wide word (e = 0 subnormal or 1..254 with the lead bit), or a special. */
static uint64_t rnd_wide(int specials)
{
    uint64_t r = rnd64();
    if (specials && (r & 7) == 0) {
        static const uint64_t sp[] = {WIDE_ZERO, WIDE_INF, WIDE_NAN, WIDE_MAX, 1, WIDE_LEAD >> 1,
                                      (UINT64_C(127) << 56) | WIDE_LEAD};
        return sp[(r >> 3) % (sizeof sp / sizeof sp[0])];
    }
    const unsigned e = (unsigned)(rnd64() % 256);
    const uint64_t m = rnd64() & WIDE_M_MASK;
    if (e == 0) return m & (WIDE_LEAD - 1);
    if (e == 255) return WIDE_MAX;
    return ((uint64_t)e << 56) | m | WIDE_LEAD;
}

/* First accept: k = 0 -> 1, e = kappa / 1, w' = w0 + w0 * kappa = w0 / alpha, exactly when
 * kappa and w0 * kappa are representable (alpha = 2^-j: kappa = 2^j - 1). */
static void test_first_accept_w(void **state)
{
    (void)state;
    static const float alphas[] = {0.5f, 0.25f, 0.125f, 1.0f};
    static const double w0s[] = {1.0, 3.0, 0.75, 0x1p-100, 0x1p100, 1234567.0, 0x1.fffffp-3};
    const preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f, 1.0f);
    for (size_t i = 0; i < sizeof alphas / sizeof alphas[0]; i++) {
        const uint32_t kappa = preu_kappa(B(alphas[i]));
        assert_int_equal(kappa, B(1.0f / alphas[i] - 1.0f));
        for (size_t j = 0; j < sizeof w0s / sizeof w0s[0]; j++) {
            preu_shp_t hp = fresh(1.0);
            hp.w = wide_from_double(w0s[j]);
            assert_int_equal(preu_stable_update(&hp, &ph, kappa), 1);
            assert_int_equal(hp.k, 1);
            assert_true(hp.w == wide_from_double(w0s[j] / alphas[i]));
            assert_true(preu_stable_r2(&hp) == alphas[i] / w0s[j]);
        }
    }
    /* alpha 0.7f (kappa not exact): w' = w0 + fl(w0 * kappa), within 2^-23 of w0 / alpha. */
    const uint32_t kappa = preu_kappa(PREU_ALPHA);
    assert_int_equal(kappa, 0x3edb6db8u);
    preu_shp_t hp = fresh(1.0);
    assert_true(hp.w == wide_from_double(1.0));
    assert_int_equal(preu_stable_update(&hp, &ph, kappa), 1);
    assert_true(hp.w == wide_add(wide_from_double(1.0), kappa));
    assert_true(fabs(wide_to_double(hp.w) * (double)F(PREU_ALPHA) - 1.0) < 0x1p-23);
}

/* T after one accept = f * phi * w0: t = fl(fl(f * phi) * w32), and 0 + t is exact. */
static void test_first_accept_T(void **state)
{
    (void)state;
    preu_shp_t hp = fresh(0.5);                          /* w0 = 2 */
    preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f, 3.0f);
    assert_int_equal(preu_stable_update(&hp, &ph, preu_kappa(PREU_ALPHA)), 1);
    assert_true(hp.T[0] == wide_from_double(3.0));       /* 0.5 * 3 * 2  */
    assert_true(hp.T[1] == wide_from_double(1.5));       /* 0.25 * 3 * 2 */
    assert_true(hp.T[2] == wide_from_double(6.0));       /* 1 * 3 * 2    */
    /* the host view tau = T r2 / PI: smallppm's (0 + f phi / PI) g with g = alpha */
    const double tau_ref = 0.5 * 3.0 / 3.14159265358979 * (double)F(PREU_ALPHA);
    assert_true(fabs(preu_stable_tau(&hp, 0) / tau_ref - 1.0) < 0x1p-22);
    for (int i = 0; i < 100000; i++) {
        const float f = (float)(rnd32() >> 8) * 0x1p-24f, phi = ldexpf((float)(rnd32() >> 8), -(int)(rnd32() % 40));
        const float w0 = ldexpf(1.0f + (float)(rnd32() >> 9) * 0x1p-23f, (int)(rnd32() % 200) - 100);
        preu_shp_t h = fresh(1.0);
        h.f[0] = B(f);
        h.w = wide_from_double((double)w0);
        preu_photon_t p = photon_at(10.0f, 20.0f, 30.0f, phi);
        assert_int_equal(preu_stable_update(&h, &p, preu_kappa(PREU_ALPHA)), 1);
        const float t = (f * phi) * w0;
        assert_true(h.T[0] == wide_from_double((double)t));
        assert_true(wide_f32(h.T[0]) == B(t));
    }
}

/* preu_stable_update (float distance, inline write-back) against the full trace: the same
 * decision, and on accept the trace's Tn, wn, kn; on reject nothing changes. Every field random. */
static void test_trace_against_update(void **state)
{
    (void)state;
    int accepted = 0;
    for (int i = 0; i < 500000; i++) {
        preu_shp_t hp;
        preu_photon_t ph;
        for (int c = 0; c < 3; c++) {
            hp.pos[c] = rnd_word(); hp.f[c] = rnd_word(); hp.T[c] = rnd_wide(1);
            ph.pos[c] = rnd_word(); ph.phi[c] = rnd_word();
        }
        hp.w = rnd_wide(1);
        const uint64_t r = rnd64();
        hp.k = (r & 3) == 0 ? (rnd64() >> (rnd32() % 64)) : (r & 3) == 1 ? UINT64_C(0xFFFFFFFF) - (r >> 60) : rnd64() % 100000;
        if (rnd32() & 1) {                               /* make acceptance common */
            memcpy(ph.pos, hp.pos, sizeof ph.pos);
            if (rnd32() & 1) hp.w = wide_from_double(1.0 / (1 + (rnd32() % 1000)));
        }
        const uint32_t kappa = (rnd32() & 7) ? preu_kappa(PREU_ALPHA) : rnd_word();
        preu_strace_t tr;
        preu_stable_update_trace(&tr, &hp, &ph, kappa);
        preu_shp_t a = hp;
        const int ra = preu_stable_update(&a, &ph, kappa);
        assert_int_equal(ra, tr.accept);
        assert_int_equal(ra, preu_stable_accepts(tr.d2, hp.w));
        if (ra) {
            for (int c = 0; c < 3; c++) assert_true(a.T[c] == tr.Tn[c]);
            assert_true(a.w == tr.wn);
            assert_true(a.k == tr.kn);
            assert_memory_equal(a.pos, hp.pos, sizeof a.pos);
            assert_memory_equal(a.f, hp.f, sizeof a.f);
        } else {
            assert_memory_equal(&a, &hp, sizeof a);
        }
        accepted += ra;
    }
    assert_true(accepted > 100000 && accepted < 400000);
}

/* preu_stable_screen_r2(w) is a true bound (accepts(d2, w) implies d2 <= rho) and never grows
 * as w grows; d2 drawn anywhere and within a few ulps of 1 / w32. */
static void test_screen_r2_bound_monotone(void **state)
{
    (void)state;
    int near_accepts = 0;
    for (int i = 0; i < 300000; i++) {
        const uint64_t w = rnd_wide(1);
        const uint32_t rho = preu_stable_screen_r2(w);
        const float w32 = F(wide_f32(w));
        uint32_t d2s[9];
        const float inv = 1.0f / w32;
        for (int j = 0; j < 8; j++) {
            uint32_t b = B(inv);
            if (!fp32_is_nan(b) && b < 0x7f800000u) b = (uint32_t)((int64_t)b + (int)(rnd32() % 9) - 4);
            if (b > 0x7f800000u) b = 0x7f800000u;
            d2s[j] = b;
        }
        d2s[8] = rnd_word();
        for (int j = 0; j < 9; j++) {
            if (preu_stable_accepts(d2s[j], w)) {
                near_accepts += j < 8;
                assert_false(fp32_is_nan(rho));
                assert_true(F(d2s[j]) <= F(rho));
            }
        }
        /* monotone: the wide encoding of finite non-negative values orders as the integers */
        const uint64_t w2 = rnd_wide(0);
        if (!wide_is_nan(w) && w != WIDE_INF && !wide_is_nan(w2)) {
            const uint64_t lo = w < w2 ? w : w2, hi = w < w2 ? w2 : w;
            assert_true(wide_to_double(lo) <= wide_to_double(hi));
            assert_true(F(preu_stable_screen_r2(lo)) >= F(preu_stable_screen_r2(hi)));
        }
    }
    assert_true(near_accepts > 100000);
    /* consecutive words near 1 and near the top of the range */
    for (uint64_t w = wide_from_double(0.75) - 5000; w < wide_from_double(0.75) + 5000; w++)
        assert_true(F(preu_stable_screen_r2(w)) >= F(preu_stable_screen_r2(w + 1)));
    const uint64_t below1 = wide_from_double(0.5) | WIDE_M_MASK;      /* the largest word below 1 */
    assert_true(wide_ld(below1) < 1.0L && wide_ld(below1) > 1.0L - 0x1p-55L);
    assert_true(F(preu_stable_screen_r2(below1)) >= F(preu_stable_screen_r2(wide_from_double(1.0))));
    assert_true(F(preu_stable_screen_r2(WIDE_MAX - 1)) >= F(preu_stable_screen_r2(WIDE_MAX)));
    assert_int_equal(preu_stable_screen_r2(WIDE_ZERO), 0x7f800000u);
    assert_true(fp32_is_nan(preu_stable_screen_r2(WIDE_NAN)));
}

/* wide_add: 0 + t exact, truncation below the last bit, the carry, saturation, and the loss
 * bound that docs/numerics.md uses (less than 2^-55 of the result per addition, never upward).
 * (tests/unit/test_wide_acc.c checks wide_add bit for bit against exact integer sums.) */
static void test_wide_add(void **state)
{
    (void)state;
    assert_true(wide_add(WIDE_ZERO, B(1.5f)) == wide_from_double(1.5));
    assert_true(wide_add(WIDE_ZERO, 1u) == 1ull << 32);                     /* 2^-149 */
    assert_true(wide_add(wide_from_double(1.0), B(0x1p-55f)) == wide_from_double(1.0) + 1); /* one ulp */
    assert_true(wide_add(wide_from_double(1.0), B(0x1p-56f)) == wide_from_double(1.0));     /* truncated */
    assert_true(wide_add(wide_from_double(1.0), B(1.0f)) == wide_from_double(2.0));         /* carry */
    assert_true(wide_add(WIDE_MAX, B(1.0f)) == WIDE_MAX);
    assert_true(wide_add(WIDE_MAX, 0x7f7fffffu) == WIDE_MAX);
    assert_true(wide_add(wide_from_double(0x1.fffffffffffffp127), 0x7f7fffffu) == WIDE_MAX); /* overflow */
    for (int i = 0; i < 300000; i++) {
        uint64_t a = rnd_wide(0);
        if (wide_exp(a) > 250) a = wide_from_double(1.0);
        uint32_t t = rnd32() & 0x7fffffffu;
        if ((t >> 23) == 255) t = B(1.0f);
        const uint64_t s = wide_add(a, t);
        const long double exact = wide_ld(a) + (long double)F(t), got = wide_ld(s);
        assert_true(got <= exact);                                           /* never upward */
        assert_true(got >= wide_ld(a));
        assert_true(exact - got <= ldexpl(got, -55) * (1.0L + 0x1p-7L) + ldexpl(1.0L, -181));
        if (a == WIDE_ZERO) assert_true(wide_f32(s) == t);
    }
}

/* The count is exact through 2^24 and 2^32; kf rounds, k does not; w keeps growing. */
static void test_count_through_2pow32(void **state)
{
    (void)state;
    const uint32_t kappa = preu_kappa(PREU_ALPHA);
    const preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f, 1.0f);
    static const uint64_t starts[] = {16777214, 4294967293ull, (UINT64_C(1) << 53) - 2};
    for (size_t i = 0; i < sizeof starts / sizeof starts[0]; i++) {
        preu_shp_t hp = fresh(1e-3);
        hp.k = starts[i];
        for (int j = 1; j <= 4; j++) {
            preu_strace_t tr;
            preu_stable_update_trace(&tr, &hp, &ph, kappa);
            assert_int_equal(tr.kf, B((float)(starts[i] + (uint64_t)j)));
            const uint64_t w_before = hp.w;
            assert_int_equal(preu_stable_update(&hp, &ph, kappa), 1);
            assert_true(hp.k == starts[i] + (uint64_t)j);
            assert_true(hp.w > w_before);
        }
    }
}

/* Radiance: L += T32 * (1 / ((PI * PI) * NE)); special T and NE. */
static void test_radiance(void **state)
{
    (void)state;
    preu_shp_t hp = fresh(1.0);
    hp.T[0] = wide_from_double(1.0); hp.T[1] = WIDE_NAN; hp.T[2] = WIDE_INF;
    uint32_t L[3] = {0, B(1.0f), 0};
    const uint32_t ne = preu_n_emitted(1000);
    preu_stable_radiance(L, &hp, ne);
    const float k = 1.0f / ((F(PREU_PI) * F(PREU_PI)) * 1000.0f);
    assert_int_equal(L[0], B(k));
    assert_int_equal(L[1], 0x7fc00000u);
    assert_int_equal(L[2], 0x7f800000u);
    /* the T view truncates: the low 32 significand bits of T never reach L */
    hp.T[0] = wide_from_double(1.0) | 0xFFFFFFFFu;
    L[0] = 0;
    preu_stable_radiance(L, &hp, ne);
    assert_int_equal(L[0], B(k));
    /* saturated T: a finite L; NE = 0: k = inf, T = 0 gives the default NaN */
    hp.T[0] = WIDE_MAX; hp.T[1] = WIDE_ZERO;
    L[0] = L[1] = 0;
    preu_stable_radiance(L, &hp, ne);
    assert_int_equal(L[0], B(FLT_MAX * k));
    preu_stable_radiance(L, &hp, 0);
    assert_int_equal(L[0], 0x7f800000u);
    assert_int_equal(L[1], FP32_DEFAULT_NAN);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_accept_w),
        cmocka_unit_test(test_first_accept_T),
        cmocka_unit_test(test_trace_against_update),
        cmocka_unit_test(test_screen_r2_bound_monotone),
        cmocka_unit_test(test_wide_add),
        cmocka_unit_test(test_count_through_2pow32),
        cmocka_unit_test(test_radiance),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
