// SPDX-License-Identifier: Apache-2.0
/* kdtree.h: a balanced kd-tree over 3-D points (the photon map's positions), with range queries
 * that give runs of tree positions.
 *
 * The tree is implicit: build permutes the points so that each node of [lo, hi) splits at
 * mid = (lo + hi) / 2 on the axis of the widest extent of its points, with points ordered by
 * (coordinate, original index) so the tree and every query's order are the same on any
 * machine and thread count. Ranges of KD_LEAF points or fewer are leaves. Queries walk nodes in
 * a fixed order and report tree positions (index[] maps them to original indices). */
#ifndef PREE_KDTREE_H
#define PREE_KDTREE_H

#include <stddef.h>
#include <stdint.h>

#define KD_LEAF 8
#define KD_RUN_LEAF 32   /* kdtree_runs takes subtrees of this many positions or fewer whole */

typedef struct {
    size_t n;
    double *x, *y, *z;     /* positions in tree order */
    uint32_t *index;       /* tree order -> original index */
    uint8_t *axis;         /* split axis of the node whose median is at this position */
} kdtree_t;

/* Build over n points (x, y, z of point i at pts[i * stride + 0..2]). 0, or -1 out of memory. */
int kdtree_build(kdtree_t *t, const double *pts, size_t stride, size_t n);
void kdtree_free(kdtree_t *t);

/* A run of tree positions [lo, hi). */
typedef struct { uint32_t lo, hi; } kd_range_t;

/* The tree positions around q with radius r, as runs in increasing order, adjacent runs merged
 * (*n of them in *out, *cap its capacity): the subtrees of up to KD_RUN_LEAF positions whose
 * cells (the boxes the splits bound) reach within r of q, and the split points between two such
 * cells; a superset of the points within r (d^2 <= r^2, in floating point too) that a vector
 * kernel streams through without a gather (the larger subtrees cost a few more positions
 * streamed and save the walk most of its nodes). 0, or -1 when out of memory. */
int kdtree_runs(const kdtree_t *t, const double q[3], double r, kd_range_t **out, size_t *n, size_t *cap);

#endif
