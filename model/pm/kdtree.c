/* kdtree.c: the implicit balanced kd-tree (see kdtree.h). */
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "kdtree.h"

typedef struct {
    const double *pts;
    size_t stride;
    uint32_t *idx;
    uint8_t *axis;
} build_t;

static inline double coord(const build_t *b, uint32_t i, int a) { return b->pts[(size_t)i * b->stride + a]; }

/* (coordinate, index) order: a strict total order, so selection is deterministic. */
static inline int less(const build_t *b, uint32_t i, uint32_t j, int a)
{
    double ci = coord(b, i, a), cj = coord(b, j, a);
    return ci < cj || (ci == cj && i < j);
}

static inline void swap(uint32_t *v, size_t i, size_t j) { uint32_t t = v[i]; v[i] = v[j]; v[j] = t; }

/* Put the k-th smallest of v[lo, hi) at k, smaller ones before it, larger after (quickselect,
 * median-of-three pivots). */
static void select_kth(const build_t *b, size_t lo, size_t hi, size_t k, int a)
{
    uint32_t *v = b->idx;
    while (hi - lo > 1) {
        size_t m = lo + (hi - lo) / 2, l = hi - 1;
        if (less(b, v[m], v[lo], a)) swap(v, m, lo);
        if (less(b, v[l], v[lo], a)) swap(v, l, lo);
        if (less(b, v[l], v[m], a)) swap(v, l, m);
        swap(v, m, l);                       /* the pivot (the median of three) to the end */
        size_t store = lo;
        for (size_t i = lo; i < l; i++)
            if (less(b, v[i], v[l], a)) swap(v, i, store++);
        swap(v, store, l);
        if (store == k) return;
        if (k < store) hi = store; else lo = store + 1;
    }
}

static int widest_axis(const build_t *b, size_t lo, size_t hi)
{
    double mn[3], mx[3];
    for (int a = 0; a < 3; a++) mn[a] = mx[a] = coord(b, b->idx[lo], a);
    for (size_t i = lo + 1; i < hi; i++)
        for (int a = 0; a < 3; a++) {
            double c = coord(b, b->idx[i], a);
            if (c < mn[a]) mn[a] = c;
            if (c > mx[a]) mx[a] = c;
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
    for (size_t i = 0; i < n; i++) t->index[i] = (uint32_t)i;
    build_t b = {pts, stride, t->index, t->axis};
    build(&b, 0, n);
    for (size_t i = 0; i < n; i++) {
        const double *p = pts + (size_t)t->index[i] * stride;
        t->x[i] = p[0]; t->y[i] = p[1]; t->z[i] = p[2];
    }
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
    uint32_t **out;
    size_t *n, *cap;
    int failed;
} query_t;

static inline void test_point(query_t *c, size_t i)
{
    double dx = c->t->x[i] - c->q[0], dy = c->t->y[i] - c->q[1], dz = c->t->z[i] - c->q[2];
    if (dx * dx + dy * dy + dz * dz > c->r2) return;
    if (grow_array((void **)c->out, c->cap, *c->n + 1, sizeof **c->out)) { c->failed = 1; return; }
    (*c->out)[(*c->n)++] = (uint32_t)i;
}

static void walk(query_t *c, size_t lo, size_t hi)
{
    while (hi - lo > KD_LEAF) {
        size_t mid = lo + (hi - lo) / 2;
        const double *axis_coord[3] = {c->t->x, c->t->y, c->t->z};
        double diff = c->q[c->t->axis[mid]] - axis_coord[c->t->axis[mid]][mid];
        test_point(c, mid);
        /* The left side holds coordinates <= the split, the right side >= it. */
        if (diff <= 0) {
            if (diff * diff <= c->r2) walk(c, mid + 1, hi);
            hi = mid;
        } else {
            if (diff * diff <= c->r2) walk(c, lo, mid);
            lo = mid + 1;
        }
    }
    for (size_t i = lo; i < hi; i++) test_point(c, i);
}

size_t kdtree_range(const kdtree_t *t, const double q[3], double r, uint32_t **out, size_t *n, size_t *cap)
{
    query_t c = {t, {q[0], q[1], q[2]}, r * r, out, n, cap, 0};
    size_t before = *n;
    walk(&c, 0, t->n);
    return c.failed ? (size_t)-1 : *n - before;
}
