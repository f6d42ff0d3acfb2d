/* knn_clustered.c: the factorized k-NN search of one cluster (see knn_clustered.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "knn_clustered.h"

typedef struct {
    double px[KNN_LANES], py[KNN_LANES], pz[KNN_LANES];
    double nx[KNN_LANES], ny[KNN_LANES], nz[KNN_LANES];
    double b2[KNN_LANES];
} lanes_t;

/* Each photon of the scope against the 16 lanes: d2, or +inf where it fails the normal test
 * or the bound. The expression order is the naive search's (knn_naive.cpp, nanoflann's L2
 * metric), so both searches see the same d2 bits. Inlined into both callers below, compiled
 * once for AVX2 and once portably: the same operations, so the same bits. */
static inline __attribute__((always_inline)) void distance_matrix(const kdtree_t *t, const photon_map_t *map,
                                                                  const lanes_t *L, double cos_min,
                                                                  const uint32_t *scope, size_t n, double *d2)
{
    for (size_t j = 0; j < n; j++) {
        const float *pn = map->p[t->index[scope[j]]].n;
        const double n0 = pn[0], n1 = pn[1], n2 = pn[2];
        const double x = t->x[scope[j]], y = t->y[scope[j]], z = t->z[scope[j]];
        double *row = d2 + j * KNN_LANES;
        for (int l = 0; l < KNN_LANES; l++) {
            double dx = L->px[l] - x, dy = L->py[l] - y, dz = L->pz[l] - z;
            double v = dx * dx + dy * dy + dz * dz;
            int ok = L->nx[l] * n0 + L->ny[l] * n1 + L->nz[l] * n2 > cos_min && v <= L->b2[l];
            row[l] = ok ? v : INFINITY;
        }
    }
}

__attribute__((target("avx2")))
static void matrix_avx2(const kdtree_t *t, const photon_map_t *map, const lanes_t *L, double cos_min,
                        const uint32_t *scope, size_t n, double *d2)
{
    distance_matrix(t, map, L, cos_min, scope, n, d2);
}

static void matrix_portable(const kdtree_t *t, const photon_map_t *map, const lanes_t *L, double cos_min,
                            const uint32_t *scope, size_t n, double *d2)
{
    distance_matrix(t, map, L, cos_min, scope, n, d2);
}

/* The histogram refinement of lane l: the upper end of the d2 range that holds its k-th
 * candidate (all candidates below it are then the k nearest and a few more), or +inf when it
 * has fewer than k candidates. */
static double refine(const double *d2, size_t n, int l, size_t k, double b2)
{
    double lo = 0, hi = nextafter(b2, INFINITY);
    size_t below = 0;
    for (int it = 0; it < KNN_ITERS; it++) {
        size_t hist[KNN_BINS] = {0};
        double mn[KNN_BINS], mx[KNN_BINS];
        const double w = (hi - lo) / KNN_BINS;
        if (!(w > 0)) break;
        for (size_t j = 0; j < n; j++) {
            double v = d2[j * KNN_LANES + l];
            if (v < lo || v >= hi) continue;
            int b = (int)((v - lo) / w);
            b = b < KNN_BINS ? b : KNN_BINS - 1;
            if (!hist[b]++) mn[b] = mx[b] = v;
            mn[b] = fmin(mn[b], v);
            mx[b] = fmax(mx[b], v);
        }
        size_t cum = below;
        int bin = -1;
        for (int b = 0; b < KNN_BINS && bin < 0; b++) {
            if (cum + hist[b] >= k) bin = b;
            else cum += hist[b];
        }
        if (bin < 0) return INFINITY;         /* fewer than k: only possible at the start */
        /* The bin index is monotone in v, so the bin's own extremes bound it exactly. */
        lo = mn[bin];
        hi = nextafter(mx[bin], INFINITY);
        below = cum;
    }
    return hi;
}

/* One pass over a scope of radius rs + far (rs <= r0): the neighbours of every member within r0
 * among the scope's photons. Returns 0, or -1 when out of memory; *exact is set when every
 * member's result is certain: the scope holds every photon within rs + far - d_l of member l,
 * so a result is certain when rs = r0, or when k were found and the k-th lies within that. */
