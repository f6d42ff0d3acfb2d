// SPDX-License-Identifier: Apache-2.0
/* test_update_double.c: the double-mode progressive update (Eq. 1-2, M = 1, alpha = 0.7)
 * against hand-worked steps, and the reference program's initial radius. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <string.h>
#include "grid.h"
#include "update.h"

static hitpoints_t one_hit_point(vec3 weight)
{
    hitpoints_t h;
    memset(&h, 0, sizeof h);
    assert_int_equal(hitpoints_push(&h, v3(1, 2, 3), v3(0, 1, 0), weight, 0, 0), 0);
    assert_int_equal(hitpoints_init_double(&h, 1.0), 0);
    h.alpha = UPDATE_ALPHA;
    return h;
}

static void test_first_update(void **state)
{
    (void)state;
    hitpoints_t h = one_hit_point(v3(0.5, 0.25, 1.0));
    /* count 0: g = (0*0.7 + 0.7)/(0*0.7 + 1) = 0.7 */
    update_accept_double(&h, 0, v3(PREE_PI, 2 * PREE_PI, 0));
    assert_true(h.r2[0] == 0.7);
    assert_int_equal(h.acc[0].count, 1);
    /* flux = (0 + w*F*(1/pi)) * 0.7: w*F*(1/pi) = (0.5 pi, 0.5 pi, 0) / pi = (0.5, 0.5, 0) within rounding. */
    assert_true(h.acc[0].flux.x == ((0.5 * PREE_PI) * (1. / PREE_PI)) * 0.7);
    assert_true(h.acc[0].flux.y == ((0.25 * (2 * PREE_PI)) * (1. / PREE_PI)) * 0.7);
    assert_true(h.acc[0].flux.z == 0.0);
    assert_true(fabs(h.acc[0].flux.x - 0.35) < 1e-15);
    hitpoints_free(&h);
}

static void test_second_update(void **state)
{
    (void)state;
    hitpoints_t h = one_hit_point(v3(1, 1, 1));
    update_accept_double(&h, 0, v3(0, 0, 0));
    update_accept_double(&h, 0, v3(0, 0, 0));
    /* count 1: g = (0.7 + 0.7)/(0.7 + 1) = 14/17; r2 = 0.7 * 14/17 = 0.576470588... */
    double g1 = (1 * 0.7 + 0.7) / (1 * 0.7 + 1.0);
    assert_true(fabs(g1 - 14.0 / 17.0) < 1e-15);
    assert_true(h.r2[0] == 0.7 * g1);
    assert_true(fabs(h.r2[0] - 9.8 / 17.0) < 1e-15);
    assert_int_equal(h.acc[0].count, 2);
    hitpoints_free(&h);
}

/* Radius after n updates is r0^2 * prod (0.7k + 0.7)/(0.7k + 1): it only shrinks. */
static void test_radius_monotone(void **state)
{
    (void)state;
    hitpoints_t h = one_hit_point(v3(1, 1, 1));
    double prev = h.r2[0];
    for (int k = 0; k < 100000; k++) {
        update_accept_double(&h, 0, v3(1, 1, 1));
        assert_true(h.r2[0] < prev);
        prev = h.r2[0];
    }
    assert_true(h.r2[0] > 0);
    hitpoints_free(&h);
}

static void test_initial_radius(void **state)
{
    (void)state;
    hitpoints_t h;
    memset(&h, 0, sizeof h);
    hitpoints_push(&h, v3(0, 0, 0), v3(0, 1, 0), v3(1, 1, 1), 0, 0);
    hitpoints_push(&h, v3(3, 6, 9), v3(0, 1, 0), v3(1, 1, 1), 1, 0);
    /* ((3 + 6 + 9)/3) / ((2 + 2)/2) * 2 = 6 */
    assert_true(grid_initial_radius(&h, 2, 2) == 6.0);
    /* The safe radius covers binary32 rounding: strictly larger, by a small margin. */
    double rs = grid_safe_radius(6.0, 9.0);
    assert_true(rs > 6.0 && rs < 6.001);
    hitpoints_free(&h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_update),
        cmocka_unit_test(test_second_update),
        cmocka_unit_test(test_radius_monotone),
        cmocka_unit_test(test_initial_radius),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
