// SPDX-License-Identifier: Apache-2.0
/* knn_kdtree.h: the classic single-pass k-NN search (--knn-search kdtree), the fair baseline
 * of the clustered search: Jensen's photon-map lookup (pbrt-v2's KdTree::Lookup) on the same
 * photon tree (photon_tree.h). One walk per shading point, near side first; a bounded max-heap
 * of the k best in (d2, photon) order; the maximum radius, and once the heap is full its
 * largest entry, prune the walk; the normal test inside the walk. Its result is the k nearest
 * photons within the radius that pass the normal test, exactly the oracle's (knn_naive.h). */
#ifndef PREE_KNN_KDTREE_H
#define PREE_KNN_KDTREE_H

#include <stddef.h>
#include "knn_select.h"
#include "photon_tree.h"

/* A search's work, summed by the caller. */
typedef struct {
    unsigned long long distance_tests;   /* exact (double) photon-to-point distances computed */
    unsigned long long kernel_tests;     /* photon-to-point tests of the float vector prefilter */
    unsigned long long selection;        /* candidates the selection handled (heap entries, or
                                          * candidates partitioned by the linear selection) */
} knn_work_t;

/* The k nearest photons p with |p - q|^2 <= r2max and n . n_p > cos_min into out[0..k), in
 * (d2, photon) order (the heap sorted by knn_select_buckets, the clustered search's sort);
 * returns their count, or (size_t)-1 when out of memory. */
size_t knn_kdtree_query(const photon_tree_t *t, const double q[3], const double n[3], double cos_min, size_t k,
                        double r2max, knn_cand_t *out, knn_buckets_t *scratch, knn_work_t *w);

#endif
