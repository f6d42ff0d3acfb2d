// SPDX-License-Identifier: Apache-2.0
/* cluster.c: hierarchical aggregation of hit points into clusters of 16 (see cluster.h). */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>
#include "cluster.h"
#include "morton.h"

typedef struct { uint32_t object; uint64_t morton; uint32_t index; } sort_key_t;

static int key_cmp(const void *a, const void *b)
{
    const sort_key_t *x = a, *y = b;
    if (x->object != y->object) return x->object < y->object ? -1 : 1;
    if (x->morton != y->morton) return x->morton < y->morton ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

static sort_key_t *sorted_keys(const hitpoints_t *h)
{
    sort_key_t *k = malloc((h->n ? h->n : 1) * sizeof *k);
    if (!k) return NULL;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < h->n; i++) {
        const double p[3] = {h->hot[i].px, h->hot[i].py, h->hot[i].pz};
        for (int a = 0; a < 3; a++) { lo[a] = fmin(lo[a], p[a]); hi[a] = fmax(hi[a], p[a]); }
    }
    for (size_t i = 0; i < h->n; i++) {
        const double p[3] = {h->hot[i].px, h->hot[i].py, h->hot[i].pz};
        uint64_t m = 0;
        for (int a = 0; a < 3; a++) {
            double span = hi[a] - lo[a], t = span > 0 ? (p[a] - lo[a]) / span : 0;
            m |= morton_spread3((uint64_t)(t * 2097151.0)) << a;
        }
        k[i] = (sort_key_t){h->object[i], m, (uint32_t)i};
    }
    qsort(k, h->n, sizeof *k, key_cmp);
    return k;
}

/* One bundle's working clusters. */
typedef struct {
    double sp[3], sn[3];                     /* sums of positions and normals */
    double c[3], nc[3];                      /* centre, normalised mean normal */
    int size, head, tail;                    /* member list through next[] */
} agg_t;

static void agg_centre(agg_t *a)
{
    double len = sqrt(a->sn[0] * a->sn[0] + a->sn[1] * a->sn[1] + a->sn[2] * a->sn[2]);
    for (int k = 0; k < 3; k++) {
        a->c[k] = a->sp[k] / a->size;
        a->nc[k] = len > 0 ? a->sn[k] / len : 0;
    }
}

static double similarity(const agg_t *a, const agg_t *b, double lambda)
{
    double dp = 0, dn = 0;
    for (int k = 0; k < 3; k++) {
        dp += (a->c[k] - b->c[k]) * (a->c[k] - b->c[k]);
        dn += (a->nc[k] - b->nc[k]) * (a->nc[k] - b->nc[k]);
    }
    return dp + lambda * dn;
}

/* Aggregate the m points idx[0..m) (m <= bundle); write them cluster by cluster to member[]
 * and the cluster sizes to sizes[]; returns the cluster count. */
static size_t aggregate(const hitpoints_t *h, const uint32_t *idx, size_t m, double lambda,
                        agg_t *a, int *next, int *list, unsigned char *used, uint32_t *member, uint8_t *sizes)
{
    for (size_t i = 0; i < m; i++) {
        const hp_hot_t *p = &h->hot[idx[i]];
        a[i] = (agg_t){.sp = {p->px, p->py, p->pz}, .sn = {p->nx, p->ny, p->nz}, .size = 1,
                       .head = (int)i, .tail = (int)i};
        agg_centre(&a[i]);
        next[i] = -1;
        list[i] = (int)i;
    }
    size_t alive = m;
    for (int merged = 1; merged;) {
        merged = 0;
        memset(used, 0, m);
        size_t kept = 0;
        for (size_t x = 0; x < alive; x++) {
            int c = list[x];
            if (used[c]) continue;
            used[c] = 1;
            int best = -1;
            double best_d = INFINITY;
            for (size_t y = x + 1; y < alive; y++) {
                int d = list[y];
                if (used[d] || a[c].size + a[d].size > CLUSTER_MAX) continue;
                double s = similarity(&a[c], &a[d], lambda);
                if (s < best_d) { best_d = s; best = d; }
            }
            if (best >= 0) {
                agg_t *p = &a[c], *q = &a[best];
                for (int k = 0; k < 3; k++) { p->sp[k] += q->sp[k]; p->sn[k] += q->sn[k]; }
                p->size += q->size;
                next[p->tail] = q->head;
                p->tail = q->tail;
                agg_centre(p);
                used[best] = 1;
                merged = 1;
            }
            list[kept++] = c;
        }
        alive = kept;
    }
    size_t w = 0;
    for (size_t x = 0; x < alive; x++) {
        sizes[x] = (uint8_t)a[list[x]].size;
        for (int i = a[list[x]].head; i >= 0; i = next[i]) member[w++] = idx[i];
    }
    return alive;
}

