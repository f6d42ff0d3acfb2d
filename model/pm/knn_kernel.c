// SPDX-License-Identifier: Apache-2.0
/* knn_kernel.c: the kernel's three paths and their run-time choice (see knn_kernel.h). Every path
 * computes the float prefilter d2 = (dx dx + dy dy) + dz dz and the exact double test with
 * separate multiplies and adds (no fused multiply-add: -ffp-contract=off and the intrinsics
 * below), so the three pass exactly the same photons with the same d2. */
#include <immintrin.h>
#include "cpu_features.h"
#include "knn_kernel.h"

static unsigned long long calls[4];   /* kernel calls by path (knn_kernel_id_t), every thread */

static size_t kernel_scalar(const photon_tree_t *t, const kd_range_t *r, size_t nr, const knn_probe_t *p,
                            knn_hits_t *out, unsigned long long *prefiltered)
{
    size_t c = 0;
    unsigned long long pre = 0;
    __atomic_fetch_add(&calls[KNN_KERNEL_SCALAR], 1, __ATOMIC_RELAXED);
    for (size_t k = 0; k < nr; k++)
        for (size_t i = r[k].lo; i < r[k].hi; i++) {
            const float dx = p->qf[0] - t->fx[i], dy = p->qf[1] - t->fy[i], dz = p->qf[2] - t->fz[i];
            if (!(dx * dx + dy * dy + dz * dz <= p->b2f)) continue;
            pre++;
            const double e = photon_d2(t, i, p->q);
            if (e > p->b2 || !photon_facing(t, i, p->n, p->cos_min)) continue;
            out->pos[c] = (uint32_t)i;
            out->d2[c++] = e;
        }
    *prefiltered += pre;
    return c;
}

/* AVX2: 4 double lanes from position i on, those of mask m (bit j: lane j) passing the float
 * prefilter; appends the ones that pass the exact test. */
__attribute__((target("avx2")))
static inline size_t exact4(const photon_tree_t *t, const knn_probe_t *p, size_t i, unsigned m, knn_hits_t *out,
                            size_t c)
{
    const __m256i live = _mm256_cmpgt_epi64(_mm256_and_si256(_mm256_set1_epi64x(m), _mm256_setr_epi64x(1, 2, 4, 8)),
                                            _mm256_setzero_si256());
    const __m256d dx = _mm256_sub_pd(_mm256_set1_pd(p->q[0]), _mm256_maskload_pd(t->kd.x + i, live));
    const __m256d dy = _mm256_sub_pd(_mm256_set1_pd(p->q[1]), _mm256_maskload_pd(t->kd.y + i, live));
    const __m256d dz = _mm256_sub_pd(_mm256_set1_pd(p->q[2]), _mm256_maskload_pd(t->kd.z + i, live));
    const __m256d e = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
    const __m128i live32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(live, _mm256_setr_epi32(0, 2, 4, 6, 0, 0, 0, 0)));
    const __m256d nx = _mm256_cvtps_pd(_mm_maskload_ps(t->nx + i, live32));
    const __m256d ny = _mm256_cvtps_pd(_mm_maskload_ps(t->ny + i, live32));
    const __m256d nz = _mm256_cvtps_pd(_mm_maskload_ps(t->nz + i, live32));
    const __m256d dot = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(p->n[0]), nx),
                                                    _mm256_mul_pd(_mm256_set1_pd(p->n[1]), ny)),
                                      _mm256_mul_pd(_mm256_set1_pd(p->n[2]), nz));
    const __m256d pass = _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(e, _mm256_set1_pd(p->b2), _CMP_LE_OQ),
                                                     _mm256_cmp_pd(dot, _mm256_set1_pd(p->cos_min), _CMP_GT_OQ)),
                                       _mm256_castsi256_pd(live));
    unsigned k = (unsigned)_mm256_movemask_pd(pass);
    if (!k) return c;
    double v[4];
    _mm256_storeu_pd(v, e);
    for (; k; k &= k - 1) {
        const unsigned j = (unsigned)__builtin_ctz(k);
        out->pos[c] = (uint32_t)(i + j);
        out->d2[c++] = v[j];
    }
    return c;
}

