// SPDX-License-Identifier: Apache-2.0
/* test_preu_fp32.c: the PREU binary32 model (model/pree/preu_fp32.c) against hand-worked cases,
 * its own full-datapath trace, and an independent plain-float version for random inputs.
 * Expected bit patterns in the hand-worked cases were derived with exact rational arithmetic
 * rounded to nearest even (not with the host's float unit). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>

#include "preu_fp32.h"

static uint32_t B(float f) { return fp32_to_bits(f); }

/* A hit point at (10, 20, 30) with radius squared r2, count n, zero flux, weight (0.5, 0.25, 1). */
static preu_hp_t fresh_hp(float r2, float n)
{
    preu_hp_t hp = {{B(10.0f), B(20.0f), B(30.0f)}, {B(0.5f), B(0.25f), B(1.0f)},
                    {0, 0, 0}, B(r2), B(n)};
    return hp;
}

static preu_photon_t photon_at(float x, float y, float z)
{
    preu_photon_t ph = {{B(x), B(y), B(z)}, {B(2.0f), B(2.0f), B(3.0f)}};
    return ph;
}

/* First accepted photon on a fresh hit point: N = 0, so g = (0 + 0.7f) / (0 + 1) = 0.7f exactly.
 * m = f*phi = (1, 0.5, 3) exactly; t = m * INV_PI; u = 0 + t = t; tau' = t * 0.7f. */
static void test_first_accept(void **state)
{
    (void)state;
    preu_hp_t hp = fresh_hp(1.0f, 0.0f);
    preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.n, PREU_ALPHA);
    assert_int_equal(hp.r2, PREU_ALPHA);            /* 1 * 0.7f */
    assert_int_equal(hp.tau[0], 0x3e642a1eu);       /* INV_PI * 0.7f */
    assert_int_equal(hp.tau[1], 0x3de42a1eu);       /* 0.5*INV_PI rounded, * 0.7f */
    assert_int_equal(hp.tau[2], 0x3f2b1f96u);       /* 3*INV_PI rounded, * 0.7f */
    assert_int_equal(hp.pos[0], B(10.0f));          /* position and weight never written */
    assert_int_equal(hp.f[1], B(0.25f));

    preu_trace_t tr;
    preu_hp_t hp0 = fresh_hp(1.0f, 0.0f);
    preu_update_trace(&tr, &hp0, &ph, PREU_ALPHA);
    assert_int_equal(tr.g, PREU_ALPHA);
    assert_int_equal(tr.n1, PREU_ONE);
    assert_int_equal(tr.t[0], PREU_INV_PI);
    assert_int_equal(tr.t[1], 0x3e22f983u);
    assert_int_equal(tr.t[2], 0x3f747644u);
    assert_int_equal(tr.d2, 0u);
}

/* Second and third accepts: N = 0.7f + 0.7f = 1.4f is exact (2 * 0.7f), N + 1 = 1.7f rounds,
 * g = 1.4f / 1.7f = 0x3f52d2d2; the third N = 2.1f is the first rounded count. */
static void test_second_third_accept(void **state)
{
    (void)state;
    preu_hp_t hp = fresh_hp(1.0f, 0.0f);
    preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    preu_trace_t tr;
    preu_update_trace(&tr, &hp, &ph, PREU_ALPHA);
    assert_int_equal(tr.na, 0x3fb33333u);
    assert_int_equal(tr.n1, 0x3fd9999au);
    assert_int_equal(tr.g, 0x3f52d2d2u);
    assert_int_equal(tr.r2n, 0x3f139393u);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.n, 0x3fb33333u);
    assert_int_equal(hp.r2, 0x3f139393u);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.n, 0x40066666u);            /* 2.0999999 */
}

