// SPDX-License-Identifier: Apache-2.0
/* test_hp_order.c: hp_order_apply moves every array of a hit-point set to new[k] = old[perm[k]]
 * (fixed points, 2-cycles and long cycles alike), hp_order_restore brings back the original
 * bits, and sets of 0 and 1 hit points and absent arrays are handled; hp_order_spatial returns
 * a permutation. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdlib.h>
#include <string.h>
#include "hp_order.h"

/* Element i of every array: bytes that differ from every other element's. */
static void fill(hitpoints_t *h, size_t n, int fp32)
{
    memset(h, 0, sizeof *h);
    h->n = h->cap = n;
    h->hot = calloc(n + 1, sizeof *h->hot);
    h->pixel = calloc(n + 1, sizeof *h->pixel);
    h->object = calloc(n + 1, sizeof *h->object);
    if (fp32) {
        h->fp32 = calloc(n + 1, sizeof *h->fp32);
        h->r2_f32 = calloc(n + 1, sizeof *h->r2_f32);
        h->dark = calloc(n + 1, 1);
    } else {
        h->acc = calloc(n + 1, sizeof *h->acc);
        h->r2 = calloc(n + 1, sizeof *h->r2);
        h->weight = calloc(n + 1, sizeof *h->weight);
    }
    for (size_t i = 0; i < n; i++) {
        h->hot[i].px = (double)i;
        h->pixel[i] = (int32_t)(7 * i + 1);
        h->object[i] = (uint32_t)(5 * i + 2);
        if (fp32) {
            memset(&h->fp32[i], (int)(i * 13 + 5) & 0xff, sizeof h->fp32[i]);
            memcpy(&h->fp32[i], &i, sizeof i < sizeof h->fp32[i] ? sizeof i : sizeof h->fp32[i]);
            h->r2_f32[i] = (uint32_t)(i ^ 0x5a5a5a5au);
            h->dark[i] = (uint8_t)(i & 1);
        } else {
            h->acc[i] = (hp_acc_t){v3((double)i, -(double)i, 0.5 * (double)i), (uint32_t)(3 * i), 0};
            h->r2[i] = 1.0 / (double)(i + 1);
            h->weight[i] = v3(2.0 * (double)i, 1, 0);
        }
    }
}

static void release(hitpoints_t *h)
{
    free(h->hot); free(h->pixel); free(h->object); free(h->fp32); free(h->r2_f32); free(h->dark);
    free(h->acc); free(h->r2); free(h->weight);
}

/* Every array of a holds at k what b holds at perm[k] (perm NULL: at k). */
static void assert_moved(const hitpoints_t *a, const hitpoints_t *b, const uint32_t *perm)
{
    for (size_t k = 0; k < a->n; k++) {
        const size_t j = perm ? perm[k] : k;
        assert_memory_equal(&a->hot[k], &b->hot[j], sizeof a->hot[k]);
        assert_int_equal(a->pixel[k], b->pixel[j]);
        assert_int_equal(a->object[k], b->object[j]);
        if (a->fp32) {
            assert_memory_equal(&a->fp32[k], &b->fp32[j], sizeof a->fp32[k]);
            assert_int_equal(a->r2_f32[k], b->r2_f32[j]);
            assert_int_equal(a->dark[k], b->dark[j]);
        } else {
            assert_memory_equal(&a->acc[k], &b->acc[j], sizeof a->acc[k]);
            assert_memory_equal(&a->r2[k], &b->r2[j], sizeof a->r2[k]);
            assert_memory_equal(&a->weight[k], &b->weight[j], sizeof a->weight[k]);
        }
    }
}

/* A permutation of n with fixed points, a 2-cycle and otherwise long cycles (a seeded shuffle). */
static uint32_t *mixed_perm(size_t n, unsigned seed)
{
    uint32_t *p = malloc((n + 1) * sizeof *p);
    for (size_t i = 0; i < n; i++) p[i] = (uint32_t)i;
    srand(seed);
    for (size_t i = n; i > 1; i--) {
        const size_t j = (size_t)rand() % i, t = p[i - 1];
        p[i - 1] = p[j];
        p[j] = (uint32_t)t;
    }
    if (n >= 6) {   /* fix 0 and 1 in place; swap 2 and 3 */
        for (uint32_t v = 0; v < 4; v++)
            for (size_t i = 0; i < n; i++)
                if (p[i] == v) { p[i] = p[v]; p[v] = v; break; }
        p[2] = 3;
        p[3] = 2;
    }
    return p;
}

static void run_case(size_t n, int fp32, unsigned seed)
{
    hitpoints_t h, ref;
    fill(&h, n, fp32);
    fill(&ref, n, fp32);
    uint32_t *perm = mixed_perm(n, seed);
    assert_int_equal(hp_order_apply(&h, perm), 0);
    assert_moved(&h, &ref, perm);
    assert_int_equal(hp_order_restore(&h, perm), 0);
    assert_moved(&h, &ref, NULL);
    free(perm);
    release(&h);
    release(&ref);
}

static void test_double_arrays(void **state)
{
    (void)state;
    run_case(1000, 0, 1);
    run_case(4099, 0, 2);
}

static void test_fp32_arrays(void **state)
{
    (void)state;
    run_case(1000, 1, 3);
}

static void test_tiny_sets(void **state)
{
    (void)state;
    run_case(0, 0, 4);
    run_case(1, 1, 5);
    run_case(2, 0, 6);
}

/* The spatial order visits every hit point once. */
static void test_spatial_is_permutation(void **state)
{
    (void)state;
    hitpoints_t h;
    const size_t n = 3000;
    fill(&h, n, 0);
    for (size_t i = 0; i < n; i++) {
        h.hot[i].px = (double)(i % 40);
        h.hot[i].py = (double)(i / 40 % 30);
        h.hot[i].pz = (double)(i % 7);
        h.pixel[i] = (int32_t)i;   /* a 40x75 image */
    }
    uint32_t *perm = hp_order_spatial(&h, 40, 2, 1.5);
    assert_non_null(perm);
    char *seen = calloc(n, 1);
    for (size_t k = 0; k < n; k++) {
        assert_true(perm[k] < n);
        assert_false(seen[perm[k]]);
        seen[perm[k]] = 1;
    }
    free(seen);
    free(perm);
    release(&h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_double_arrays),
        cmocka_unit_test(test_fp32_arrays),
        cmocka_unit_test(test_tiny_sets),
        cmocka_unit_test(test_spatial_is_permutation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