int cluster_build(const hitpoints_t *h, const cluster_opts_t *o, clusters_t *out)
{
    memset(out, 0, sizeof *out);
    out->n = h->n;
    sort_key_t *k = sorted_keys(h);
    size_t nb = 0, *bstart = malloc((h->n + 2) * sizeof *bstart);
    uint32_t *idx = malloc((h->n ? h->n : 1) * sizeof *idx);
    uint8_t *sizes = malloc(h->n ? h->n : 1);
    size_t *bcount = malloc((h->n + 1) * sizeof *bcount);
    out->member = malloc((h->n ? h->n : 1) * sizeof *out->member);
    int failed = !k || !bstart || !idx || !sizes || !bcount || !out->member;
    /* Bundles: runs of at most o->bundle points of one object. */
    for (size_t i = 0; !failed && i < h->n; i++) {
        idx[i] = k[i].index;
        if (i == 0 || k[i].object != k[i - 1].object || i - bstart[nb - 1] == o->bundle) bstart[nb++] = i;
    }
    if (!failed) bstart[nb] = h->n;
    const int threads = o->threads > 0 ? o->threads : omp_get_max_threads();
#pragma omp parallel num_threads(threads) reduction(| : failed)
    {
        agg_t *a = malloc(o->bundle * sizeof *a);
        int *next = malloc(o->bundle * sizeof *next), *list = malloc(o->bundle * sizeof *list);
        unsigned char *used = malloc(o->bundle);
        if (!a || !next || !list || !used) failed = 1;
#pragma omp for schedule(dynamic, 1)
        for (size_t b = 0; b < nb; b++) {
            if (failed) continue;
            size_t lo = bstart[b];
            bcount[b] = aggregate(h, idx + lo, bstart[b + 1] - lo, o->lambda, a, next, list, used,
                                  out->member + lo, sizes + lo);
        }
        free(a); free(next); free(list); free(used);
    }
    size_t total = 0;
    for (size_t b = 0; !failed && b < nb; b++) total += bcount[b];
    out->start = failed ? NULL : malloc((total + 1) * sizeof *out->start);
    if (!out->start) failed = 1;
    for (size_t b = 0, c = 0; !failed && b < nb; b++) {
        size_t at = bstart[b];
        for (size_t j = 0; j < bcount[b]; j++) { out->start[c++] = at; at += sizes[bstart[b] + j]; }
    }
    if (!failed) { out->start[total] = h->n; out->count = total; }
    free(k); free(bstart); free(idx); free(sizes); free(bcount);
    if (failed) { clusters_free(out); return -1; }
    return 0;
}

void clusters_free(clusters_t *c)
{
    free(c->member);
    free(c->start);
    memset(c, 0, sizeof *c);
}

void cluster_centre(const hitpoints_t *h, const clusters_t *c, size_t k, double centre[3], double *farthest)
{
    size_t lo = c->start[k], hi = c->start[k + 1];
    double s[3] = {0, 0, 0};
    for (size_t i = lo; i < hi; i++) {
        const hp_hot_t *p = &h->hot[c->member[i]];
        s[0] += p->px; s[1] += p->py; s[2] += p->pz;
    }
    for (int a = 0; a < 3; a++) centre[a] = s[a] / (double)(hi - lo);
    double f2 = 0;
    for (size_t i = lo; i < hi; i++) {
        const hp_hot_t *p = &h->hot[c->member[i]];
        double dx = p->px - centre[0], dy = p->py - centre[1], dz = p->pz - centre[2];
        f2 = fmax(f2, dx * dx + dy * dy + dz * dz);
    }
    *farthest = sqrt(f2);
}

double cluster_coherent_fraction(const hitpoints_t *h, const clusters_t *c)
{
    double eps = 0, centre[3], far;
    size_t multi = 0, coherent = 0;
    for (size_t k = 0; k < c->count; k++) { cluster_centre(h, c, k, centre, &far); eps += far; }
    if (c->count) eps /= (double)c->count;
    for (size_t k = 0; k < c->count; k++) {
        size_t lo = c->start[k], hi = c->start[k + 1];
        if (hi - lo < 2) continue;
        multi++;
        int ok = 1;
        for (size_t i = lo; i < hi && ok; i++) {
            const hp_hot_t *p = &h->hot[c->member[i]];
            double best = INFINITY;
            for (size_t j = lo; j < hi; j++) {
                if (j == i) continue;
                const hp_hot_t *q = &h->hot[c->member[j]];
                double dx = p->px - q->px, dy = p->py - q->py, dz = p->pz - q->pz;
                best = fmin(best, dx * dx + dy * dy + dz * dz);
            }
            ok = sqrt(best) < eps;
        }
        coherent += (size_t)ok;
    }
    return multi ? (double)coherent / (double)multi : 1.0;
}