/* A photon outside the radius leaves every word of the hit point as it was. */
static void test_rejected(void **state)
{
    (void)state;
    preu_hp_t hp = fresh_hp(1.0f, 5.0f);
    hp.tau[1] = B(7.0f);
    preu_hp_t before = hp;
    preu_photon_t ph = photon_at(11.0f, 21.0f, 30.0f); /* d2 = 2 > 1 */
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 0);
    assert_memory_equal(&hp, &before, sizeof hp);
    preu_trace_t tr;
    preu_update_trace(&tr, &before, &ph, PREU_ALPHA);
    assert_int_equal(tr.d2, B(2.0f));
    assert_int_equal(tr.accept, 0);
}

/* d2 exactly equal to r2 is accepted (d2 <= r2); one ulp less radius is not. */
static void test_distance_equals_radius(void **state)
{
    (void)state;
    preu_photon_t ph = photon_at(13.0f, 24.0f, 30.0f); /* d = (-3, -4, 0): d2 = 25 */
    preu_hp_t hp = fresh_hp(25.0f, 0.0f);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.r2, B(25.0f * 0.7f));
    hp = fresh_hp(25.0f, 0.0f);
    hp.r2 = B(25.0f) - 1u;
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 0);
    /* signed zeros: d2 = +0 against r2 = -0 is accepted (+0 <= -0) */
    hp = fresh_hp(0.0f, 0.0f);
    hp.r2 = 0x80000000u;
    ph = photon_at(10.0f, 20.0f, 30.0f);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
}

/* NaN and infinity: a NaN distance or radius never accepts; NaNs in the written-back state
 * follow the SSE rule (first operand's NaN, quieted), invalid operations give 0xFFC00000. */
static void test_nan_inf(void **state)
{
    (void)state;
    preu_hp_t hp = fresh_hp(1.0f, 0.0f), before;
    preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f);

    ph.pos[1] = 0x7fc01234u;                             /* NaN photon position */
    before = hp;
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 0);
    assert_memory_equal(&hp, &before, sizeof hp);

    ph = photon_at(10.0f, 20.0f, 30.0f);
    hp.r2 = 0x7f800001u;                                 /* signalling NaN radius */
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 0);

    hp = fresh_hp(1.0f, 0.0f);
    hp.pos[2] = ph.pos[2] = 0x7f800000u;                 /* inf - inf: default NaN distance */
    preu_trace_t tr;
    preu_update_trace(&tr, &hp, &ph, PREU_ALPHA);
    assert_int_equal(tr.d[2], FP32_DEFAULT_NAN);
    assert_int_equal(tr.d2, FP32_DEFAULT_NAN);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 0);

    hp = fresh_hp(1.0f, 0.0f);
    ph = photon_at(10.0f, 20.0f, 30.0f);
    hp.tau[0] = 0x7f800001u;                             /* sNaN flux: quieted, kept */
    hp.f[1] = 0xff812345u;                               /* NaN weight: m, t, u, tau' carry it */
    hp.f[2] = 0;  ph.phi[2] = 0x7f800000u;               /* 0 * inf: default NaN */
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.tau[0], 0x7fc00001u);
    assert_int_equal(hp.tau[1], 0xffc12345u);
    assert_int_equal(hp.tau[2], FP32_DEFAULT_NAN);
    assert_int_equal(hp.r2, PREU_ALPHA);

    hp = fresh_hp(1.0f, 0.0f);
    hp.n = 0xff800010u;                                  /* NaN count: g, r2', tau', N' all NaN */
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.n, 0xffc00010u);
    assert_int_equal(hp.r2, 0xffc00010u);
    assert_int_equal(hp.tau[0], 0xffc00010u);

    hp = fresh_hp(1.0f, 0.0f);
    hp.n = 0x7f800000u;                                  /* N = inf: g = inf / inf */
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.n, 0x7f800000u);
    assert_int_equal(hp.r2, FP32_DEFAULT_NAN);
}

/* N held in binary32: from 2^23 each + 0.7f adds 1 and g = 1 (the radius stops shrinking);
 * from 2^24 on N no longer grows. */
