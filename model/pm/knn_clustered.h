// SPDX-License-Identifier: Apache-2.0
/* knn_clustered.h: paper 002's clustered k-NN search for one cluster of up to 16 shading points
 * (--knn-search clustered, the default of --estimator pm), on the photon tree (photon_tree.h).
 *
 * 1. A bound b for the cluster: the thread's guess of the k-th distance (the last cluster's
 *    largest, with a margin), at most r0.
 * 2. One walk of the tree for the whole cluster: the runs of tree positions within b + far of
 *    the centre (far: the farthest member's distance), which hold every photon within b of
 *    every member. Adaptive: a cluster whose members lie farther than KNN_SPREAD_MAX b from its
 *    centre (sparse shading points, where one shared scope would hold many photons no member
 *    needs) gives each member a scope of its own, the runs within b of it.
 * 3. Per member, the vector kernel (knn_kernel.h) streams through the runs: the float prefilter
 *    within the member's own bound (the last member's k-th distance with a margin, at most b; b
 *    again when that holds fewer than k), then the exact double test (the oracle's expression
 *    order) on what passes; a linear-time selection (knn_select_arrays) of its output keeps the
 *    k nearest, sorted.
 * 4. A member with fewer than k within b < r0 is not certain: it alone is searched again with the
 *    single-pass search within r0.
 * Either way member j's result is the k nearest within r0 in (d2, photon) order: the oracle's. */
#ifndef PREE_KNN_CLUSTERED_H
#define PREE_KNN_CLUSTERED_H

#include <stddef.h>
#include <stdint.h>
#include "hitpoints.h"
#include "knn_kdtree.h"
#include "knn_kernel.h"
#include "knn_select.h"
#include "photon_tree.h"

#define KNN_LANES 16          /* shading points a cluster at most (cluster.h's CLUSTER_MAX) */
#define KNN_MARGIN 1.25       /* the bound: this times the last cluster's largest k-th distance */
#define KNN_LANE_MARGIN 1.05  /* a member's own bound: this times the last member's k-th distance */
#define KNN_SPREAD_MAX 2.0    /* clusters spread wider than this times the bound: point by point */

typedef struct {
    kd_range_t *runs;    /* the cluster's scope as runs of tree positions */
    size_t runs_n, runs_cap;
    knn_hits_t hits;     /* the kernel's output for one member */
    size_t pos_cap, d2_cap;
    double guess;        /* the bound to try: the last cluster's k-th distance with a margin (0: r0) */
    double lane_guess;   /* a member's own bound to try: the last member's k-th distance with a
                          * margin (0: the cluster's) */
    knn_buckets_t buckets;
} knn_scratch_t;

typedef struct {
    unsigned long long clusters, per_point, widened, fallback, scope_photons;
    knn_work_t work;
} knn_cluster_stats_t;

/* The members' neighbours: for member j (0..m), out + j * k holds counts[j] of them, in
 * (d2, photon) order. 0, or -1 when out of memory. */
int knn_cluster(const photon_tree_t *t, knn_kernel_fn kernel, const hitpoints_t *h, const uint32_t *members, int m,
                double r0, size_t k, double cos_min, knn_scratch_t *s, knn_cand_t *out, size_t *counts,
                knn_cluster_stats_t *st);
void knn_scratch_free(knn_scratch_t *s);

#endif