static int scope_pass(const kdtree_t *t, const photon_map_t *map, const lanes_t *L, const double c[3], double far,
                      const double *d, int m, double rs, double r0, size_t k, double cos_min, knn_scratch_t *s,
                      knn_cand_t *out, size_t *counts, knn_cluster_stats_t *st, int *exact)
{
    const double R0 = rs + far;
    s->scope_n = 0;
    if (kdtree_range(t, c, R0, &s->scope, &s->scope_n, &s->scope_cap) == (size_t)-1) return -1;
    const size_t n = s->scope_n;
    if (grow_array((void **)&s->d2, &s->d2_cap, n * KNN_LANES + 1, sizeof *s->d2)) return -1;
    if (__builtin_cpu_supports("avx2")) matrix_avx2(t, map, L, cos_min, s->scope, n, s->d2);
    else matrix_portable(t, map, L, cos_min, s->scope, n, s->d2);
    const double Kc = (R0 / rs) * (R0 / rs) * (double)k;
    const int sparse = (double)n < Kc;
    st->sparse += (unsigned long long)sparse;
    st->scope_photons += n;
    st->distance_tests += (unsigned long long)n * (unsigned long long)m;
    *exact = 1;
    for (int l = 0; l < m; l++) {
        /* The exact selection among the candidates below hi: the k nearest and the few others
         * of the k-th's histogram range (every candidate in a sparse scope). */
        const double hi = sparse ? INFINITY : refine(s->d2, n, l, k, L->b2[l]);
        size_t nc = 0;
        if (grow_array((void **)&s->cand, &s->cand_cap, n + 1, sizeof *s->cand)) return -1;
        for (size_t j = 0; j < n; j++) {
            double v = s->d2[j * KNN_LANES + l];
            if (v < hi) s->cand[nc++] = (knn_cand_t){v, t->index[s->scope[j]]};
        }
        size_t got = knn_select(s->cand, nc, k);
        memcpy(out + (size_t)l * k, s->cand, got * sizeof *s->cand);
        counts[l] = got;
        const double g = R0 - d[l];
        if (rs < r0 && !(got == k && s->cand[k - 1].d2 <= g * g)) *exact = 0;
    }
    return 0;
}

int knn_cluster(const kdtree_t *t, const photon_map_t *map, const hitpoints_t *h, const uint32_t *members,
                int m, double r0, size_t k, double cos_min, knn_scratch_t *s, knn_cand_t *out, size_t *counts,
                double *bound2, knn_cluster_stats_t *st)
{
    double c[3] = {0, 0, 0}, d[KNN_LANES], far = 0;
    lanes_t L;
    for (int l = 0; l < KNN_LANES; l++) {
        const hp_hot_t *p = &h->hot[members[l < m ? l : 0]];
        L.px[l] = p->px; L.py[l] = p->py; L.pz[l] = p->pz;
        L.nx[l] = p->nx; L.ny[l] = p->ny; L.nz[l] = p->nz;
        if (l < m) { c[0] += p->px; c[1] += p->py; c[2] += p->pz; }
    }
    for (int a = 0; a < 3; a++) c[a] /= m;
    for (int l = 0; l < m; l++) {
        double dx = L.px[l] - c[0], dy = L.py[l] - c[1], dz = L.pz[l] - c[2];
        d[l] = sqrt(dx * dx + dy * dy + dz * dz);
        far = fmax(far, d[l]);
    }
    /* Every member's search stops at r0 (the naive search's bound), so both searches find the
     * same neighbours. The scope's radius starts from the thread's guess of the k-th distance
     * (the last cluster's, with a margin) and falls back to r0 + far when a result is not
     * certain: the guess changes the work, never the result. */
    for (int l = 0; l < KNN_LANES; l++) {
        L.b2[l] = l < m ? r0 * r0 : -1;        /* unused lanes accept nothing */
        if (l < m) bound2[l] = L.b2[l];
    }
    st->clusters++;
    double rs = s->guess > 0 && s->guess < r0 ? s->guess : r0;
    int exact;
    if (scope_pass(t, map, &L, c, far, d, m, rs, r0, k, cos_min, s, out, counts, st, &exact)) return -1;
    if (!exact) {
        st->widened++;
        if (scope_pass(t, map, &L, c, far, d, m, r0, r0, k, cos_min, s, out, counts, st, &exact)) return -1;
    }
    double kth = 0;
    for (int l = 0; l < m; l++) kth = counts[l] == k ? fmax(kth, sqrt(out[(size_t)l * k + k - 1].d2)) : r0;
    s->guess = 1.25 * kth;
    return 0;
}

void knn_scratch_free(knn_scratch_t *s)
{
    free(s->scope);
    free(s->d2);
    free(s->cand);
    memset(s, 0, sizeof *s);
}