static void test_count_limits(void **state)
{
    (void)state;
    preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f);
    preu_hp_t hp = fresh_hp(1.0f, 8388608.0f);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.n, B(8388609.0f));
    assert_int_equal(hp.r2, B(1.0f));                    /* N + 0.7f = N + 1: g = 1 */
    hp = fresh_hp(1.0f, 16777216.0f);
    assert_int_equal(preu_update(&hp, &ph, PREU_ALPHA), 1);
    assert_int_equal(hp.n, B(16777216.0f));
    assert_int_equal(hp.r2, B(1.0f));                    /* N + 1 ties to even N: g = 1 */
}

static void test_radiance(void **state)
{
    (void)state;
    preu_hp_t hp = fresh_hp(1.0f, 0.0f);
    hp.tau[0] = B(1.0f); hp.tau[1] = B(2.0f); hp.tau[2] = B(0.5f);
    uint32_t L[3] = {0, 0, 0};
    preu_radiance(L, &hp, B(1.0f));                      /* k = 1 / PI_f rounds to INV_PI */
    assert_int_equal(L[0], 0x3ea2f983u);
    assert_int_equal(L[1], 0x3f22f983u);
    assert_int_equal(L[2], 0x3e22f983u);

    hp.r2 = B(0.25f);
    hp.tau[0] = B(3.0f); hp.tau[1] = 0; hp.tau[2] = B(1.0f);
    L[0] = B(1.0f); L[1] = B(0.5f); L[2] = 0;
    preu_radiance(L, &hp, preu_n_emitted(768000));       /* a = PI/4, b = a * 768000, k = 1/b */
    assert_int_equal(L[0], 0x3f80002au);
    assert_int_equal(L[1], B(0.5f));
    assert_int_equal(L[2], 0x35de83c5u);

    hp.r2 = 0;                                           /* r2 = 0: k = +inf, 0 * inf invalid */
    L[0] = L[1] = L[2] = 0;
    preu_radiance(L, &hp, B(1.0f));
    assert_int_equal(L[0], 0x7f800000u);
    assert_int_equal(L[1], FP32_DEFAULT_NAN);
}

static void test_boundary_rounding(void **state)
{
    (void)state;
    assert_int_equal(preu_f32(0.1), 0x3dcccccdu);
    assert_int_equal(preu_f32(1.0 + 0x1p-24), 0x3f800000u);          /* tie to even: down */
    assert_int_equal(preu_f32(1.0 + 3 * 0x1p-24), 0x3f800002u);      /* tie to even: up */
    assert_int_equal(preu_f32(1e39), 0x7f800000u);
    assert_int_equal(preu_f32(-1e-45), 0x80000001u);                 /* subnormal kept */
    assert_int_equal(preu_n_emitted(16777216u), B(16777216.0f));
    assert_int_equal(preu_n_emitted(16777217u), B(16777216.0f));     /* tie to even */
    assert_int_equal(preu_n_emitted(49152000u), B(49152000.0f));
}

/* xorshift64*: a fixed, portable random sequence. */
static uint64_t rng = 0x9E3779B97F4A7C15ull;
static uint32_t rnd32(void)
{
    rng ^= rng >> 12; rng ^= rng << 25; rng ^= rng >> 27;
    return (uint32_t)((rng * 0x2545F4914F6CDD1Dull) >> 32);
}
static float rndf(float lo, float hi) { return lo + (hi - lo) * (float)(rnd32() >> 8) * 0x1p-24f; }

/* Any bit pattern, biased towards special values. */
static uint32_t rnd_word(void)
{
    static const uint32_t sp[] = {0, 0x80000000u, 0x7f800000u, 0xff800000u, 0x7fc00000u,
                                  0x7f800001u, 0xffc00123u, 0x00000001u, 0x007fffffu,
                                  0x3f800000u, 0x7f7fffffu, 0x00800000u};
    uint32_t r = rnd32();
    if ((r & 7) == 0) return sp[(r >> 3) % (sizeof sp / sizeof sp[0])];
    return rnd32();
}

