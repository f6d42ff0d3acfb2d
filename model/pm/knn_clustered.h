/* knn_clustered.h: paper 002's factorized k-NN search for one cluster of up to 16 shading
 * points (--knn-search clustered, the default of --estimator pm).
 *
 * 1. One range query in the photon kd-tree per cluster: all photons within R0 = r0 + the
 *    farthest member's distance from the centre. That scope holds every photon within
 *    b_i = R0 - d_i of member i (d_i: its distance from the centre), and b_i >= r0.
 * 2. A distance matrix, one photon against the 16 members at a time (16 lanes; AVX2 where the
 *    processor has it, the same bits from the portable path): d2, or +inf where the photon fails
 *    member i's normal test or lies beyond b_i.
 * 3. Dense scope (at least K_c = (R0 / r0)^2 k photons): per member, a histogram of d2 over
 *    [0, b_i^2] in KNN_BINS ranges; the range holding the k-th photon is split again, at most
 *    KNN_ITERS times; then an exact selection inside it. Sparse scope (the paper's hybrid): the
 *    exact selection directly, within r_i = b_i = r0 + distance - d_i.
 * The scope's r0 above starts as a guess of the k-th distance (the thread's last cluster's, with a
 * margin); when a member's k-th neighbour is not certain inside the guessed scope, the cluster
 * is searched again with the full r0 + distance. The guess changes the work, never the result.
 * Either way the result is the k nearest within b_i in (d2, photon) order: the same set as the
 * naive search's within r0 wherever member i has k photons within r0. */
#ifndef PREE_KNN_CLUSTERED_H
#define PREE_KNN_CLUSTERED_H

#include <stddef.h>
#include <stdint.h>
#include "hitpoints.h"
#include "kdtree.h"
#include "knn_select.h"
#include "photon_map.h"

#define KNN_BINS 16
#define KNN_ITERS 3
#define KNN_LANES 16

typedef struct {
    uint32_t *scope;     /* tree positions in the cluster's scope */
    size_t scope_n, scope_cap;
    double *d2;          /* scope_n x KNN_LANES */
    size_t d2_cap;
    knn_cand_t *cand;    /* one member's candidates */
    size_t cand_cap;
    double guess;        /* the scope radius to try first: the last cluster's k-th distance, with a
                          * margin (0: r0) */
} knn_scratch_t;

typedef struct {
    unsigned long long clusters, sparse, scope_photons, distance_tests;
    unsigned long long widened;   /* clusters whose guessed scope left a result uncertain */
} knn_cluster_stats_t;

/* The members' neighbours: for member j (0..m), out + j * k holds counts[j] of them, in
 * (d2, photon) order, and bound2[j] = b_j^2. 0, or -1 when out of memory. */
int knn_cluster(const kdtree_t *t, const photon_map_t *map, const hitpoints_t *h, const uint32_t *members,
                int m, double r0, size_t k, double cos_min, knn_scratch_t *s, knn_cand_t *out, size_t *counts,
                double *bound2, knn_cluster_stats_t *st);
void knn_scratch_free(knn_scratch_t *s);

#endif
