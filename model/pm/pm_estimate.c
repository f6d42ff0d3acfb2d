/* pm_estimate.c: the photon-map radiance estimate at every hit point (see pm_estimate.h). */
#include <omp.h>
#include <time.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cluster.h"
#include "kdtree.h"
#include "knn_clustered.h"
#include "knn_naive.h"
#include "pm_estimate.h"
#include "update.h"

/* Hit point i's radiance from its neighbours c[0..count) (in (d2, photon) order), r2 the
 * squared radius when fewer than k were found. */
static void estimate(const hitpoints_t *h, size_t i, const photon_map_t *map, const knn_cand_t *c, size_t count,
                     size_t k, double r2_short, double *L)
{
    double f[3] = {0, 0, 0};
    for (size_t j = 0; j < count; j++)
        for (int a = 0; a < 3; a++) f[a] += map->p[c[j].photon].flux[a];
    const double r2 = count == k ? c[k - 1].d2 : r2_short;
    const double s = count && r2 > 0 ? 1.0 / ((PREE_PI * r2) * (double)map->emitted) : 0.0;
    const vec3 w = h->weight[i];
    L[3 * i + 0] = w.x * (f[0] * (1. / PREE_PI)) * s;
    L[3 * i + 1] = w.y * (f[1] * (1. / PREE_PI)) * s;
    L[3 * i + 2] = w.z * (f[2] * (1. / PREE_PI)) * s;
}

double pm_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int search_naive(const hitpoints_t *h, const photon_map_t *map, const pm_estimate_opts_t *o, double *L,
                        pm_stats_t *st)
{
    knn_naive_t *nv = knn_naive_new(map);
    if (!nv) return -1;
    int failed = 0;
    unsigned long long found = 0, short_k = 0;
#pragma omp parallel num_threads(o->threads) reduction(| : failed) reduction(+ : found, short_k)
    {
        knn_cand_t *c = malloc(o->k * sizeof *c);
        if (!c) failed = 1;
#pragma omp for schedule(dynamic, 256)
        for (size_t i = 0; i < h->n; i++) {
            if (failed) continue;
            const double q[3] = {h->hot[i].px, h->hot[i].py, h->hot[i].pz};
            const double n[3] = {h->hot[i].nx, h->hot[i].ny, h->hot[i].nz};
            size_t got = knn_naive_query(nv, q, n, UPDATE_NORMAL_COS, o->k, o->r0 * o->r0, c);
            if (got == (size_t)-1) { failed = 1; continue; }
            estimate(h, i, map, c, got, o->k, o->r0 * o->r0, L);
            found += got;
            short_k += got < o->k;
        }
        free(c);
    }
    knn_naive_free(nv);
    st->neighbours = found;
    st->short_of_k = short_k;
    return failed ? -1 : 0;
}

static int search_clustered(const hitpoints_t *h, const photon_map_t *map, const pm_estimate_opts_t *o, double *L,
                            pm_stats_t *st)
{
    double t = omp_get_wtime(), c0 = pm_cpu_now();
    clusters_t cl;
    cluster_opts_t co = {o->bundle, 1.0, o->threads};
    if (cluster_build(h, &co, &cl)) return -1;
    st->coherent_fraction = cluster_coherent_fraction(h, &cl);
    st->sec_cluster = omp_get_wtime() - t;
    st->cpu_cluster = pm_cpu_now() - c0;
    kdtree_t tree;
    if (kdtree_build(&tree, map->p[0].x, sizeof *map->p / sizeof(double), map->n)) { clusters_free(&cl); return -1; }
    int failed = 0;
    unsigned long long found = 0, short_k = 0;
    knn_cluster_stats_t total = {0, 0, 0, 0, 0};
#pragma omp parallel num_threads(o->threads) reduction(| : failed) reduction(+ : found, short_k)
    {
        knn_scratch_t s = {0};
        knn_cluster_stats_t cs = {0, 0, 0, 0, 0};
        knn_cand_t *out = malloc(KNN_LANES * o->k * sizeof *out);
        size_t counts[KNN_LANES];
        double b2[KNN_LANES];
        if (!out) failed = 1;
#pragma omp for schedule(dynamic, 16)
        for (size_t c = 0; c < cl.count; c++) {
            if (failed) continue;
            const uint32_t *mem = cl.member + cl.start[c];
            const int m = (int)(cl.start[c + 1] - cl.start[c]);
            if (knn_cluster(&tree, map, h, mem, m, o->r0, o->k, UPDATE_NORMAL_COS, &s, out, counts, b2, &cs)) {
                failed = 1;
                continue;
            }
            for (int j = 0; j < m; j++) {
                estimate(h, mem[j], map, out + (size_t)j * o->k, counts[j], o->k, b2[j], L);
                found += counts[j];
                short_k += counts[j] < o->k;
            }
        }
#pragma omp critical
        {
            total.clusters += cs.clusters;
            total.sparse += cs.sparse;
            total.scope_photons += cs.scope_photons;
            total.distance_tests += cs.distance_tests;
            total.widened += cs.widened;
        }
        knn_scratch_free(&s);
        free(out);
    }
    kdtree_free(&tree);
    clusters_free(&cl);
    st->clusters = total.clusters;
    st->clusters_sparse = total.sparse;
    st->scope_photons = total.scope_photons;
    st->distance_tests = total.distance_tests;
    st->clusters_widened = total.widened;
    st->neighbours = found;
    st->short_of_k = short_k;
    return failed ? -1 : 0;
}

int pm_estimate(const hitpoints_t *h, const photon_map_t *map, const pm_estimate_opts_t *o, double *L,
                pm_stats_t *st, char *err, size_t errlen)
{
    memset(L, 0, 3 * h->n * sizeof *L);
    st->k = o->k;
    st->max_radius = o->r0;
    st->photons_stored = map->n;
    if (h->n == 0 || map->n == 0) return 0;
    double t = omp_get_wtime(), c0 = pm_cpu_now();
    int rc = o->search == KNN_NAIVE ? search_naive(h, map, o, L, st) : search_clustered(h, map, o, L, st);
    st->sec_search = omp_get_wtime() - t - st->sec_cluster;
    st->cpu_search = pm_cpu_now() - c0 - st->cpu_cluster;
    if (rc) snprintf(err, errlen, "out of memory in the photon-map search");
    return rc;
}
