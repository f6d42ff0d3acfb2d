// SPDX-License-Identifier: Apache-2.0
/* knn_naive.h: the test oracle's k-NN search (--knn-search naive): per shading point, the k nearest
 * photons within the maximum radius that pass the normal test, through nanoflann's kd-tree and
 * its k-nearest result set (Debian's libnanoflann-dev), not the project's own tree: code the
 * project did not write checks the clustered search. C++ only because nanoflann is a C++
 * header library. */
#ifndef PREE_KNN_NAIVE_H
#define PREE_KNN_NAIVE_H

#include <stddef.h>
#include "knn_select.h"
#include "photon_map.h"

#ifdef __cplusplus
extern "C" {
#endif
typedef struct knn_naive knn_naive_t;

/* An index over map's photons (kept by reference); NULL when out of memory. */
knn_naive_t *knn_naive_new(const photon_map_t *map);
void knn_naive_free(knn_naive_t *s);
/* The k nearest photons p with |p - q|^2 <= r2max and n . n_p > cos_min, in (d2, photon)
 * order, into out[0..k); returns their count, or (size_t)-1 when out of memory. Thread-safe. */
size_t knn_naive_query(const knn_naive_t *s, const double q[3], const double n[3], double cos_min,
                       size_t k, double r2max, knn_cand_t *out);
/* The calling thread's work since its last call: points whose distance nanoflann computed in
 * queries, and candidates sorted (every round); both counters then restart from zero. */
void knn_naive_work(unsigned long long *distance_tests, unsigned long long *selection);
#ifdef __cplusplus
}
#endif

#endif
