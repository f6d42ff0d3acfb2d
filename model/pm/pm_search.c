// SPDX-License-Identifier: Apache-2.0
/* pm_search.c: the searches' set-up and query loops (see pm_search.h). */
#include <omp.h>
#include <stdlib.h>
#include <string.h>
#include "knn_clustered.h"
#include "knn_kdtree.h"
#include "pm_search.h"
#include "update.h"

/* Hit point i's radiance from its neighbours c[0..count) (in (d2, photon) order), r2 the
 * squared radius when fewer than k were found; tree: the neighbours' pos are its positions. */
static void estimate(const hitpoints_t *h, size_t i, const photon_map_t *map, const photon_tree_t *tree,
                     const knn_cand_t *c, size_t count, size_t k, double r2_short, double *L)
{
    double f[3] = {0, 0, 0};
    for (size_t j = 0; j < count; j++)   /* the same flux, read in tree order when the search gave it */
        for (int a = 0; a < 3; a++) f[a] += tree ? tree->flux[3 * (size_t)c[j].pos + a] : map->p[c[j].photon].flux[a];
    const double r2 = count == k ? c[k - 1].d2 : r2_short;
    const double s = count && r2 > 0 ? 1.0 / ((PREE_PI * r2) * (double)map->emitted) : 0.0;
    const vec3 w = h->weight[i];
    L[3 * i + 0] = w.x * (f[0] * (1. / PREE_PI)) * s;
    L[3 * i + 1] = w.y * (f[1] * (1. / PREE_PI)) * s;
    L[3 * i + 2] = w.z * (f[2] * (1. / PREE_PI)) * s;
}

/* The estimates of hit points idx[0..m) from their neighbours (point j's: c + j k, counts[j]);
 * returns the thread's CPU seconds they took, so that the searches' query time leaves them out. */
static double estimate_block(const hitpoints_t *h, const uint32_t *idx, int m, const photon_map_t *map,
                             const photon_tree_t *tree, const knn_cand_t *c, const size_t *counts, size_t k,
                             double r2_short, double *L)
{
    const double t = pm_thread_cpu_now();
    for (int j = 0; j < m; j++) estimate(h, idx[j], map, tree, c + (size_t)j * k, counts[j], k, r2_short, L);
    return pm_thread_cpu_now() - t;
}

/* The hit points one by one (the oracle, or the single-pass search on the photon tree), in
 * blocks of PM_BLOCK: the block's queries, then its estimates. */
#define PM_BLOCK 16
static int search_per_point(const hitpoints_t *h, const photon_map_t *map, const knn_naive_t *nv,
                            const photon_tree_t *tree, const pm_estimate_opts_t *o, double *L, pm_stats_t *st)
{
    int failed = 0;
    unsigned long long found = 0, short_k = 0, tests = 0, selection = 0;
    double cpu_est = 0;
    const size_t blocks = (h->n + PM_BLOCK - 1) / PM_BLOCK;
#pragma omp parallel num_threads(o->threads) reduction(| : failed) reduction(+ : found, short_k, tests, selection, cpu_est)
    {
        knn_cand_t *c = malloc(PM_BLOCK * o->k * sizeof *c);
        knn_work_t w = {0, 0, 0};
        knn_buckets_t b = {0};
        if (!c) failed = 1;
#pragma omp for schedule(dynamic, 16)
        for (size_t blk = 0; blk < blocks; blk++) {
            if (failed) continue;
            uint32_t idx[PM_BLOCK];
            size_t counts[PM_BLOCK];
            int m = 0;
            for (size_t i = blk * PM_BLOCK; i < h->n && m < PM_BLOCK; i++, m++) {
                const double q[3] = {h->hot[i].px, h->hot[i].py, h->hot[i].pz};
                const double n[3] = {h->hot[i].nx, h->hot[i].ny, h->hot[i].nz};
                knn_cand_t *cj = c + (size_t)m * o->k;
                idx[m] = (uint32_t)i;
                counts[m] = nv ? knn_naive_query(nv, q, n, UPDATE_NORMAL_COS, o->k, o->r0 * o->r0, cj)
                               : knn_kdtree_query(tree, q, n, UPDATE_NORMAL_COS, o->k, o->r0 * o->r0, cj, &b, &w);
                if (counts[m] == (size_t)-1) { failed = 1; break; }
                found += counts[m];
                short_k += counts[m] < o->k;
            }
            if (!failed) cpu_est += estimate_block(h, idx, m, map, nv ? NULL : tree, c, counts, o->k, o->r0 * o->r0, L);
        }
        if (nv) knn_naive_work(&w.distance_tests, &w.selection);
        tests += w.distance_tests;
        selection += w.selection;
        knn_buckets_free(&b);
        free(c);
    }
    st->distance_tests = tests;
    st->selection = selection;
    st->neighbours = found;
    st->short_of_k = short_k;
    st->cpu_estimate = cpu_est;
    return failed ? -1 : 0;
}

