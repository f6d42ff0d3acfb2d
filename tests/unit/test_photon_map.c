/* test_photon_map.c: the photon-map estimator's pieces against brute force on random point
 * sets: the kd-tree's range query (with duplicated points and points on split planes), the
 * clustered k-NN and nanoflann's naive k-NN against a sort of every photon (ties broken by
 * photon index, k larger than the photon count, an empty map, the normal test), and the
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
            all[c++] = (knn_cand_t){d2, (uint32_t)i};
    }
    size_t got = knn_select(all, c, k);
    memcpy(out, all, got * sizeof *out);
    free(all);
    return got;
}

static void test_kdtree_range(void **state)
{
    (void)state;
    const double steps[] = {0, 0.125};
    for (int s = 0; s < 2; s++) {
        rng_state = 0x9e3779b97f4a7c15ull + (uint64_t)s;
        photon_map_t m = make_map(3000, steps[s]);
        kdtree_t t;
        assert_int_equal(kdtree_build(&t, m.p[0].x, sizeof *m.p / sizeof(double), m.n), 0);
        uint32_t *out = NULL;
        size_t n = 0, cap = 0;
        for (int q = 0; q < 200; q++) {
            const double c[3] = {rnd(), rnd(), rnd()}, r = q % 2 ? 0.125 : 0.05 + 0.3 * rnd();
            n = 0;
            assert_true(kdtree_range(&t, c, r, &out, &n, &cap) != (size_t)-1);
            unsigned char *seen = calloc(m.n, 1);
            for (size_t j = 0; j < n; j++) {
                uint32_t i = t.index[out[j]];
                assert_false(seen[i]);
                seen[i] = 1;
            }
            size_t want = 0;
            for (size_t i = 0; i < m.n; i++) {
                double dx = m.p[i].x[0] - c[0], dy = m.p[i].x[1] - c[1], dz = m.p[i].x[2] - c[2];
                int in = dx * dx + dy * dy + dz * dz <= r * r;
                if (in != seen[i]) fail_msg("point %zu: in range %d, reported %d", i, in, seen[i]);
                want += (size_t)in;
            }
            assert_int_equal(n, want);
            free(seen);
        }
        free(out);
        kdtree_free(&t);
        free(m.p);
    }
}

static void test_kdtree_empty(void **state)
{
    (void)state;
    kdtree_t t;
    double dummy[3] = {0, 0, 0};
    assert_int_equal(kdtree_build(&t, dummy, 3, 0), 0);
    uint32_t *out = NULL;
    size_t n = 0, cap = 0;
    assert_int_equal(kdtree_range(&t, dummy, 1.0, &out, &n, &cap), 0);
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

/* Returns the search's counters: how many clusters took the sparse (hybrid) path. */
static knn_cluster_stats_t check_knn_guess(const photon_map_t *m, size_t k, double r0, double guess)
{
    kdtree_t t;
    assert_int_equal(kdtree_build(&t, m->n ? m->p[0].x : (const double[3]){0, 0, 0}, sizeof *m->p / sizeof(double), m->n), 0);
    knn_naive_t *nv = knn_naive_new(m);
    assert_non_null(nv);
    knn_scratch_t s = {0};
    knn_cluster_stats_t st = {0, 0, 0, 0, 0};
    knn_cand_t *out = malloc(KNN_LANES * k * sizeof *out), *want = malloc(k * sizeof *want), *nav = malloc(k * sizeof *nav);
    for (int rep = 0; rep < 20; rep++) {
        hitpoints_t h = make_points(KNN_LANES, 0.2, 1);
        uint32_t members[KNN_LANES];
        for (int j = 0; j < KNN_LANES; j++) members[j] = (uint32_t)j;
        const int mcount = 1 + rep % KNN_LANES;
        if (guess > 0) s.guess = guess;   /* a scope guess far too small: the full scope must follow */
        size_t counts[KNN_LANES];
        double b2[KNN_LANES];
        assert_int_equal(knn_cluster(&t, m, &h, members, mcount, r0, k, UPDATE_NORMAL_COS, &s, out, counts, b2, &st), 0);
        for (int j = 0; j < mcount; j++) {
            const double q[3] = {h.hot[j].px, h.hot[j].py, h.hot[j].pz}, n[3] = {0, 1, 0};
            size_t w = brute_knn(m, q, n, k, r0 * r0, want);
            size_t v = knn_naive_query(nv, q, n, UPDATE_NORMAL_COS, k, r0 * r0, nav);
            assert_int_equal(counts[j], w);
            assert_int_equal(v, w);
            for (size_t i = 0; i < w; i++) {
                const knn_cand_t *c = out + (size_t)j * k;
                if (c[i].photon != want[i].photon || c[i].d2 != want[i].d2)
                    fail_msg("clustered: member %d neighbour %zu: photon %u d2 %.17g, want %u %.17g", j, i,
                             c[i].photon, c[i].d2, want[i].photon, want[i].d2);
                if (nav[i].photon != want[i].photon || nav[i].d2 != want[i].d2)
                    fail_msg("naive: member %d neighbour %zu: photon %u, want %u", j, i, nav[i].photon, want[i].photon);
            }
        }
        hitpoints_free(&h);
    }
    free(out); free(want); free(nav);
    knn_scratch_free(&s);
    knn_naive_free(nv);
    kdtree_free(&t);
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
    knn_cluster_stats_t b = check_knn(&m, 8, 0.3);     /* dense: the histogram refines */
    knn_cluster_stats_t c = check_knn(&m, 400, 0.05);  /* sparse: the hybrid path */
    assert_true(b.sparse < b.clusters);
    knn_cluster_stats_t g = check_knn_guess(&m, 8, 0.3, 1e-3);
    assert_true(g.widened == g.clusters);
    assert_true(c.sparse > 0);
    assert_true(a.clusters == 20 && b.clusters == 20 && c.clusters == 20);
    (void)a;
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
        cmocka_unit_test(test_kdtree_range),
        cmocka_unit_test(test_kdtree_empty),
        cmocka_unit_test(test_knn_random),
        cmocka_unit_test(test_knn_ties),
        cmocka_unit_test(test_knn_small_and_empty),
        cmocka_unit_test(test_clusters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
