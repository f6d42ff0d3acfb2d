// SPDX-License-Identifier: Apache-2.0
/* test_preu_stable_special.c: the stable PREU datapath model's defined behaviour on non-finite
 * and out-of-range inputs (docs/numerics.md, "Non-finite and out-of-range inputs";
 * tests/stress/stress_hitpoint --nonfinite prints the same cases). */
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

/* Photon flux and weight: NaN, infinite, negative and zero values. */
static void test_special_flux_weight(void **state)
{
    (void)state;
    const uint32_t kappa = preu_kappa(PREU_ALPHA);
    const preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f, 1.0f);
    preu_shp_t hp, ref, before;

    /* photon flux: NaN -> T NaN (w, k update); +inf -> T saturates; negative, -inf, -0: the term
     * is dropped (T unchanged), w and k update */
    static const uint32_t nan_flux[] = {0x7fc00000u, 0x7f800001u};
    for (int i = 0; i < 2; i++) {
        hp = fresh(1.0); ref = hp;
        preu_photon_t p = ph;
        p.phi[0] = p.phi[1] = p.phi[2] = nan_flux[i];
        assert_int_equal(preu_stable_update(&hp, &p, kappa), 1);
        preu_stable_update(&ref, &ph, kappa);
        assert_true(hp.T[0] == WIDE_NAN && hp.T[2] == WIDE_NAN);
        assert_true(hp.w == ref.w && hp.k == 1);
    }
    hp = fresh(1.0);
    preu_photon_t p = ph;
    p.phi[0] = p.phi[1] = p.phi[2] = 0x7f800000u;
    assert_int_equal(preu_stable_update(&hp, &p, kappa), 1);
    assert_true(hp.T[0] == WIDE_MAX && hp.T[1] == WIDE_MAX);
    static const uint32_t neg_flux[] = {0xff800000u, 0xbf800000u, 0x80000000u, 0x80000001u};
    for (int i = 0; i < 4; i++) {
        hp = fresh(1.0);
        preu_stable_update(&hp, &ph, kappa);
        before = hp; ref = hp;
        p = ph;
        p.phi[0] = p.phi[1] = p.phi[2] = neg_flux[i];
        assert_int_equal(preu_stable_update(&hp, &p, kappa), 1);
        preu_stable_update(&ref, &ph, kappa);
        assert_memory_equal(hp.T, before.T, sizeof hp.T);
        assert_true(hp.w == ref.w && hp.k == 2);
    }
    /* weight: negative dropped; 0 times an infinite flux is the default NaN: T NaN */
    hp = fresh(1.0);
    hp.f[0] = B(-1.0f); hp.f[1] = 0;
    p = ph; p.phi[1] = 0x7f800000u;
    assert_int_equal(preu_stable_update(&hp, &p, kappa), 1);
    assert_true(hp.T[0] == WIDE_ZERO);
    assert_true(hp.T[1] == WIDE_NAN);
}

/* Special inputs: photon positions out of range, initial radii at the ends of the range. */
static void test_special_position_r2(void **state)
{
    (void)state;
    const uint32_t kappa = preu_kappa(PREU_ALPHA);
    const preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f, 1.0f);
    preu_shp_t hp, before;
    preu_photon_t p;

    /* photon position NaN or infinite, or d2 overflowing: rejected, nothing changes */
    static const uint32_t bad_pos[] = {0x7fc00000u, 0x7f800000u, 0xff800000u, 0x7149f2cau /* 1e30 */};
    for (int i = 0; i < 4; i++) {
        hp = fresh(1.0); before = hp;
        p = ph; p.pos[1] = bad_pos[i];
        assert_int_equal(preu_stable_update(&hp, &p, kappa), 0);
        assert_memory_equal(&hp, &before, sizeof hp);
    }

    /* initial r2: 0 and below 1/FLT_MAX give w = inf (never accepts, not even d2 = 0); NaN,
     * negative and -0 give w NaN (never accepts); +inf gives w = 0: every finite d2 accepts,
     * w stays 0, an infinite d2 does not */
    static const double dead[] = {0.0, 1e-40, 2.9e-39, -0.0, -1.0, NAN};
    for (int i = 0; i < 6; i++) {
        hp = fresh(dead[i]); before = hp;
        assert_true(hp.w == (i < 3 ? WIDE_INF : WIDE_NAN));
        assert_int_equal(preu_stable_update(&hp, &ph, kappa), 0);
        assert_memory_equal(&hp, &before, sizeof hp);
    }
    hp = fresh(3e-39);                                   /* just inside: w < FLT_MAX, saturates */
    assert_true(hp.w != WIDE_INF && hp.w < WIDE_MAX);
    assert_int_equal(preu_stable_update(&hp, &ph, kappa), 1);
    assert_true(hp.w == WIDE_MAX);
    hp = fresh(INFINITY);
    assert_true(hp.w == WIDE_ZERO);
    p = ph; p.pos[0] = B(1e18f);                         /* d2 = 1e36, finite */
    assert_int_equal(preu_stable_update(&hp, &p, kappa), 1);
    assert_true(hp.w == WIDE_ZERO && hp.k == 1 && hp.T[0] == WIDE_ZERO);
    p.pos[0] = 0x7f800000u;
    assert_int_equal(preu_stable_update(&hp, &p, kappa), 0);
}