static int search_clustered(const hitpoints_t *h, const photon_map_t *map, const photon_tree_t *tree,
                            const clusters_t *cl, knn_kernel_fn kernel, const pm_estimate_opts_t *o, double *L,
                            pm_stats_t *st)
{
    int failed = 0;
    unsigned long long found = 0, short_k = 0;
    knn_cluster_stats_t total = {0};
    double cpu_est = 0;
#pragma omp parallel num_threads(o->threads) reduction(| : failed) reduction(+ : found, short_k, cpu_est)
    {
        knn_scratch_t s = {0};
        knn_cluster_stats_t cs = {0};
        knn_cand_t *out = malloc(KNN_LANES * o->k * sizeof *out);
        size_t counts[KNN_LANES];
        if (!out) failed = 1;
#pragma omp for schedule(dynamic, 16)
        for (size_t c = 0; c < cl->count; c++) {
            if (failed) continue;
            const uint32_t *mem = cl->member + cl->start[c];
            const int m = (int)(cl->start[c + 1] - cl->start[c]);
            if (knn_cluster(tree, kernel, h, mem, m, o->r0, o->k, UPDATE_NORMAL_COS, &s, out, counts, &cs)) {
                failed = 1;
                continue;
            }
            for (int j = 0; j < m; j++) {
                found += counts[j];
                short_k += counts[j] < o->k;
            }
            cpu_est += estimate_block(h, mem, m, map, tree, out, counts, o->k, o->r0 * o->r0, L);
        }
#pragma omp critical
        {
            total.clusters += cs.clusters;
            total.per_point += cs.per_point;
            total.fallback += cs.fallback;
            total.widened += cs.widened;
            total.scope_photons += cs.scope_photons;
            total.work.kernel_tests += cs.work.kernel_tests;
            total.work.distance_tests += cs.work.distance_tests;
            total.work.selection += cs.work.selection;
        }
        knn_scratch_free(&s);
        free(out);
    }
    st->clusters = total.clusters;
    st->clusters_sparse = total.per_point;
    st->fallback = total.fallback;
    st->widened = total.widened;
    st->scope_photons = total.scope_photons;
    st->kernel_tests = total.work.kernel_tests;
    st->distance_tests = total.work.distance_tests;
    st->selection = total.work.selection;
    st->neighbours = found;
    st->short_of_k = short_k;
    st->cpu_estimate = cpu_est;
    return failed ? -1 : 0;
}

int pm_search_prepare(pm_searches_t *s, knn_search_t m, const hitpoints_t *h, const photon_map_t *map,
                      const pm_estimate_opts_t *o, pm_stats_t *st, double *sec_tree, double *cpu_tree)
{
    double t = omp_get_wtime(), c = pm_cpu_now();
    if (m == KNN_NAIVE) {
        if (!s->nv && !(s->nv = knn_naive_new(map))) return -1;
        pm_lap(&t, &c, sec_tree, cpu_tree);
        return 0;
    }
    knn_kernel_id_t taken;
    s->kernel = knn_kernel_get((knn_kernel_id_t)o->kernel, &taken);
    st->kernel = (int)taken;
    if (!s->kernel) return -2;
    if (!s->has_tree) {
        if (photon_tree_build(&s->tree, map)) return -1;
        s->has_tree = 1;
    }
    pm_lap(&t, &c, sec_tree, cpu_tree);
    if (m == KNN_CLUSTERED && !s->has_clusters) {
        cluster_opts_t co = {o->bundle, 1.0, o->threads};
        if (cluster_build(h, &co, &s->cl)) return -1;
        s->has_clusters = 1;
        st->coherent_fraction = cluster_coherent_fraction(h, &s->cl);
        pm_lap(&t, &c, &st->sec_cluster, &st->cpu_cluster);
    }
    return 0;
}

int pm_search_run(const pm_searches_t *s, knn_search_t m, const hitpoints_t *h, const photon_map_t *map,
                  const pm_estimate_opts_t *o, double *L, pm_stats_t *st)
{
    if (m == KNN_CLUSTERED) {
        unsigned long long before[4], after[4];
        knn_kernel_calls(before);
        const int rc = search_clustered(h, map, &s->tree, &s->cl, s->kernel, o, L, st);
        knn_kernel_calls(after);
        for (int i = 0; i < 4; i++) st->kernel_calls[i] = after[i] - before[i];
        return rc;
    }
    return search_per_point(h, map, m == KNN_NAIVE ? s->nv : NULL, &s->tree, o, L, st);
}

void pm_search_release(pm_searches_t *s)
{
    if (s->nv) knn_naive_free(s->nv);
    if (s->has_tree) photon_tree_free(&s->tree);
    if (s->has_clusters) clusters_free(&s->cl);
    memset(s, 0, sizeof *s);
}

void pm_lap(double *t, double *c, double *sec, double *cpu)
{
    const double t1 = omp_get_wtime(), c1 = pm_cpu_now();
    *sec = t1 - *t;
    *cpu = c1 - *c;
    *t = t1;
    *c = c1;
}