__attribute__((target("avx2")))
static size_t kernel_avx2(const photon_tree_t *t, const kd_range_t *r, size_t nr, const knn_probe_t *p,
                          knn_hits_t *out, unsigned long long *prefiltered)
{
    const __m256 qx = _mm256_set1_ps(p->qf[0]), qy = _mm256_set1_ps(p->qf[1]), qz = _mm256_set1_ps(p->qf[2]);
    const __m256 bound = _mm256_set1_ps(p->b2f);
    const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const float *fx = t->fx, *fy = t->fy, *fz = t->fz;
    size_t c = 0;
    unsigned long long pre = 0;
    __atomic_fetch_add(&calls[KNN_KERNEL_AVX2], 1, __ATOMIC_RELAXED);
    for (size_t k = 0; k < nr; k++)
        for (size_t i = r[k].lo; i < r[k].hi; i += 8) {
            const int left = (int)(r[k].hi - i);
            /* The run's tail: masked loads read nothing past it, and the mask drops those lanes. */
            const __m256i live = _mm256_cmpgt_epi32(_mm256_set1_epi32(left), iota);
            const __m256 dx = _mm256_sub_ps(qx, _mm256_maskload_ps(fx + i, live));
            const __m256 dy = _mm256_sub_ps(qy, _mm256_maskload_ps(fy + i, live));
            const __m256 dz = _mm256_sub_ps(qz, _mm256_maskload_ps(fz + i, live));
            const __m256 e = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)),
                                           _mm256_mul_ps(dz, dz));
            const unsigned m = (unsigned)_mm256_movemask_ps(
                _mm256_and_ps(_mm256_cmp_ps(e, bound, _CMP_LE_OQ), _mm256_castsi256_ps(live)));
            if (!m) continue;   /* none within the bound: nothing more read */
            pre += (unsigned)__builtin_popcount(m);
            if (m & 15) c = exact4(t, p, i, m & 15, out, c);
            if (m >> 4) c = exact4(t, p, i + 4, m >> 4, out, c);
        }
    *prefiltered += pre;
    return c;
}

/* AVX-512: 8 double lanes from position i on, those of mask m passing the float prefilter;
 * appends the ones that pass the exact test, compressed in registers and stored whole (the
 * outputs have 16 entries of slack). */
__attribute__((target("avx512f")))
static inline size_t exact8(const photon_tree_t *t, const knn_probe_t *p, size_t i, __mmask8 m, knn_hits_t *out,
                            size_t c)
{
    const __m512d dx = _mm512_sub_pd(_mm512_set1_pd(p->q[0]), _mm512_maskz_loadu_pd(m, t->kd.x + i));
    const __m512d dy = _mm512_sub_pd(_mm512_set1_pd(p->q[1]), _mm512_maskz_loadu_pd(m, t->kd.y + i));
    const __m512d dz = _mm512_sub_pd(_mm512_set1_pd(p->q[2]), _mm512_maskz_loadu_pd(m, t->kd.z + i));
    const __m512d e = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
    const __mmask8 near = _mm512_mask_cmp_pd_mask(m, e, _mm512_set1_pd(p->b2), _CMP_LE_OQ);
    if (!near) return c;
    const __m512d nx = _mm512_cvtps_pd(_mm512_castps512_ps256(_mm512_maskz_loadu_ps(near, t->nx + i)));
    const __m512d ny = _mm512_cvtps_pd(_mm512_castps512_ps256(_mm512_maskz_loadu_ps(near, t->ny + i)));
    const __m512d nz = _mm512_cvtps_pd(_mm512_castps512_ps256(_mm512_maskz_loadu_ps(near, t->nz + i)));
    const __m512d dot = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(_mm512_set1_pd(p->n[0]), nx),
                                                    _mm512_mul_pd(_mm512_set1_pd(p->n[1]), ny)),
                                      _mm512_mul_pd(_mm512_set1_pd(p->n[2]), nz));
    const __mmask8 k = _mm512_mask_cmp_pd_mask(near, dot, _mm512_set1_pd(p->cos_min), _CMP_GT_OQ);
    const __m512i at = _mm512_add_epi32(_mm512_set1_epi32((int)i),
                                        _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 0, 0, 0, 0, 0, 0, 0, 0));
    _mm512_storeu_pd(out->d2 + c, _mm512_maskz_compress_pd(k, e));
    _mm512_storeu_si512((void *)(out->pos + c), _mm512_maskz_compress_epi32(k, at));
    return c + (size_t)__builtin_popcount(k);
}

