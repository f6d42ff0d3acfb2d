// SPDX-License-Identifier: Apache-2.0
/* sphere_group.c: all spheres of a small group against one ray, scalar or four at a time. */
#include <math.h>
#include "cpu_features.h"
#include "sphere_group.h"

void sphere_group_init(sphere_group_t *g, const sphere_t *spheres, int n)
{
    g->n = n;
    for (int i = 0; i < SPHERE_GROUP_MAX; i++) {
        const int real = i < n;
        g->cx[i] = real ? spheres[i].centre.x : 0;
        g->cy[i] = real ? spheres[i].centre.y : 0;
        g->cz[i] = real ? spheres[i].centre.z : 0;
        g->rr[i] = real ? spheres[i].radius * spheres[i].radius : -INFINITY;
    }
#if defined(__x86_64__) && defined(__GNUC__)
    g->avx2 = cpu_simd_level() >= SIMD_AVX2;
#else
    g->avx2 = 0;
#endif
}

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
/* A ray's coordinates and eps in every lane. */
typedef struct { __m256d ox, oy, oz, dx, dy, dz, e; } ray_lanes_t;

__attribute__((target("avx2")))
static inline ray_lanes_t ray_lanes(vec3 o, vec3 d, double eps)
{
    return (ray_lanes_t){_mm256_set1_pd(o.x), _mm256_set1_pd(o.y), _mm256_set1_pd(o.z),
                         _mm256_set1_pd(d.x), _mm256_set1_pd(d.y), _mm256_set1_pd(d.z), _mm256_set1_pd(eps)};
}

/* t of spheres i .. i+3 (0 for a miss), lane by lane the scalar expression: separate multiplies
 * and adds in the same order, IEEE sqrt, ordered comparisons (false for NaN, as in the scalar
 * test). A pad lane has rr = -inf: det is -inf, a miss. */
__attribute__((target("avx2")))
static inline __m256d t_lanes(const sphere_group_t *g, int i, const ray_lanes_t *r)
{
    const __m256d zero = _mm256_setzero_pd();
    __m256d px = _mm256_sub_pd(_mm256_loadu_pd(g->cx + i), r->ox);
    __m256d py = _mm256_sub_pd(_mm256_loadu_pd(g->cy + i), r->oy);
    __m256d pz = _mm256_sub_pd(_mm256_loadu_pd(g->cz + i), r->oz);
    __m256d b = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(px, r->dx), _mm256_mul_pd(py, r->dy)), _mm256_mul_pd(pz, r->dz));
    __m256d pp = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(px, px), _mm256_mul_pd(py, py)), _mm256_mul_pd(pz, pz));
    __m256d det = _mm256_add_pd(_mm256_sub_pd(_mm256_mul_pd(b, b), pp), _mm256_loadu_pd(g->rr + i));
    __m256d miss = _mm256_cmp_pd(det, zero, _CMP_LT_OQ);
    __m256d sq = _mm256_sqrt_pd(det);
    __m256d t1 = _mm256_sub_pd(b, sq), t2 = _mm256_add_pd(b, sq);
    __m256d t2ok = _mm256_and_pd(t2, _mm256_cmp_pd(t2, r->e, _CMP_GT_OQ));          /* t2 or +0 */
    __m256d t = _mm256_blendv_pd(t2ok, t1, _mm256_cmp_pd(t1, r->e, _CMP_GT_OQ));    /* t1 if t1 > eps */
    return _mm256_andnot_pd(miss, t);
}

__attribute__((target("avx2")))
static void t_all_avx2(const sphere_group_t *g, vec3 o, vec3 d, double eps, double t[SPHERE_GROUP_MAX])
{
    const ray_lanes_t r = ray_lanes(o, d, eps);
    for (int i = 0; i < g->n; i += 4) _mm256_storeu_pd(t + i, t_lanes(g, i, &r));
}

/* The nearest hit against the empty starting state, kept in registers: a miss (t = 0, NaN
 * never arises) reads as +inf, then the first lane holding the minimum. */
__attribute__((target("avx2")))
static int nearest_avx2(const sphere_group_t *g, vec3 o, vec3 d, double eps, double *t_hit)
{
    const ray_lanes_t r = ray_lanes(o, d, eps);
    const __m256d zero = _mm256_setzero_pd(), inf = _mm256_set1_pd(INFINITY);
    __m256d v[SPHERE_GROUP_MAX / 4], m = inf;
    const int nv = (g->n + 3) / 4;
    for (int k = 0; k < nv; k++) {
        const __m256d t = t_lanes(g, 4 * k, &r);
        v[k] = _mm256_blendv_pd(t, inf, _mm256_cmp_pd(t, zero, _CMP_EQ_OQ));
        m = _mm256_min_pd(m, v[k]);
    }
    __m128d m2 = _mm_min_pd(_mm256_castpd256_pd128(m), _mm256_extractf128_pd(m, 1));
    m2 = _mm_min_sd(m2, _mm_unpackhi_pd(m2, m2));
    const double mt = _mm_cvtsd_f64(m2);
    if (!(mt < INFINITY)) return -1;
    const __m256d mb = _mm256_set1_pd(mt);
    for (int k = 0; k < nv; k++) {
        const int hit = _mm256_movemask_pd(_mm256_cmp_pd(v[k], mb, _CMP_EQ_OQ));
        if (hit) { *t_hit = mt; return 4 * k + __builtin_ctz((unsigned)hit); }
    }
    return -1;
}

