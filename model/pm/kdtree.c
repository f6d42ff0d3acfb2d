// SPDX-License-Identifier: Apache-2.0
/* kdtree.c: the implicit balanced kd-tree (see kdtree.h). */
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "kdtree.h"

/* The build permutes the tree's own arrays in place (positions and original indices moved
 * together), so partitions read memory in order. */
typedef struct {
    double *c[3];          /* x, y, z, being permuted into tree order */
    uint32_t *idx;
    uint8_t *axis;
} build_t;

/* (coordinate, index) order: a strict total order, so selection is deterministic. */
static inline int less(const build_t *b, size_t i, size_t j, int a)
{
    const double ci = b->c[a][i], cj = b->c[a][j];
    return ci < cj || (ci == cj && b->idx[i] < b->idx[j]);
}

static inline void swap(const build_t *b, size_t i, size_t j)
{
    for (int a = 0; a < 3; a++) { double t = b->c[a][i]; b->c[a][i] = b->c[a][j]; b->c[a][j] = t; }
    uint32_t t = b->idx[i]; b->idx[i] = b->idx[j]; b->idx[j] = t;
}

/* Put the k-th smallest of [lo, hi) at k, smaller ones before it, larger after (quickselect,
 * median-of-three pivots). */
static void select_kth(const build_t *b, size_t lo, size_t hi, size_t k, int a)
{
    while (hi - lo > 1) {
        size_t m = lo + (hi - lo) / 2, l = hi - 1;
        if (less(b, m, lo, a)) swap(b, m, lo);
        if (less(b, l, lo, a)) swap(b, l, lo);
        if (less(b, l, m, a)) swap(b, l, m);
        swap(b, m, l);                       /* the pivot (the median of three) to the end */
        size_t store = lo;
        for (size_t i = lo; i < l; i++)
            if (less(b, i, l, a)) swap(b, i, store++);
        swap(b, store, l);
        if (store == k) return;
        if (k < store) hi = store; else lo = store + 1;
    }
}

static int widest_axis(const build_t *b, size_t lo, size_t hi)
{
    double mn[3], mx[3];
    for (int a = 0; a < 3; a++) {
        mn[a] = mx[a] = b->c[a][lo];
        for (size_t i = lo + 1; i < hi; i++) {
            const double c = b->c[a][i];
            mn[a] = c < mn[a] ? c : mn[a];
            mx[a] = c > mx[a] ? c : mx[a];
        }
    }
    int best = 0;
    for (int a = 1; a < 3; a++)
        if (mx[a] - mn[a] > mx[best] - mn[best]) best = a;
    return best;
}

static void build(build_t *b, size_t lo, size_t hi)
{
    while (hi - lo > KD_LEAF) {
        size_t mid = lo + (hi - lo) / 2;
        int a = widest_axis(b, lo, hi);
        select_kth(b, lo, hi, mid, a);
        b->axis[mid] = (uint8_t)a;
        build(b, lo, mid);
        lo = mid + 1;
    }
}

int kdtree_build(kdtree_t *t, const double *pts, size_t stride, size_t n)
{
    memset(t, 0, sizeof *t);
    size_t m = n ? n : 1;
    t->x = malloc(m * sizeof *t->x);
    t->y = malloc(m * sizeof *t->y);
    t->z = malloc(m * sizeof *t->z);
    t->index = malloc(m * sizeof *t->index);
    t->axis = calloc(m, 1);
    if (!t->x || !t->y || !t->z || !t->index || !t->axis || n > UINT32_MAX) { kdtree_free(t); return -1; }
    t->n = n;
    for (size_t i = 0; i < n; i++) {
        const double *p = pts + i * stride;
        t->x[i] = p[0]; t->y[i] = p[1]; t->z[i] = p[2];
        t->index[i] = (uint32_t)i;
    }
    build_t b = {{t->x, t->y, t->z}, t->index, t->axis};
    build(&b, 0, n);
    return 0;
}

void kdtree_free(kdtree_t *t)
{
    free(t->x); free(t->y); free(t->z); free(t->index); free(t->axis);
    memset(t, 0, sizeof *t);
}

typedef struct {
    const kdtree_t *t;
    double q[3], r2;
    kd_range_t **out;
    size_t *n, *cap;
    int failed;
} runs_t;

static void emit(runs_t *c, size_t lo, size_t hi)
{
    if (*c->n && (*c->out)[*c->n - 1].hi == lo) { (*c->out)[*c->n - 1].hi = (uint32_t)hi; return; }
    if (grow_array((void **)c->out, c->cap, *c->n + 1, sizeof **c->out)) { c->failed = 1; return; }
    (*c->out)[(*c->n)++] = (kd_range_t){(uint32_t)lo, (uint32_t)hi};
}

/* In order (left, split point, right), so the runs come out sorted; a subtree of KD_RUN_LEAF
 * positions or fewer is taken whole, as a leaf is. off: q's offset from the node's cell (the box
 * its splits bound) along each axis, 0 within its slab; each a coordinate difference rounded as
 * a point's own offset from q is, so that the cell's squared distance (off . off, summed in the
 * points' order) lies within r of q and no point inside the cell is nearer, in floating point
 * too (Arya and Mount's incremental distance). The near child is walked; the far child, and the
 * split point on the plane between the two, while the far child's cell reaches r. */
static void walk_runs(runs_t *c, size_t lo, size_t hi, double off[3])
{
    if (hi - lo <= KD_RUN_LEAF) { if (hi > lo) emit(c, lo, hi); return; }
    const size_t mid = lo + (hi - lo) / 2;
    const int a = c->t->axis[mid];
    const double *axis_coord[3] = {c->t->x, c->t->y, c->t->z};
    const double diff = c->q[a] - axis_coord[a][mid], keep = off[a];
    off[a] = diff < 0 ? -diff : diff;                /* the far child's cell */
    const int far = off[0] * off[0] + off[1] * off[1] + off[2] * off[2] <= c->r2;
    if (diff <= 0) {
        off[a] = keep;
        walk_runs(c, lo, mid, off);
        if (far) {
            emit(c, mid, mid + 1);
            off[a] = -diff;
            walk_runs(c, mid + 1, hi, off);
        }
    } else {
        if (far) {
            walk_runs(c, lo, mid, off);
            emit(c, mid, mid + 1);
        }
        off[a] = keep;
        walk_runs(c, mid + 1, hi, off);
    }
    off[a] = keep;
}

int kdtree_runs(const kdtree_t *t, const double q[3], double r, kd_range_t **out, size_t *n, size_t *cap)
{
    runs_t c = {t, {q[0], q[1], q[2]}, r * r, out, n, cap, 0};
    double off[3] = {0, 0, 0};
    *n = 0;
    walk_runs(&c, 0, t->n, off);
    return c.failed ? -1 : 0;
}
