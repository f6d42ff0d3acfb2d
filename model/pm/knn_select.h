// SPDX-License-Identifier: Apache-2.0
/* knn_select.h: the selection every k-NN search ends with, and the tie rule they share:
 * neighbours ordered by (squared distance, photon index), the k first kept.
 *
 * knn_select sorts every candidate (qsort): the oracle's selection and the unit tests' brute
 * force. knn_select_buckets (candidates as records: the single-pass search's heap) and
 * knn_select_arrays (as arrays: the clustered search's kernel output) are the fast searches'
 * own, linear in the candidates: a counting sort
 * by d2 into twice as many buckets as candidates (photons on a surface are close to uniform in
 * d2, so few buckets hold more than one), of the buckets up to the one holding the k-th only;
 * then one insertion pass over them, in which an element already after its predecessor costs
 * one integer comparison (buckets of more than 16, from equal or crowded d2, are quicksorted
 * first: knn_sort). The order is a strict total order (photon indices differ), so every route
 * gives the same k in the same order. */
#ifndef PREE_KNN_SELECT_H
#define PREE_KNN_SELECT_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    double d2;
    uint32_t photon;   /* index into the photon map */
    uint32_t pos;      /* its tree position (photon_tree.h); the oracle leaves it 0 */
} knn_cand_t;

/* Scratch of knn_select_buckets, grown as needed (zero-initialise; knn_buckets_free). */
typedef struct {
    knn_cand_t *sorted;
    size_t sorted_cap;
    uint32_t *count;
    size_t count_cap;
    uint32_t *bucket;
    size_t bucket_cap;
} knn_buckets_t;

/* a before b in (d2, photon) order */
static inline int knn_less(knn_cand_t a, knn_cand_t b)
{
    return a.d2 < b.d2 || (a.d2 == b.d2 && a.photon < b.photon);
}

#ifdef __cplusplus
extern "C" {
#endif
/* Sort c[0..n) by (d2, photon); returns min(n, k), the count of the k nearest. */
size_t knn_select(knn_cand_t *c, size_t n, size_t k);
/* Sort c[0..n) by (d2, photon) (quicksort with insertion sort below 16, median of three). */
void knn_sort(knn_cand_t *c, size_t n);
/* The min(n, k) nearest of c[0..n) (every d2 in [0, max_d2]) in (d2, photon) order into
 * out[0..); returns their count, or (size_t)-1 when out of memory. */
size_t knn_select_buckets(const knn_cand_t *c, size_t n, size_t k, double max_d2, knn_buckets_t *b, knn_cand_t *out);
/* The same for candidates as arrays (the clustered search's kernel output): candidate i is
 * {d2[i], photon[pos[i]], pos[i]} (photon: tree position -> photon index). */
size_t knn_select_arrays(const double *d2, const uint32_t *pos, const uint32_t *photon, size_t n, size_t k,
                         double max_d2, knn_buckets_t *b, knn_cand_t *out);
void knn_buckets_free(knn_buckets_t *b);
#ifdef __cplusplus
}
#endif

#endif