/* The independent version: the update written as plain float expressions, for NaN-free data. */
static int float_update(preu_hp_t *hp, const preu_photon_t *ph)
{
    float px = fp32_from_bits(hp->pos[0]) - fp32_from_bits(ph->pos[0]);
    float py = fp32_from_bits(hp->pos[1]) - fp32_from_bits(ph->pos[1]);
    float pz = fp32_from_bits(hp->pos[2]) - fp32_from_bits(ph->pos[2]);
    float r2 = fp32_from_bits(hp->r2), n = fp32_from_bits(hp->n);
    if (px * px + py * py + pz * pz > r2) return 0;
    float g = (n + 0.7f) / (n + 1.0f);
    for (int c = 0; c < 3; c++) {
        float t = fp32_from_bits(hp->f[c]) * fp32_from_bits(ph->phi[c]) * (float)(1.0 / 3.14159265358979);
        hp->tau[c] = fp32_to_bits((fp32_from_bits(hp->tau[c]) + t) * g);
    }
    hp->r2 = fp32_to_bits(r2 * g);
    hp->n = fp32_to_bits(n + 0.7f);
    return 1;
}

static void test_random_against_float(void **state)
{
    (void)state;
    int accepted = 0;
    for (int i = 0; i < 1000000; i++) {
        preu_hp_t hp;
        preu_photon_t ph;
        float r2 = rndf(0.01f, 1.0f), r = sqrtf(r2);
        for (int k = 0; k < 3; k++) {
            float p = rndf(0.0f, 200.0f);
            hp.pos[k] = B(p);
            ph.pos[k] = B(p + rndf(-r, r));
            hp.f[k] = B(rndf(0.0f, 1.0f));
            hp.tau[k] = B(rndf(0.0f, 1000.0f));
            ph.phi[k] = B(rndf(0.0f, 50.0f));
        }
        hp.r2 = B(r2);
        hp.n = B((float)(rnd32() % 100000) * 0.7f);
        preu_hp_t a = hp, b = hp;
        int ra = preu_update(&a, &ph, PREU_ALPHA), rb = float_update(&b, &ph);
        assert_int_equal(ra, rb);
        assert_memory_equal(&a, &b, sizeof a);
        accepted += ra;
    }
    /* the radius test must go both ways for this to mean anything */
    assert_true(accepted > 200000 && accepted < 800000);
}

/* preu_update (plain-float distance, fp32_ops write-back) equals the full explicit trace,
 * special values and NaN payloads included. */
static void test_random_against_trace(void **state)
{
    (void)state;
    int accepted = 0;
    for (int i = 0; i < 1000000; i++) {
        preu_hp_t hp;
        preu_photon_t ph;
        uint32_t *w = (uint32_t *)&hp;
        for (size_t k = 0; k < sizeof hp / 4; k++) w[k] = rnd_word();
        w = (uint32_t *)&ph;
        for (size_t k = 0; k < sizeof ph / 4; k++) w[k] = rnd_word();
        if (rnd32() & 1) {                               /* make acceptance common */
            memcpy(ph.pos, hp.pos, sizeof ph.pos);
            hp.r2 = B(1.0f);
        }
        preu_trace_t tr;
        preu_update_trace(&tr, &hp, &ph, PREU_ALPHA);
        preu_hp_t a = hp;
        int ra = preu_update(&a, &ph, PREU_ALPHA);
        assert_int_equal(ra, tr.accept);
        if (ra) {
            assert_memory_equal(a.tau, tr.tau_n, sizeof a.tau);
            assert_int_equal(a.r2, tr.r2n);
            assert_int_equal(a.n, tr.na);
        } else {
            assert_memory_equal(&a, &hp, sizeof a);
        }
        accepted += ra;
    }
    assert_true(accepted > 100000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_accept),
        cmocka_unit_test(test_second_third_accept),
        cmocka_unit_test(test_rejected),
        cmocka_unit_test(test_distance_equals_radius),
        cmocka_unit_test(test_nan_inf),
        cmocka_unit_test(test_count_limits),
        cmocka_unit_test(test_radiance),
        cmocka_unit_test(test_boundary_rounding),
        cmocka_unit_test(test_random_against_float),
        cmocka_unit_test(test_random_against_trace),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
