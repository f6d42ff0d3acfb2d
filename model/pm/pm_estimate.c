// SPDX-License-Identifier: Apache-2.0
/* pm_estimate.c: the photon-map radiance estimate at every hit point, and --knn-bench (see
 * pm_estimate.h). */
#include <omp.h>
#include <time.h>
#include <stdio.h>
#include <string.h>
#include "fnv1a.h"
#include "pm_search.h"

static double cpu_clock(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double pm_cpu_now(void) { return cpu_clock(CLOCK_PROCESS_CPUTIME_ID); }
double pm_thread_cpu_now(void) { return cpu_clock(CLOCK_THREAD_CPUTIME_ID); }

/* The queries' share of the search seconds: the estimates' CPU time left out. */
static void query_share(pm_stats_t *st)
{
    st->cpu_query = st->cpu_search - st->cpu_estimate;
    st->sec_query = st->cpu_search > 0 ? st->sec_search * st->cpu_query / st->cpu_search : st->sec_search;
}

/* Every method on the same trees, repetitions interleaved (each round runs the three, starting
 * one further each round, so a shared machine's changing load falls on all alike); the oracle
 * only in the first o->bench_oracle_reps rounds when that is set (it is slow at large k). st's
 * counters are o->search's last run's, L the last run's. 0; -3 when the radiance of the methods
 * run differs in any bit. */
static int bench(pm_searches_t *s, const hitpoints_t *h, const photon_map_t *map, const pm_estimate_opts_t *o,
                 double *L, pm_stats_t *st)
{
    int reps[3] = {o->bench_reps, o->bench_reps, o->bench_reps};
    if (o->bench_oracle_reps >= 0 && o->bench_oracle_reps < o->bench_reps)
        reps[KNN_NAIVE] = o->search == KNN_NAIVE && o->bench_oracle_reps == 0 ? 1 : o->bench_oracle_reps;
    for (int m = 0; m < 3; m++) {
        if (!reps[m]) continue;
        int rc = pm_search_prepare(s, (knn_search_t)m, h, map, o, st, &st->bench[m].sec_tree, &st->bench[m].cpu_tree);
        if (rc) return rc;
    }
    st->bench[KNN_KDTREE].sec_tree = st->bench[KNN_CLUSTERED].sec_tree;   /* one photon tree, built once */
    st->bench[KNN_KDTREE].cpu_tree = st->bench[KNN_CLUSTERED].cpu_tree;
    st->sec_tree = st->bench[o->search].sec_tree;
    st->cpu_tree = st->bench[o->search].cpu_tree;
    st->bench_reps = o->bench_reps;
    pm_stats_t keep = *st;
    for (int rep = 0; rep < o->bench_reps; rep++)
        for (int j = 0; j < 3; j++) {
            const int m = (rep + j) % 3;
            if (rep >= reps[m]) continue;
            pm_stats_t run = *st;
            pm_method_stats_t *b = &st->bench[m];
            double t = omp_get_wtime(), c = pm_cpu_now();
            memset(L, 0, 3 * h->n * sizeof *L);
            if (pm_search_run(s, (knn_search_t)m, h, map, o, L, &run)) return -1;
            pm_lap(&t, &c, &run.sec_search, &run.cpu_search);
            query_share(&run);
            b->sec[rep] = run.sec_query;
            b->cpu[rep] = run.cpu_query;
            b->distance_tests = run.distance_tests;
            b->kernel_tests = run.kernel_tests;
            b->selection = run.selection;
            b->clusters_sparse = run.clusters_sparse;
            b->widened = run.widened;
            b->fallback = run.fallback;
            b->state_hash = fnv1a(FNV1A_BASIS, L, 3 * h->n * sizeof *L);
            b->runs = rep + 1;
            if (m == (int)o->search) keep = run;
        }
    for (int m = 0; m < 3; m++) keep.bench[m] = st->bench[m];
    keep.bench_reps = st->bench_reps;
    *st = keep;
    for (int m = 0; m < 3; m++)
        if (st->bench[m].runs && st->bench[m].state_hash != st->bench[o->search].state_hash) return -3;
    return 0;
}

/* The search: its tree (and clusters) built and timed apart from the queries. */
static int search(pm_searches_t *s, const hitpoints_t *h, const photon_map_t *map, const pm_estimate_opts_t *o,
                  double *L, pm_stats_t *st)
{
    if (o->bench_reps > 0) return bench(s, h, map, o, L, st);
    int rc = pm_search_prepare(s, o->search, h, map, o, st, &st->sec_tree, &st->cpu_tree);
    if (rc) return rc;
    double t = omp_get_wtime(), c = pm_cpu_now();
    rc = pm_search_run(s, o->search, h, map, o, L, st);
    pm_lap(&t, &c, &st->sec_search, &st->cpu_search);
    query_share(st);
    return rc;
}

int pm_estimate(const hitpoints_t *h, const photon_map_t *map, const pm_estimate_opts_t *o, double *L,
                pm_stats_t *st, char *err, size_t errlen)
{
    memset(L, 0, 3 * h->n * sizeof *L);
    st->k = o->k;
    st->max_radius = o->r0;
    st->photons_stored = map->n;
    if (h->n == 0 || map->n == 0) return 0;
    pm_searches_t s = {0};
    const int rc = search(&s, h, map, o, L, st);
    pm_search_release(&s);
    if (rc == -3)
        snprintf(err, errlen, "--knn-bench: the searches' radiance differs (clustered %016llx, naive %016llx, kdtree %016llx)",
                 (unsigned long long)st->bench[0].state_hash, (unsigned long long)st->bench[1].state_hash,
                 (unsigned long long)st->bench[2].state_hash);
    else if (rc == -2)
        snprintf(err, errlen, "--knn-kernel %s: this processor does not have it", knn_kernel_name((knn_kernel_id_t)st->kernel));
    else if (rc)
        snprintf(err, errlen, "out of memory in the photon-map search");
    return rc ? -1 : 0;
}
