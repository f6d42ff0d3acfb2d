// SPDX-License-Identifier: Apache-2.0
/* test_photon_map.c: the photon-map estimator's pieces against brute force on random point
 * sets: the kd-tree's runs (with duplicated points and points on split planes), the
 * clustered k-NN and nanoflann's naive k-NN against a sort of every photon (ties broken by
 * photon index, k larger than the photon count, an empty map, the normal test; the clustered
 * search on every prefilter path the processor runs, and the single-pass search), the fast
 * selection against a full sort, and the
 * clustering's invariants (every shading point in exactly one cluster, at most 16 each,
 * one object a cluster). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cluster.h"
#include "kdtree.h"
#include "knn_clustered.h"
#include "knn_naive.h"
#include "photon_tree.h"
#include "update.h"

static uint64_t rng_state;
static double rnd(void)   /* xorshift64*, uniform in [0, 1) */
{
    rng_state ^= rng_state >> 12; rng_state ^= rng_state << 25; rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ull) >> 11) * 0x1p-53;
}

/* n photons in the unit cube; with grid_step > 0 their coordinates snap to a grid (many
 * duplicates and equal distances). Normals point up, a quarter of them down. */
static photon_map_t make_map(size_t n, double grid_step)
{
    photon_map_t m = {0};
    m.p = calloc(n ? n : 1, sizeof *m.p);
    m.n = n;
    m.emitted = 1000;
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < 3; a++) {
            double v = rnd();
            m.p[i].x[a] = grid_step > 0 ? floor(v / grid_step) * grid_step : v;
        }
        m.p[i].n[1] = (i % 4 == 3) ? -1.0f : 1.0f;
        m.p[i].flux[0] = m.p[i].flux[1] = m.p[i].flux[2] = 1;
    }
    return m;
}

/* Brute force: the k nearest within r2max passing the normal test, in (d2, photon) order. */
static size_t brute_knn(const photon_map_t *m, const double q[3], const double n[3], size_t k, double r2max,
                        knn_cand_t *out)
{
    knn_cand_t *all = malloc((m->n ? m->n : 1) * sizeof *all);
    size_t c = 0;
    for (size_t i = 0; i < m->n; i++) {
        double dx = q[0] - m->p[i].x[0], dy = q[1] - m->p[i].x[1], dz = q[2] - m->p[i].x[2];
        double d2 = dx * dx + dy * dy + dz * dz;
        const float *pn = m->p[i].n;
        if (d2 <= r2max && n[0] * pn[0] + n[1] * pn[1] + n[2] * pn[2] > UPDATE_NORMAL_COS)
            all[c++] = (knn_cand_t){d2, (uint32_t)i, 0};
    }
    size_t got = knn_select(all, c, k);
    memcpy(out, all, got * sizeof *out);
    free(all);
    return got;
}

static void test_kdtree_empty(void **state)
{
    (void)state;
    kdtree_t t;
    double dummy[3] = {0, 0, 0};
    assert_int_equal(kdtree_build(&t, dummy, 3, 0), 0);
    kd_range_t *out = NULL;
    size_t n = 0, cap = 0;
    assert_int_equal(kdtree_runs(&t, dummy, 1.0, &out, &n, &cap), 0);
    assert_int_equal(n, 0);
    kdtree_free(&t);
    free(out);
}

/* One cluster of m shading points around a random centre, all facing up. */
static hitpoints_t make_points(size_t n, double spread, uint32_t objects)
{
    hitpoints_t h = {.with_object = 1};
    for (size_t i = 0; i < n; i++) {
        vec3 p = v3(0.5 + spread * (rnd() - 0.5), 0.5 + spread * (rnd() - 0.5), 0.5 + spread * (rnd() - 0.5));
        assert_int_equal(hitpoints_push(&h, p, v3(0, 1, 0), v3(1, 1, 1), (int32_t)i, (uint32_t)(i % objects)), 0);
    }
    return h;
}

/* Every search against brute force on 20 clusters of 1..16 points: the clustered search with
 * each prefilter path this processor runs, the single-pass search, and the oracle. `guess`, when
 * set, is a bound far too small: every member must then fall back. Returns the clustered search's
 * counters (the widest path's). */
