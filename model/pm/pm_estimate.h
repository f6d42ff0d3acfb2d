// SPDX-License-Identifier: Apache-2.0
/* pm_estimate.h: each hit point's radiance from its k nearest photons (see pm_render.h),
 * through the clustered search (knn_clustered.h), the single-pass search (knn_kdtree.h) or the
 * oracle (knn_naive.h). */
#ifndef PREE_PM_ESTIMATE_H
#define PREE_PM_ESTIMATE_H

#include "hitpoints.h"
#include "photon_map.h"
#include "pm_stats.h"
#include "render.h"

typedef struct {
    size_t k;
    double r0;              /* maximum radius */
    knn_search_t search;
    size_t bundle;          /* clustered: shading points a bundle */
    int threads;
    int kernel;             /* clustered: the prefilter path (knn_kernel_id_t; 0: the widest) */
    int bench_reps;         /* > 0: every method this many times on the same trees (--knn-bench) */
    int bench_oracle_reps;  /* the oracle's repetitions in it (-1: bench_reps) */
} pm_estimate_opts_t;

/* CPU seconds of the whole process so far (every thread), and of the calling thread. */
double pm_cpu_now(void);
double pm_thread_cpu_now(void);

/* L[3 i .. 3 i + 2]: hit point i's radiance. 0, or -1 with err (out of memory, or a prefilter
 * path the processor lacks). */
int pm_estimate(const hitpoints_t *h, const photon_map_t *map, const pm_estimate_opts_t *o, double *L,
                pm_stats_t *st, char *err, size_t errlen);

#endif
