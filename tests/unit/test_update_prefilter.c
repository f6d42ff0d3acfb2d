// SPDX-License-Identifier: Apache-2.0
/* test_update_prefilter.c: the screening's binary32 prefilter (model/ppm/update_prefilter.c) at
 * every vector level the processor has: it keeps every candidate whose double distance test
 * against the safe radius passes, also within a few ulps of the radius, at coordinates up to
 * the bound's magnitude, in entry order; it rejects the clearly far ones; lists of every length
 * up to 40 (the vectors' tails). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "update_prefilter.h"

#define N 4096

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double uniform(void)   /* [0, 1) */
{
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

/* Hit points on spheres around the photon p, at distances r_safe * (1 + k ulp) for small k (either
 * side of the radius) and at 0.5 and 1.5 r_safe: the double test as the screening computes it. */
static void check_level(simd_level_t level, double scale)
{
    static hp_hot_t hot[N];
    hitpoints_t h;
    memset(&h, 0, sizeof h);
    h.hot = hot;
    h.n = N;
    grid_t g;
    memset(&g, 0, sizeof g);
    g.kind = GRID_CELLS;
    g.max_abs_coord = scale;
    g.r_safe = 0.0123456789 * scale * 0.01 + 1e-9;
    const double rs2 = g.r_safe * g.r_safe;
    const double p[3] = {scale * 0.7 * (2 * uniform() - 1), scale * 0.7 * (2 * uniform() - 1), -scale * 0.69};
    for (size_t i = 0; i < N; i++) {
        double d[3], len = 0;
        for (int a = 0; a < 3; a++) { d[a] = 2 * uniform() - 1; len += d[a] * d[a]; }
        len = sqrt(len);
        const double f = i % 4 == 0 ? 0.5 : i % 4 == 1 ? 1.5 : 1 + ((double)(i % 97) - 48) * 0x1p-23;
        hot[i].px = p[0] + d[0] / len * g.r_safe * f;
        hot[i].py = p[1] + d[1] / len * g.r_safe * f;
        hot[i].pz = p[2] + d[2] / len * g.r_safe * f;
    }
    update_prefilter_t pf;
    assert_int_equal(update_prefilter_build(&pf, &h, &g, level), 0);
    assert_non_null(pf.xyz);
    assert_true(update_prefilter_covers(&pf, p[0], p[1], p[2]));
    uint32_t idx[N], out[N + PREFILTER_OUT_PAD];
    for (size_t i = 0; i < N; i++) idx[i] = (uint32_t)((i * 2654435761u) % N);   /* any order */
    for (size_t start = 0; start + 40 <= N; start += 40)
        for (size_t count = start < 1000 ? start / 40 : 40; count; count = 0) {
            const size_t n = update_prefilter_near(&pf, idx + start, count, p[0], p[1], p[2], out);
            size_t k = 0;
            for (size_t c = 0; c < count; c++) {
                const hp_hot_t *q = &hot[idx[start + c]];
                const double vx = q->px - p[0], vy = q->py - p[1], vz = q->pz - p[2];
                const double v2 = vx * vx + vy * vy + vz * vz;
                const int kept = k < n && out[k] == idx[start + c];
                if (!(v2 > rs2)) assert_true(kept);                 /* never a candidate lost */
                if (v2 > 1.1 * rs2) assert_false(kept);             /* the far ones go */
                k += kept;
            }
            assert_int_equal(k, n);                                 /* in order, nothing else */
        }
    update_prefilter_free(&pf);
}

static void test_every_level(void **state)
{
    (void)state;
    for (int level = SIMD_AVX2; level <= SIMD_AVX512; level++) {
        if (!cpu_simd_supported((simd_level_t)level)) continue;
        for (int r = 0; r < 20; r++) {
            check_level((simd_level_t)level, 1.0);
            check_level((simd_level_t)level, 137.5);
            check_level((simd_level_t)level, 1e6);
        }
    }
}

/* Scalar builds nothing (the exact tests run alone); an unbounded magnitude disables the bound. */
static void test_none(void **state)
{
    (void)state;
    hp_hot_t hot[1] = {{0}};
    hitpoints_t h;
    memset(&h, 0, sizeof h);
    h.hot = hot;
    h.n = 1;
    grid_t g;
    memset(&g, 0, sizeof g);
    g.kind = GRID_CELLS;
    g.r_safe = 1;
    g.max_abs_coord = 10;
    update_prefilter_t pf;
    assert_int_equal(update_prefilter_build(&pf, &h, &g, SIMD_SCALAR), 0);
    assert_null(pf.xyz);
    assert_false(update_prefilter_covers(&pf, 0, 0, 0));
    g.kind = GRID_SMALLPPM;
    assert_int_equal(update_prefilter_build(&pf, &h, &g, SIMD_AVX2), 0);
    assert_null(pf.xyz);
    assert_true(isinf(update_prefilter_bound(1, INFINITY)));
    assert_true(isinf(update_prefilter_bound(1, 0x1p61)));
    /* The bound sits just above r_safe^2: within a relative 1e-5 here. */
    const float t = update_prefilter_bound(1, 10);
    assert_true(t >= 1.0f && t < 1.00001f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_level),
        cmocka_unit_test(test_none),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
