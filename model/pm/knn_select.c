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

/* The bucket plan shared by both selections. Bucket j of nb = 2n holds d2 in
 * [j, j + 1) * max_d2 / nb: monotone in d2, so bucket order is d2 order and equal d2 share a
 * bucket; twice as many buckets as candidates, so few share one. Candidate i's d2 is
 * d2[i * stride]; its bucket goes to b->bucket, and b->count becomes each bucket's start up to
 * the last one needed (the one that holds the got-th candidate; *end: the candidates through
 * it), then the start of a discard region (bucket last + 1) for the rest. Returns last, or
 * (size_t)-1 when out of memory; *crowded: some bucket holds more than 16. */
static size_t plan(const double *d2, size_t stride, size_t n, size_t got, double max_d2, knn_buckets_t *b,
                   size_t *end, int *crowded)
{
    const size_t nb = 2 * n;
    if (grow_array((void **)&b->sorted, &b->sorted_cap, n, sizeof *b->sorted) ||
        grow_array((void **)&b->count, &b->count_cap, nb + 1, sizeof *b->count) ||
        grow_array((void **)&b->bucket, &b->bucket_cap, n, sizeof *b->bucket))
        return (size_t)-1;
    const double scale = max_d2 > 0 ? (double)nb / max_d2 : 0, top = (double)(nb - 1);
    uint32_t *count = b->count, *id = b->bucket, big = 0;
    memset(count, 0, nb * sizeof *count);
    for (size_t i = 0; i < n; i++) {
        const double v = d2[i * stride] * scale;
        const uint32_t j = v < top ? (uint32_t)v : (uint32_t)top;
        id[i] = j;
        big |= ++count[j] > 16;
    }
    size_t last = 0, e = 0;
    for (;; last++) {
        const uint32_t size = count[last];
        count[last] = (uint32_t)e;
        e += size;
        if (e >= got) break;
    }
    count[last + 1] = (uint32_t)e;
    *end = e;
    *crowded = big != 0;
    return last;
}

/* The bucket of candidate i in the plan: its own through last, else the discard region's. */
static inline size_t slot(const knn_buckets_t *b, size_t i, size_t last)
{
    const size_t j = b->bucket[i];
    return j <= last ? j : last + 1;
}

/* b->sorted[0..end), the candidates through the plan's last bucket, into (d2, photon) order
 * (count[j] is bucket j's end now): buckets of more than 16 (equal or crowded d2) are quicksorted
 * first; then one insertion pass over all of them orders the small ones (each element moves
 * within its bucket only). The got first into out. */
static void finish(knn_buckets_t *b, size_t last, size_t end, int crowded, size_t got, knn_cand_t *out)
{
    if (crowded)
        for (size_t j = 0, lo = 0; j <= last; lo = b->count[j++])
            if (b->count[j] - lo > 16) knn_sort(b->sorted + lo, b->count[j] - lo);
    sort_nearly(b->sorted, end);
    memcpy(out, b->sorted, got * sizeof *out);
}

size_t knn_select_buckets(const knn_cand_t *c, size_t n, size_t k, double max_d2, knn_buckets_t *b, knn_cand_t *out)
{
    const size_t got = n < k ? n : k;
    if (got == 0) return 0;
    size_t end;
    int crowded;
    const size_t last = plan(&c[0].d2, sizeof *c / sizeof(double), n, got, max_d2, b, &end, &crowded);
    if (last == (size_t)-1) return (size_t)-1;
    for (size_t i = 0; i < n; i++) b->sorted[b->count[slot(b, i, last)]++] = c[i];
    finish(b, last, end, crowded, got, out);
    return got;
}

size_t knn_select_arrays(const double *d2, const uint32_t *pos, const uint32_t *photon, size_t n, size_t k,
                         double max_d2, knn_buckets_t *b, knn_cand_t *out)
{
    const size_t got = n < k ? n : k;
    if (got == 0) return 0;
    size_t end;
    int crowded;
    const size_t last = plan(d2, 1, n, got, max_d2, b, &end, &crowded);
    if (last == (size_t)-1) return (size_t)-1;
    for (size_t i = 0; i < n; i++) b->sorted[b->count[slot(b, i, last)]++] = (knn_cand_t){d2[i], photon[pos[i]], pos[i]};
    finish(b, last, end, crowded, got, out);
    return got;
}

void knn_buckets_free(knn_buckets_t *b)
{
    free(b->sorted);
    free(b->count);
    free(b->bucket);
    memset(b, 0, sizeof *b);
}