static knn_cluster_stats_t check_knn_guess(const photon_map_t *m, size_t k, double r0, double guess)
{
    photon_tree_t t;
    assert_int_equal(photon_tree_build(&t, m), 0);
    knn_naive_t *nv = knn_naive_new(m);
    assert_non_null(nv);
    knn_cluster_stats_t st = {0};
    knn_cand_t *out = malloc(KNN_LANES * k * sizeof *out), *want = malloc(k * sizeof *want), *nav = malloc(k * sizeof *nav);
    for (int path = KNN_KERNEL_SCALAR; path <= KNN_KERNEL_AVX512; path++) {
        knn_kernel_id_t taken;
        knn_kernel_fn kernel = knn_kernel_get((knn_kernel_id_t)path, &taken);
        assert_int_equal(taken, path);
        if (!kernel) continue;   /* not on this processor */
        knn_scratch_t s = {0};
        st = (knn_cluster_stats_t){0};
        for (int rep = 0; rep < 20; rep++) {
            hitpoints_t h = make_points(KNN_LANES, 0.2, 1);
            uint32_t members[KNN_LANES];
            for (int j = 0; j < KNN_LANES; j++) members[j] = (uint32_t)j;
            const int mcount = 1 + rep % KNN_LANES;
            if (guess > 0) s.guess = guess;
            size_t counts[KNN_LANES];
            assert_int_equal(knn_cluster(&t, kernel, &h, members, mcount, r0, k, UPDATE_NORMAL_COS, &s, out, counts, &st), 0);
            for (int j = 0; j < mcount; j++) {
                const double q[3] = {h.hot[j].px, h.hot[j].py, h.hot[j].pz}, n[3] = {0, 1, 0};
                knn_work_t w = {0, 0, 0};
                knn_buckets_t bk = {0};
                size_t wn = brute_knn(m, q, n, k, r0 * r0, want);
                size_t v = knn_naive_query(nv, q, n, UPDATE_NORMAL_COS, k, r0 * r0, nav);
                assert_int_equal(counts[j], wn);
                assert_int_equal(v, wn);
                for (size_t i = 0; i < wn; i++) {
                    const knn_cand_t *c = out + (size_t)j * k;
                    if (c[i].photon != want[i].photon || c[i].d2 != want[i].d2)
                        fail_msg("clustered (%s): member %d neighbour %zu: photon %u d2 %.17g, want %u %.17g",
                                 knn_kernel_name(taken), j, i, c[i].photon, c[i].d2, want[i].photon, want[i].d2);
                    if (nav[i].photon != want[i].photon || nav[i].d2 != want[i].d2)
                        fail_msg("naive: member %d neighbour %zu: photon %u, want %u", j, i, nav[i].photon, want[i].photon);
                }
                assert_int_equal(knn_kdtree_query(&t, q, n, UPDATE_NORMAL_COS, k, r0 * r0, nav, &bk, &w), wn);
                for (size_t i = 0; i < wn; i++)
                    if (nav[i].photon != want[i].photon || nav[i].d2 != want[i].d2)
                        fail_msg("kdtree: member %d neighbour %zu: photon %u, want %u", j, i, nav[i].photon, want[i].photon);
                knn_buckets_free(&bk);
            }
            hitpoints_free(&h);
        }
        knn_scratch_free(&s);
    }
    free(out); free(want); free(nav);
    knn_naive_free(nv);
    photon_tree_free(&t);
    return st;
}

static knn_cluster_stats_t check_knn(const photon_map_t *m, size_t k, double r0)
{
    return check_knn_guess(m, k, r0, 0);
}

static void test_knn_random(void **state)
{
    (void)state;
    rng_state = 12345;
    photon_map_t m = make_map(5000, 0);
    knn_cluster_stats_t a = check_knn(&m, 50, 0.1);
    knn_cluster_stats_t b = check_knn(&m, 8, 0.3);     /* a bound below r0 after the first cluster */
    check_knn(&m, 400, 0.05);                          /* fewer than k within r0: short results */
    assert_true(b.scope_photons > 0 && b.clusters - b.per_point > 0);
    knn_cluster_stats_t g = check_knn_guess(&m, 50, 0.3, 0.1);   /* a bound below most k-th distances */
    assert_true(g.fallback > 0);
    knn_cluster_stats_t p = check_knn_guess(&m, 8, 0.3, 1e-3);   /* clusters far wider than the bound */
    assert_true(p.per_point > 0 && p.fallback > 0);
    assert_true(a.clusters == 20 && b.clusters == 20);
    free(m.p);
}

/* The bucket selections (records and arrays): the same k in the same order as a sort of every
 * candidate. */
static void test_select_fast(void **state)
{
    (void)state;
    rng_state = 31337;
    for (size_t n = 0; n < 600; n += 37)
        for (size_t k = 1; k < 700; k = k * 3 + 1) {
            knn_cand_t *a = malloc((n + 1) * sizeof *a), *b = malloc((n + 1) * sizeof *b), *c = malloc((k + 1) * sizeof *c);
            double *d2 = malloc((n + 1) * sizeof *d2);
            uint32_t *pos = malloc((n + 1) * sizeof *pos), *photon = malloc((n + 1) * sizeof *photon);
            knn_buckets_t bk = {0};
            for (size_t i = 0; i < n; i++) {
                a[i] = b[i] = (knn_cand_t){floor(rnd() * 20), (uint32_t)(n - i), (uint32_t)i};
                d2[i] = a[i].d2;
                pos[i] = (uint32_t)i;
                photon[i] = a[i].photon;
            }
            size_t gc = knn_select_arrays(d2, pos, photon, n, k, 20, &bk, c);
            size_t ga = knn_select(a, n, k), gb = knn_select_buckets(b, n, k, 20, &bk, b);
            knn_buckets_free(&bk);
            assert_int_equal(ga, gb);
            assert_int_equal(ga, gc);
            for (size_t i = 0; i < ga; i++) {
                assert_true(a[i].d2 == b[i].d2 && a[i].photon == b[i].photon && a[i].pos == b[i].pos);
                assert_true(a[i].d2 == c[i].d2 && a[i].photon == c[i].photon && a[i].pos == c[i].pos);
            }
            free(a); free(b); free(c); free(d2); free(pos); free(photon);
        }
}