__attribute__((target("avx512f")))
static size_t kernel_avx512(const photon_tree_t *t, const kd_range_t *r, size_t nr, const knn_probe_t *p,
                            knn_hits_t *out, unsigned long long *prefiltered)
{
    const __m512 qx = _mm512_set1_ps(p->qf[0]), qy = _mm512_set1_ps(p->qf[1]), qz = _mm512_set1_ps(p->qf[2]);
    const __m512 bound = _mm512_set1_ps(p->b2f);
    const float *fx = t->fx, *fy = t->fy, *fz = t->fz;
    size_t c = 0;
    unsigned long long pre = 0;
    __atomic_fetch_add(&calls[KNN_KERNEL_AVX512], 1, __ATOMIC_RELAXED);
    for (size_t k = 0; k < nr; k++)
        for (size_t i = r[k].lo; i < r[k].hi; i += 16) {
            const size_t left = r[k].hi - i;
            const __mmask16 live = left >= 16 ? (__mmask16)0xffff : (__mmask16)((1u << left) - 1);
            const __m512 dx = _mm512_sub_ps(qx, _mm512_maskz_loadu_ps(live, fx + i));
            const __m512 dy = _mm512_sub_ps(qy, _mm512_maskz_loadu_ps(live, fy + i));
            const __m512 dz = _mm512_sub_ps(qz, _mm512_maskz_loadu_ps(live, fz + i));
            const __m512 e = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)),
                                           _mm512_mul_ps(dz, dz));
            const __mmask16 m = _mm512_mask_cmp_ps_mask(live, e, bound, _CMP_LE_OQ);
            if (!m) continue;   /* none within the bound: nothing more read */
            pre += (unsigned)__builtin_popcount(m);
            if (m & 0xff) c = exact8(t, p, i, (__mmask8)m, out, c);
            if (m >> 8) c = exact8(t, p, i + 8, (__mmask8)(m >> 8), out, c);
        }
    *prefiltered += pre;
    return c;
}

knn_kernel_fn knn_kernel_get(knn_kernel_id_t id, knn_kernel_id_t *taken)
{
    const int has512 = cpu_simd_supported(SIMD_AVX512), has2 = cpu_simd_supported(SIMD_AVX2);
    if (id == KNN_KERNEL_AUTO) id = has512 ? KNN_KERNEL_AVX512 : has2 ? KNN_KERNEL_AVX2 : KNN_KERNEL_SCALAR;
    *taken = id;
    switch (id) {
    case KNN_KERNEL_AVX512: return has512 ? kernel_avx512 : NULL;
    case KNN_KERNEL_AVX2: return has2 ? kernel_avx2 : NULL;
    default: return kernel_scalar;
    }
}

void knn_kernel_calls(unsigned long long out[4])
{
    for (int i = 0; i < 4; i++) out[i] = __atomic_load_n(&calls[i], __ATOMIC_RELAXED);
}

const char *knn_kernel_name(knn_kernel_id_t id)
{
    static const char *const names[] = {"auto", "scalar", "avx2", "avx512"};
    return names[id];
}
