// SPDX-License-Identifier: Apache-2.0
/* test_halton.c: the reverse-permuted Halton sequence: hand-computed values, the first
 * dimension's stratification, range over every dimension, and the same bits as the digit loop
 * written with division. */
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

/* The digit loop written with plain division: halton() must give the same bits (it divides
 * by multiplication for indices below 2^32). */
static double halton_by_division(int b, long long j)
{
    static const int primes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73,
                                 79, 83, 89, 97, 101, 103, 107, 109, 113, 127, 131, 137, 139, 149, 151, 157, 163,
                                 167, 173, 179, 181, 191, 193, 197, 199, 211, 223, 227, 229, 233, 239, 241, 251,
                                 257, 263, 269, 271, 277, 281, 283};
    const int p = primes[b];
    const double f = 1.0 / (double)p;
    double h = 0.0, fct = f;
    while (j > 0) {
        int digit = (int)(j % p);
        h += (double)(digit == 0 ? 0 : p - digit) * fct;
        j /= p;
        fct *= f;
    }
    return h;
}

static void test_same_bits_as_division(void **state)
{
    (void)state;
    uint64_t x = 0x9E3779B97F4A7C15ull;
    for (int b = 0; b < HALTON_DIMENSIONS; b++) {
        for (long long j = 0; j < 3000; j++) assert_true(halton(b, j) == halton_by_division(b, j));
        for (int r = 0; r < 3000; r++) {
            x ^= x << 13; x ^= x >> 7; x ^= x << 17;
            long long j = (long long)(x & 0xFFFFFFFFull);
            assert_true(halton(b, j) == halton_by_division(b, j));
        }
        assert_true(halton(b, 0xFFFFFFFFll) == halton_by_division(b, 0xFFFFFFFFll));
        assert_true(halton(b, 0x100000000ll) == halton_by_division(b, 0x100000000ll));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_values),
        cmocka_unit_test(test_base2_stratified),
        cmocka_unit_test(test_range_all_dimensions),
        cmocka_unit_test(test_same_bits_as_division),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