/* Special inputs: saturated w, and T infinite or NaN. */
static void test_special_w_T(void **state)
{
    (void)state;
    const uint32_t kappa = preu_kappa(PREU_ALPHA);
    const preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f, 1.0f);
    preu_shp_t hp;
    preu_photon_t p;

    /* w saturated (WIDE_MAX): accepts only d2 <= ~2.9e-39, stays saturated; T saturates */
    hp = fresh(1.0);
    hp.w = WIDE_MAX;
    assert_int_equal(preu_stable_update(&hp, &ph, kappa), 1);
    assert_true(hp.w == WIDE_MAX);
    assert_true(hp.T[0] == wide_from_double((double)(0.5f * FLT_MAX)));
    p = ph; p.pos[0] = B(10.0f + 0x1p-20f);
    assert_int_equal(preu_stable_update(&hp, &p, kappa), 0);
    hp.T[0] = WIDE_MAX;
    assert_int_equal(preu_stable_update(&hp, &ph, kappa), 1);
    assert_true(hp.T[0] == WIDE_MAX);

    /* T infinite or NaN (only from the host) stays so */
    hp = fresh(1.0);
    hp.T[0] = WIDE_INF; hp.T[1] = WIDE_NAN;
    assert_int_equal(preu_stable_update(&hp, &ph, kappa), 1);
    assert_true(hp.T[0] == WIDE_INF && hp.T[1] == WIDE_NAN);
}

/* Special inputs: kappa NaN, zero, negative and infinite, and the count wrapping. */
static void test_special_kappa_count(void **state)
{
    (void)state;
    const uint32_t kappa = preu_kappa(PREU_ALPHA);
    const preu_photon_t ph = photon_at(10.0f, 20.0f, 30.0f, 1.0f);
    preu_shp_t hp;

    /* kappa: NaN (alpha NaN) -> w NaN, then nothing is accepted; 0 (alpha 1) -> w constant;
     * negative (alpha > 1) -> the term dropped, w constant; inf (alpha 0) -> w saturates */
    hp = fresh(1.0);
    assert_int_equal(preu_stable_update(&hp, &ph, preu_kappa(0x7fc00000u)), 1);
    assert_true(hp.w == WIDE_NAN);
    assert_int_equal(preu_stable_update(&hp, &ph, kappa), 0);
    static const uint32_t flat[] = {0x3f800000u, 0x3fc00000u};
    for (int i = 0; i < 2; i++) {
        hp = fresh(1.0);
        const uint64_t w0 = hp.w;
        for (int j = 0; j < 3; j++) assert_int_equal(preu_stable_update(&hp, &ph, preu_kappa(flat[i])), 1);
        assert_true(hp.w == w0 && hp.k == 3);
    }
    hp = fresh(1.0);
    assert_int_equal(preu_kappa(0), 0x7f800000u);
    assert_int_equal(preu_stable_update(&hp, &ph, preu_kappa(0)), 1);
    assert_true(hp.w == WIDE_MAX);

    /* the count wraps at 2^64 (unreachable: centuries of photons): kf = 0, e = inf, w saturates */
    hp = fresh(1.0);
    hp.k = UINT64_MAX;
    assert_int_equal(preu_stable_update(&hp, &ph, kappa), 1);
    assert_true(hp.k == 0 && hp.w == WIDE_MAX);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_special_flux_weight),
        cmocka_unit_test(test_special_position_r2),
        cmocka_unit_test(test_special_w_T),
        cmocka_unit_test(test_special_kappa_count),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