/* The runs cover every point within r, in increasing order, without overlap. */
static void test_kdtree_runs(void **state)
{
    (void)state;
    rng_state = 2024;
    photon_map_t m = make_map(3000, 0.125);
    kdtree_t t;
    assert_int_equal(kdtree_build(&t, m.p[0].x, sizeof *m.p / sizeof(double), m.n), 0);
    kd_range_t *runs = NULL;
    size_t n = 0, cap = 0;
    for (int q = 0; q < 200; q++) {
        const double c[3] = {rnd(), rnd(), rnd()}, r = 0.02 + 0.3 * rnd();
        assert_int_equal(kdtree_runs(&t, c, r, &runs, &n, &cap), 0);
        unsigned char *in = calloc(m.n, 1);
        for (size_t j = 0; j < n; j++) {
            assert_true(runs[j].lo < runs[j].hi && runs[j].hi <= m.n);
            if (j) assert_true(runs[j].lo > runs[j - 1].hi);
            for (size_t i = runs[j].lo; i < runs[j].hi; i++) in[i] = 1;
        }
        for (size_t i = 0; i < m.n; i++) {
            double dx = t.x[i] - c[0], dy = t.y[i] - c[1], dz = t.z[i] - c[2];
            if (dx * dx + dy * dy + dz * dz <= r * r && !in[i]) fail_msg("position %zu within r, in no run", i);
        }
        free(in);
    }
    free(runs);
    kdtree_free(&t);
    free(m.p);
}

static void test_knn_ties(void **state)
{
    (void)state;
    rng_state = 777;
    photon_map_t m = make_map(4000, 0.0625);   /* 16^3 grid positions: duplicates and equal distances */
    check_knn(&m, 30, 0.15);
    check_knn(&m, 3, 0.2);
    free(m.p);
}

static void test_knn_small_and_empty(void **state)
{
    (void)state;
    rng_state = 99;
    photon_map_t m = make_map(20, 0);
    check_knn(&m, 100, 2.0);    /* k larger than the map: every photon that passes */
    free(m.p);
    photon_map_t e = {0};
    check_knn(&e, 10, 1.0);
}

static void test_clusters(void **state)
{
    (void)state;
    rng_state = 4242;
    hitpoints_t h = make_points(7777, 1.0, 5);
    const size_t bundles[] = {16, 100, 2000};
    for (int b = 0; b < 3; b++) {
        clusters_t c;
        cluster_opts_t o = {bundles[b], 1.0, b + 1};
        assert_int_equal(cluster_build(&h, &o, &c), 0);
        unsigned char *seen = calloc(h.n, 1);
        assert_int_equal(c.start[0], 0);
        assert_int_equal(c.start[c.count], h.n);
        for (size_t k = 0; k < c.count; k++) {
            size_t lo = c.start[k], hi = c.start[k + 1];
            assert_true(hi > lo && hi - lo <= CLUSTER_MAX);
            for (size_t i = lo; i < hi; i++) {
                uint32_t p = c.member[i];
                assert_true(p < h.n);
                assert_false(seen[p]);
                seen[p] = 1;
                assert_int_equal(h.object[p], h.object[c.member[lo]]);
            }
        }
        for (size_t i = 0; i < h.n; i++) assert_true(seen[i]);
        /* The thread count changes nothing. */
        clusters_t c1;
        cluster_opts_t o1 = o;
        o1.threads = 1;
        assert_int_equal(cluster_build(&h, &o1, &c1), 0);
        assert_int_equal(c1.count, c.count);
        assert_memory_equal(c1.member, c.member, h.n * sizeof *c.member);
        double f = cluster_coherent_fraction(&h, &c);
        assert_true(f >= 0 && f <= 1);
        clusters_free(&c1);
        clusters_free(&c);
        free(seen);
    }
    hitpoints_free(&h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kdtree_empty),
        cmocka_unit_test(test_knn_random),
        cmocka_unit_test(test_select_fast),
        cmocka_unit_test(test_kdtree_runs),
        cmocka_unit_test(test_knn_ties),
        cmocka_unit_test(test_knn_small_and_empty),
        cmocka_unit_test(test_clusters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
