/* test_halton.c: the reverse-permuted Halton sequence: hand-computed values, the first
 * dimension's stratification, and range over every dimension. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include "halton.h"

static void test_hand_values(void **state)
{
    (void)state;
    assert_true(halton(0, 0) == 0.0);
    assert_true(halton(0, 1) == 0.5);       /* digit 1 -> 2-1 = 1, times 1/2 */
    assert_true(halton(0, 2) == 0.25);      /* digits 0,1 -> 0 + 1/4 */
    assert_true(halton(0, 3) == 0.75);      /* digits 1,1 -> 1/2 + 1/4 */
    assert_true(halton(1, 1) == 2.0 * (1.0 / 3.0));            /* digit 1 -> 3-1 = 2 */
    assert_true(halton(1, 2) == 1.0 * (1.0 / 3.0));            /* digit 2 -> 1 */
    assert_true(halton(1, 3) == 0.0 + 2.0 * ((1.0 / 3.0) * (1.0 / 3.0)));  /* digits 0,1 */
    assert_true(halton(1, 4) == 2.0 * (1.0 / 3.0) + 2.0 * ((1.0 / 3.0) * (1.0 / 3.0)));
    assert_true(halton(60, 1) == 282.0 * (1.0 / 283.0));       /* the 61st prime is 283 */
    assert_true(halton(2, 5) == 0.0 + 4.0 * ((1.0 / 5.0) * (1.0 / 5.0)));  /* 5 = "10" base 5 */
}

/* The first 2^k points of dimension 0 are exactly the multiples of 2^-k. */
static void test_base2_stratified(void **state)
{
    (void)state;
    const int n = 1 << 12;
    char *seen = calloc(n, 1);
    for (int j = 0; j < n; j++) {
        double v = halton(0, j) * n;
        assert_true(v == floor(v));
        assert_true(v >= 0 && v < n);
        assert_false(seen[(int)v]);
        seen[(int)v] = 1;
    }
    free(seen);
}

static void test_range_all_dimensions(void **state)
{
    (void)state;
    for (int b = 0; b < HALTON_DIMENSIONS; b++)
        for (long long j = 0; j < 20000; j += 7) {
            double v = halton(b, j);
            assert_true(v >= 0.0 && v < 1.0);
        }
    /* Large indices (long runs) stay in range too. */
    assert_true(halton(3, 5000000000LL) >= 0.0 && halton(3, 5000000000LL) < 1.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_values),
        cmocka_unit_test(test_base2_stratified),
        cmocka_unit_test(test_range_all_dimensions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
