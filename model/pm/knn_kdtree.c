// SPDX-License-Identifier: Apache-2.0
/* knn_kdtree.c: the single-pass k-NN walk with a bounded max-heap (see knn_kdtree.h). */
#include "knn_kdtree.h"

typedef struct {
    const photon_tree_t *t;
    double q[3], n[3], cos_min, bound;   /* bound: r2max, then the heap's largest d2 */
    knn_cand_t *heap;                    /* max-heap in (d2, photon) order */
    size_t k, count;
    knn_work_t *w;
} walk_t;

static void sift_down(knn_cand_t *h, size_t n, size_t i)
{
    const knn_cand_t v = h[i];
    for (size_t c; (c = 2 * i + 1) < n; i = c) {
        if (c + 1 < n && knn_less(h[c], h[c + 1])) c++;
        if (!knn_less(v, h[c])) break;
        h[i] = h[c];
    }
    h[i] = v;
}

static void sift_up(knn_cand_t *h, size_t i)
{
    const knn_cand_t v = h[i];
    for (; i > 0 && knn_less(h[(i - 1) / 2], v); i = (i - 1) / 2) h[i] = h[(i - 1) / 2];
    h[i] = v;
}

/* Tree position i against the query: the oracle's exact test (photon_tree.h), so both see the
 * same bits. */
static inline void visit(walk_t *c, size_t i)
{
    c->w->distance_tests++;
    const double d2 = photon_d2(c->t, i, c->q);
    if (d2 > c->bound || !photon_facing(c->t, i, c->n, c->cos_min)) return;
    const knn_cand_t v = {d2, c->t->kd.index[i], (uint32_t)i};
    c->w->selection++;
    if (c->count < c->k) {
        c->heap[c->count] = v;
        sift_up(c->heap, c->count++);
    } else if (knn_less(v, c->heap[0])) {
        c->heap[0] = v;
        sift_down(c->heap, c->k, 0);
    } else {
        return;
    }
    if (c->count == c->k) c->bound = c->heap[0].d2;
}

static void walk(walk_t *c, size_t lo, size_t hi)
{
    const kdtree_t *kd = &c->t->kd;
    const double *axis_coord[3] = {kd->x, kd->y, kd->z};
    while (hi - lo > KD_LEAF) {
        const size_t mid = lo + (hi - lo) / 2;
        const double diff = c->q[kd->axis[mid]] - axis_coord[kd->axis[mid]][mid];
        /* The left side holds coordinates <= the split, the right side >= it: the near side
         * first, the split point, then the far side while the bound still reaches it. */
        if (diff <= 0) walk(c, lo, mid); else walk(c, mid + 1, hi);
        visit(c, mid);
        if (diff * diff > c->bound) return;
        if (diff <= 0) lo = mid + 1; else hi = mid;
    }
    for (size_t i = lo; i < hi; i++) visit(c, i);
}

size_t knn_kdtree_query(const photon_tree_t *t, const double q[3], const double n[3], double cos_min, size_t k,
                        double r2max, knn_cand_t *out, knn_buckets_t *scratch, knn_work_t *w)
{
    if (k == 0 || t->kd.n == 0) return 0;
    walk_t c = {t, {q[0], q[1], q[2]}, {n[0], n[1], n[2]}, cos_min, r2max, out, k, 0, w};
    walk(&c, 0, t->kd.n);
    return c.count ? knn_select_buckets(out, c.count, k, out[0].d2, scratch, out) : 0;
}
