// SPDX-License-Identifier: Apache-2.0
/* cluster.h: shading points (hit points) in clusters of at most 16, after paper 002, Sec. 4.1.
 *
 * Points are grouped by the object they lie on and ordered along a Morton curve within the
 * group; each group is cut into bundles of at most `bundle` consecutive points (the paper's
 * "set of shading points", at most 2000). Within a bundle, hierarchical aggregation merges
 * clusters level by level: the first unmerged cluster of the level merges with its most
 * similar unmerged cluster, D(c1, c2) = |p1 - p2|^2 + lambda |n1 - n2|^2 on the clusters'
 * centres (mean position, normalised sum of normals), while the two hold 16 points or fewer
 * together; levels repeat until no merge is possible. Deterministic: no thread or random
 * order enters. */
#ifndef PREE_CLUSTER_H
#define PREE_CLUSTER_H

#include <stddef.h>
#include <stdint.h>
#include "hitpoints.h"

#define CLUSTER_MAX 16

typedef struct {
    uint32_t *member;     /* hit point indices, cluster by cluster */
    size_t *start;        /* cluster c holds member[start[c] .. start[c + 1]) */
    size_t count;         /* clusters */
    size_t n;             /* hit points */
} clusters_t;

typedef struct {
    size_t bundle;        /* points per bundle (>= 16) */
    double lambda;        /* normal weight of D */
    int threads;          /* 0: OpenMP's default */
} cluster_opts_t;

/* Cluster hit points [0, h->n). 0, or -1 when out of memory. */
int cluster_build(const hitpoints_t *h, const cluster_opts_t *o, clusters_t *out);
void clusters_free(clusters_t *c);

/* The centre of cluster c (mean position) and the distance from it to its farthest member. */
void cluster_centre(const hitpoints_t *h, const clusters_t *c, size_t k, double centre[3], double *farthest);

/* Paper 002's coherence test: d_i is the distance from member i to the nearest other member
 * of its cluster; eps is the mean over clusters of their farthest-member distance; a cluster
 * is coherent when every member has d_i < eps. Returns the coherent fraction of the clusters
 * of two or more points (1 when there are none). */
double cluster_coherent_fraction(const hitpoints_t *h, const clusters_t *c);

#endif