/* The same choice four lanes at a time: the nearest of the lanes that may replace the hit (the
 * others read as +inf), then the first lane that may and has that t. Comparisons only, so the
 * pick is the scalar loop's, also where t is +inf. Pad lanes hold t = 0 (a miss). */
__attribute__((target("avx2")))
static int pick_avx2(const sphere_group_t *g, const double t[SPHERE_GROUP_MAX], int first, double best_t, int best_id,
                     int triangle_holds, double tfar)
{
    const __m256d zero = _mm256_setzero_pd(), inf = _mm256_set1_pd(INFINITY);
    const __m256d best = _mm256_set1_pd(best_t), limit = _mm256_set1_pd(triangle_holds ? tfar : INFINITY);
    const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3), best_lane = _mm256_set1_epi64x((long long)best_id - first);
    __m256d ok[SPHERE_GROUP_MAX / 4], v[SPHERE_GROUP_MAX / 4];
    __m256d m = inf;
    const int nv = (g->n + 3) / 4;
    for (int k = 0; k < nv; k++) {
        const __m256d tk = _mm256_loadu_pd(t + 4 * k);
        const __m256i id = _mm256_add_epi64(lane, _mm256_set1_epi64x(4 * k));
        const __m256d lower = _mm256_castsi256_pd(_mm256_cmpgt_epi64(best_lane, id));   /* id < best_id */
        __m256d good = _mm256_cmp_pd(tk, zero, _CMP_NEQ_OQ);
        good = _mm256_and_pd(good, _mm256_or_pd(_mm256_cmp_pd(tk, best, _CMP_LT_OQ),
                                                _mm256_and_pd(_mm256_cmp_pd(tk, best, _CMP_EQ_OQ), lower)));
        good = _mm256_andnot_pd(_mm256_cmp_pd(limit, tk, _CMP_LT_OQ), good);   /* not beyond the triangle */
        ok[k] = good;
        v[k] = tk;
        m = _mm256_min_pd(m, _mm256_blendv_pd(inf, tk, good));
    }
    /* The horizontal minimum, then the first good lane holding it. */
    __m128d m2 = _mm_min_pd(_mm256_castpd256_pd128(m), _mm256_extractf128_pd(m, 1));
    m2 = _mm_min_sd(m2, _mm_unpackhi_pd(m2, m2));
    const __m256d mb = _mm256_broadcastsd_pd(m2);
    for (int k = 0; k < nv; k++) {
        const int hit = _mm256_movemask_pd(_mm256_and_pd(ok[k], _mm256_cmp_pd(v[k], mb, _CMP_EQ_OQ)));
        if (hit) return 4 * k + __builtin_ctz((unsigned)hit);
    }
    return -1;
}
#endif

int sphere_group_pick(const sphere_group_t *g, const double t[SPHERE_GROUP_MAX], int first, double best_t, int best_id,
                      int triangle_holds, double tfar)
{
#if defined(__x86_64__) && defined(__GNUC__)
    if (g->avx2) return pick_avx2(g, t, first, best_t, best_id, triangle_holds, tfar);
#endif
    int pick = -1;
    double pick_t = INFINITY;
    for (int i = 0; i < g->n; i++)
        if (sphere_may_replace(t[i], first + i, best_t, best_id, triangle_holds, tfar) && (pick < 0 || t[i] < pick_t)) {
            pick = i;
            pick_t = t[i];
        }
    return pick;
}

void sphere_group_t_all(const sphere_group_t *g, vec3 o, vec3 d, double eps, double t[SPHERE_GROUP_MAX])
{
#if defined(__x86_64__) && defined(__GNUC__)
    if (g->avx2) { t_all_avx2(g, o, d, eps, t); return; }
#endif
    for (int i = 0; i < g->n; i++) t[i] = sphere_group_t_scalar(g->cx[i], g->cy[i], g->cz[i], g->rr[i], o, d, eps);
}

int sphere_group_nearest(const sphere_group_t *g, vec3 o, vec3 d, double eps, double *t_hit)
{
#if defined(__x86_64__) && defined(__GNUC__)
    if (g->avx2) return nearest_avx2(g, o, d, eps, t_hit);
#endif
    double t[SPHERE_GROUP_MAX];
    sphere_group_t_all(g, o, d, eps, t);
    const int i = sphere_group_pick(g, t, 0, INFINITY, -1, 0, INFINITY);
    if (i >= 0) *t_hit = t[i];
    return i;
}
