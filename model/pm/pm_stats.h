// SPDX-License-Identifier: Apache-2.0
/* pm_stats.h: the photon-map estimator's figures in the render statistics ("pm" in the JSON).
 * The tree each search method reads is built once per render and timed on its own (sec_tree);
 * sec_search is the queries alone, so that methods compare query against query. */
#ifndef PREE_PM_STATS_H
#define PREE_PM_STATS_H

#include <stdint.h>

#define PM_BENCH_MAX 15   /* repetitions of --knn-bench at most */

/* One search method under --knn-bench: its tree's build, each repetition's query time, the
 * last repetition's work and the hash of the radiance it gave (every method's must agree). */
typedef struct {
    double sec_tree, cpu_tree;
    double sec[PM_BENCH_MAX], cpu[PM_BENCH_MAX];   /* the queries alone (as cpu_query, sec_query) */
    unsigned long long distance_tests, kernel_tests, selection, clusters_sparse, widened, fallback;
    uint64_t state_hash;
    int runs;                            /* repetitions it ran (0: not run) */
} pm_method_stats_t;

typedef struct {
    unsigned long long photons_stored;   /* diffuse photon hits in the map */
    /* The tracing's load balance (paper 001; photon_map.h): the longest task unit's and photon
     * path's segments, the busiest and the least busy thread's CPU seconds of tracing. */
    unsigned long long unit_segments_max, path_segments_max;
    double thread_busy_max, thread_busy_min;
    unsigned long long k;                /* neighbours asked for */
    double max_radius;                   /* r0 */
    /* The clustered search's work counters below depend on the threads' schedule (each thread's
     * bound guess carries from the cluster it searched last); with one thread they repeat. */
    unsigned long long clusters;         /* clustered search: clusters of <= 16 shading points */
    unsigned long long clusters_sparse;  /* ... spread too wide for a shared scope: a scope a member */
    unsigned long long widened;          /* ... members not certain within their own bound, searched
                                          * again within the cluster's */
    unsigned long long fallback;         /* ... members not certain within the cluster's bound,
                                          * searched again alone within r0 */
    unsigned long long scope_photons;    /* photons in the shared scopes, summed over clusters */
    unsigned long long kernel_tests;     /* photon-to-point tests of the float vector prefilter */
    unsigned long long distance_tests;   /* exact (double) photon-to-point distances computed
                                          * (the oracle's: nanoflann's, counted as it reads points) */
    unsigned long long selection;        /* candidates the selection handled: heap entries (kdtree),
                                          * candidates into the linear selection (clustered), into
                                          * the sort (naive, every round) */
    unsigned long long neighbours;       /* neighbours found, summed over hit points */
    unsigned long long short_of_k;       /* hit points with fewer than k neighbours */
    double coherent_fraction;            /* paper 002's coherence test */
    int kernel;                          /* the prefilter path taken (knn_kernel_id_t) */
    unsigned long long kernel_calls[4];  /* the clustered search's kernel calls by path, as the
                                          * kernels counted them (index knn_kernel_id_t) */
    double sec_map, sec_tree, sec_cluster, sec_search;   /* wall seconds */
    double cpu_map, cpu_tree, cpu_cluster, cpu_search;   /* CPU seconds of the process (all threads):
                                                          * the figures to compare on a shared machine */
    double cpu_estimate;                 /* the radiance estimates' share of cpu_search (every thread) */
    double cpu_query, sec_query;         /* the queries alone: cpu_search less cpu_estimate, and
                                          * sec_search in the same proportion */
    int bench_reps;                      /* --knn-bench: repetitions of every method (0: none) */
    pm_method_stats_t bench[3];          /* ... indexed by knn_search_t */
} pm_stats_t;

#endif
