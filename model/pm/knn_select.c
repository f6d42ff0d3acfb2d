// SPDX-License-Identifier: Apache-2.0
/* knn_select.c: the selections of the k nearest (see knn_select.h). */
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "knn_select.h"

static int cand_cmp(const void *a, const void *b)
{
    const knn_cand_t *x = a, *y = b;
    if (x->d2 != y->d2) return x->d2 < y->d2 ? -1 : 1;
    return x->photon < y->photon ? -1 : x->photon > y->photon;
}

size_t knn_select(knn_cand_t *c, size_t n, size_t k)
{
    if (n > 1) qsort(c, n, sizeof *c, cand_cmp);   /* c may be NULL when n is 0 (qsort's contract) */
    return n < k ? n : k;
}

static inline void swap(knn_cand_t *c, size_t i, size_t j) { knn_cand_t t = c[i]; c[i] = c[j]; c[j] = t; }

/* Partition c[lo, hi) (hi - lo >= 3) around the median of its first, middle and last
 * elements; returns the pivot's final place p: c[lo, p) before it, c(p, hi) after it. */
static size_t partition(knn_cand_t *c, size_t lo, size_t hi)
{
    size_t m = lo + (hi - lo) / 2, l = hi - 1;
    if (knn_less(c[m], c[lo])) swap(c, m, lo);
    if (knn_less(c[l], c[lo])) swap(c, l, lo);
    if (knn_less(c[l], c[m])) swap(c, l, m);
    swap(c, m, l);                         /* the median of three to the end */
    const knn_cand_t p = c[l];
    size_t store = lo;
    for (size_t i = lo; i < l; i++)
        if (knn_less(c[i], p)) swap(c, i, store++);
    swap(c, store, l);
    return store;
}

static inline void insertion(knn_cand_t *c, size_t lo, size_t hi)
{
    for (size_t i = lo + 1; i < hi; i++) {
        knn_cand_t v = c[i];
        size_t j = i;
        for (; j > lo && knn_less(v, c[j - 1]); j--) c[j] = c[j - 1];
        c[j] = v;
    }
}

void knn_sort(knn_cand_t *c, size_t n)
{
    size_t lo = 0, hi = n;
    while (hi - lo > 16) {             /* recurse on the smaller side, loop on the larger */
        size_t p = partition(c, lo, hi);
        if (p - lo < hi - p - 1) { knn_sort(c + lo, p - lo); lo = p + 1; }
        else { knn_sort(c + p + 1, hi - p - 1); hi = p; }
    }
    insertion(c, lo, hi);
}

/* a before b in (d2, photon) order for d2 >= 0 (not NaN): the bits of such doubles order as
 * their values, so one branch-free integer comparison decides it. */
static inline int before(const knn_cand_t *a, const knn_cand_t *b)
{
    uint64_t x, y;
    memcpy(&x, &a->d2, sizeof x);
    memcpy(&y, &b->d2, sizeof y);
    return (x < y) | ((x == y) & (a->photon < b->photon));
}

/* Insertion sort of c[0..n) where each element lies close to its place (the buckets' order):
 * an element already after its predecessor costs one comparison. */
static void sort_nearly(knn_cand_t *c, size_t n)
{
    for (size_t i = 1; i < n; i++) {
        if (!before(&c[i], &c[i - 1])) continue;
        const knn_cand_t v = c[i];
        size_t j = i;
        do { c[j] = c[j - 1]; j--; } while (j > 0 && before(&v, &c[j - 1]));
        c[j] = v;
    }
}

size_t knn_select_buckets(const knn_cand_t *c, size_t n, size_t k, double max_d2, knn_buckets_t *b, knn_cand_t *out)
{
    const size_t got = n < k ? n : k, nb = 2 * n;
    if (got == 0) return 0;
    if (grow_array((void **)&b->sorted, &b->sorted_cap, n, sizeof *b->sorted) ||
        grow_array((void **)&b->count, &b->count_cap, nb, sizeof *b->count))
        return (size_t)-1;
    /* Bucket j holds d2 in [j, j + 1) * max_d2 / nb: monotone in d2, so bucket order is d2 order
     * and equal d2 share a bucket. Twice as many buckets as candidates: few share one. */
    const double scale = max_d2 > 0 ? (double)nb / max_d2 : 0;
    uint32_t *count = b->count;
    memset(count, 0, nb * sizeof *count);
    for (size_t i = 0; i < n; i++) {
        const size_t j = (size_t)(c[i].d2 * scale);
        count[j < nb ? j : nb - 1]++;
    }
    /* Each bucket's start, up to the last one needed: the one that holds the got-th candidate. */
    size_t last = 0, end = 0;                /* end: the candidates through the last bucket */
    uint32_t most = 0;                       /* the most a bucket through it holds */
    for (;; last++) {
        const uint32_t size = count[last];
        count[last] = (uint32_t)end;
        end += size;
        most = size > most ? size : most;
        if (end >= got) break;
    }
    for (size_t i = 0; i < n; i++) {
        size_t j = (size_t)(c[i].d2 * scale);
        j = j < nb ? j : nb - 1;
        if (j <= last) b->sorted[count[j]++] = c[i];
    }
    /* count[j] is now bucket j's end. Buckets of more than 16 (equal or crowded d2) are
     * quicksorted; then one insertion pass over all of them orders the small ones (each
     * element moves within its bucket only). */
    if (most > 16)
        for (size_t j = 0, lo = 0; j <= last; lo = count[j++])
            if (count[j] - lo > 16) knn_sort(b->sorted + lo, count[j] - lo);
    sort_nearly(b->sorted, end);
    memcpy(out, b->sorted, got * sizeof *out);
    return got;
}

void knn_buckets_free(knn_buckets_t *b)
{
    free(b->sorted);
    free(b->count);
    memset(b, 0, sizeof *b);
}
