/* sphere_group.c: all spheres of a small group against one ray, scalar or four at a time. */
#include <math.h>
#include <stdlib.h>
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
    g->avx2 = __builtin_cpu_supports("avx2") && !getenv("PREE_NO_AVX2");
#else
    g->avx2 = 0;
#endif
}

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
/* Lane by lane the scalar expression: separate multiplies and adds in the same order, IEEE sqrt,
 * ordered comparisons (false for NaN, as in the scalar test). A pad lane has rr = -inf: det is
 * -inf, a miss. */
__attribute__((target("avx2")))
static void t_all_avx2(const sphere_group_t *g, vec3 o, vec3 d, double eps, double t[SPHERE_GROUP_MAX])
{
    const __m256d ox = _mm256_set1_pd(o.x), oy = _mm256_set1_pd(o.y), oz = _mm256_set1_pd(o.z);
    const __m256d dx = _mm256_set1_pd(d.x), dy = _mm256_set1_pd(d.y), dz = _mm256_set1_pd(d.z);
    const __m256d e = _mm256_set1_pd(eps), zero = _mm256_setzero_pd();
    for (int i = 0; i < g->n; i += 4) {
        __m256d px = _mm256_sub_pd(_mm256_loadu_pd(g->cx + i), ox);
        __m256d py = _mm256_sub_pd(_mm256_loadu_pd(g->cy + i), oy);
        __m256d pz = _mm256_sub_pd(_mm256_loadu_pd(g->cz + i), oz);
        __m256d b = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(px, dx), _mm256_mul_pd(py, dy)), _mm256_mul_pd(pz, dz));
        __m256d pp = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(px, px), _mm256_mul_pd(py, py)), _mm256_mul_pd(pz, pz));
        __m256d det = _mm256_add_pd(_mm256_sub_pd(_mm256_mul_pd(b, b), pp), _mm256_loadu_pd(g->rr + i));
        __m256d miss = _mm256_cmp_pd(det, zero, _CMP_LT_OQ);
        __m256d sq = _mm256_sqrt_pd(det);
        __m256d t1 = _mm256_sub_pd(b, sq), t2 = _mm256_add_pd(b, sq);
        __m256d t2ok = _mm256_and_pd(t2, _mm256_cmp_pd(t2, e, _CMP_GT_OQ));          /* t2 or +0 */
        __m256d r = _mm256_blendv_pd(t2ok, t1, _mm256_cmp_pd(t1, e, _CMP_GT_OQ));    /* t1 if t1 > eps */
        _mm256_storeu_pd(t + i, _mm256_andnot_pd(miss, r));
    }
}
#endif

void sphere_group_t_all(const sphere_group_t *g, vec3 o, vec3 d, double eps, double t[SPHERE_GROUP_MAX])
{
#if defined(__x86_64__) && defined(__GNUC__)
    if (g->avx2) { t_all_avx2(g, o, d, eps, t); return; }
#endif
    for (int i = 0; i < g->n; i++) t[i] = sphere_group_t_scalar(g->cx[i], g->cy[i], g->cz[i], g->rr[i], o, d, eps);
}
