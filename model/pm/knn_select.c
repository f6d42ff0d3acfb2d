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

size_t knn_select_buckets(const knn_cand_t *c, size_t n, size_t k, double max_d2, knn_buckets_t *b, knn_cand_t *out)
{
    const size_t got = n < k ? n : k;
    if (got == 0) return 0;
    if (grow_array((void **)&b->sorted, &b->sorted_cap, n, sizeof *b->sorted) ||
        grow_array((void **)&b->count, &b->count_cap, n + 1, sizeof *b->count))
        return (size_t)-1;
    /* Bucket j holds d2 in [j, j + 1) * max_d2 / n: monotone in d2, so bucket order is d2 order
     * and equal d2 share a bucket. */
    const double scale = max_d2 > 0 ? (double)n / max_d2 : 0;
    uint32_t *count = b->count;
    memset(count, 0, (n + 1) * sizeof *count);
    for (size_t i = 0; i < n; i++) {
        size_t j = (size_t)(c[i].d2 * scale);
        count[(j < n ? j : n - 1) + 1]++;
    }
    size_t last = 0;                         /* the bucket that holds the got-th candidate */
    for (size_t j = 1; j <= n; j++) {
        count[j] += count[j - 1];
        if (count[j - 1] < got) last = j - 1;
    }
    for (size_t i = 0; i < n; i++) {   /* only the buckets through the last are needed */
        size_t j = (size_t)(c[i].d2 * scale);
        j = j < n ? j : n - 1;
        if (j <= last) b->sorted[count[j]++] = c[i];
    }
    /* count[j] is now bucket j's end: sort each bucket through the last one, copy the first got. */
    for (size_t j = 0, lo = 0; j <= last; lo = count[j++]) {
        if (count[j] - lo > 16) knn_sort(b->sorted + lo, count[j] - lo);
        else if (count[j] - lo > 1) insertion(b->sorted, lo, count[j]);
    }
    memcpy(out, b->sorted, got * sizeof *out);
    return got;
}

void knn_buckets_free(knn_buckets_t *b)
{
    free(b->sorted);
    free(b->count);
    memset(b, 0, sizeof *b);
}
