// SPDX-License-Identifier: Apache-2.0
/* knn_kernel.c: the prefilter kernel's three paths and their run-time choice (see knn_kernel.h).
 * Every path computes d2 = (dx dx + dy dy) + dz dz and dot = (nx nx' + ny ny') + nz nz' with
 * separate multiplies and adds (no fused multiply-add: -ffp-contract=off and the intrinsics
 * below), so the three pass exactly the same photons. */
#include <immintrin.h>
#include "cpu_features.h"
#include "knn_kernel.h"

static unsigned long long calls[4];   /* kernel calls by path (knn_kernel_id_t), every thread */

static inline int passes(const photon_tree_t *t, size_t i, const float q[3], const float n[3], float b2,
                         float cos_lo)
{
    const float dx = q[0] - t->fx[i], dy = q[1] - t->fy[i], dz = q[2] - t->fz[i];
    const float d2 = dx * dx + dy * dy + dz * dz;
    const float dot = n[0] * t->nx[i] + n[1] * t->ny[i] + n[2] * t->nz[i];
    return d2 <= b2 && dot > cos_lo;
}

static size_t kernel_scalar(const photon_tree_t *t, const kd_range_t *r, size_t nr, const float q[3],
                            const float n[3], float b2, float cos_lo, uint32_t *out)
{
    size_t c = 0;
    __atomic_fetch_add(&calls[KNN_KERNEL_SCALAR], 1, __ATOMIC_RELAXED);
    for (size_t k = 0; k < nr; k++)
        for (size_t i = r[k].lo; i < r[k].hi; i++)
            if (passes(t, i, q, n, b2, cos_lo)) out[c++] = (uint32_t)i;
    return c;
}

__attribute__((target("avx2")))
static size_t kernel_avx2(const photon_tree_t *t, const kd_range_t *r, size_t nr, const float q[3],
                          const float n[3], float b2, float cos_lo, uint32_t *out)
{
    const __m256 qx = _mm256_set1_ps(q[0]), qy = _mm256_set1_ps(q[1]), qz = _mm256_set1_ps(q[2]);
    const __m256 nx = _mm256_set1_ps(n[0]), ny = _mm256_set1_ps(n[1]), nz = _mm256_set1_ps(n[2]);
    const __m256 bound = _mm256_set1_ps(b2), cosv = _mm256_set1_ps(cos_lo);
    const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    size_t c = 0;
    __atomic_fetch_add(&calls[KNN_KERNEL_AVX2], 1, __ATOMIC_RELAXED);
    for (size_t k = 0; k < nr; k++)
        for (size_t i = r[k].lo; i < r[k].hi; i += 8) {
            const int left = (int)(r[k].hi - i);
            /* The run's tail: masked loads read nothing past it, and the mask drops those lanes. */
            const __m256i live = _mm256_cmpgt_epi32(_mm256_set1_epi32(left), iota);
            const __m256 dx = _mm256_sub_ps(qx, _mm256_maskload_ps(t->fx + i, live));
            const __m256 dy = _mm256_sub_ps(qy, _mm256_maskload_ps(t->fy + i, live));
            const __m256 dz = _mm256_sub_ps(qz, _mm256_maskload_ps(t->fz + i, live));
            const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)),
                                            _mm256_mul_ps(dz, dz));
            const __m256 near = _mm256_and_ps(_mm256_cmp_ps(d2, bound, _CMP_LE_OQ), _mm256_castsi256_ps(live));
            if (_mm256_testz_ps(near, near)) continue;   /* none within the bound: no normals read */
            const __m256 dot = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(nx, _mm256_maskload_ps(t->nx + i, live)),
                                                           _mm256_mul_ps(ny, _mm256_maskload_ps(t->ny + i, live))),
                                             _mm256_mul_ps(nz, _mm256_maskload_ps(t->nz + i, live)));
            unsigned m = (unsigned)_mm256_movemask_ps(_mm256_and_ps(near, _mm256_cmp_ps(dot, cosv, _CMP_GT_OQ)));
            for (; m; m &= m - 1) out[c++] = (uint32_t)(i + (size_t)__builtin_ctz(m));
        }
    return c;
}

__attribute__((target("avx512f")))
static size_t kernel_avx512(const photon_tree_t *t, const kd_range_t *r, size_t nr, const float q[3],
                            const float n[3], float b2, float cos_lo, uint32_t *out)
{
    const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
    const __m512 nx = _mm512_set1_ps(n[0]), ny = _mm512_set1_ps(n[1]), nz = _mm512_set1_ps(n[2]);
    const __m512 bound = _mm512_set1_ps(b2), cosv = _mm512_set1_ps(cos_lo);
    const __m512i iota = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    size_t c = 0;
    __atomic_fetch_add(&calls[KNN_KERNEL_AVX512], 1, __ATOMIC_RELAXED);
    for (size_t k = 0; k < nr; k++)
        for (size_t i = r[k].lo; i < r[k].hi; i += 16) {
            const size_t left = r[k].hi - i;
            const __mmask16 live = left >= 16 ? (__mmask16)0xffff : (__mmask16)((1u << left) - 1);
            const __m512 dx = _mm512_sub_ps(qx, _mm512_maskz_loadu_ps(live, t->fx + i));
            const __m512 dy = _mm512_sub_ps(qy, _mm512_maskz_loadu_ps(live, t->fy + i));
            const __m512 dz = _mm512_sub_ps(qz, _mm512_maskz_loadu_ps(live, t->fz + i));
            const __m512 d2 = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)),
                                            _mm512_mul_ps(dz, dz));
            const __mmask16 near = _mm512_mask_cmp_ps_mask(live, d2, bound, _CMP_LE_OQ);
            if (!near) continue;   /* none within the bound: no normals read */
            const __m512 dot = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(nx, _mm512_maskz_loadu_ps(near, t->nx + i)),
                                                           _mm512_mul_ps(ny, _mm512_maskz_loadu_ps(near, t->ny + i))),
                                             _mm512_mul_ps(nz, _mm512_maskz_loadu_ps(near, t->nz + i)));
            const __mmask16 m = _mm512_mask_cmp_ps_mask(near, dot, cosv, _CMP_GT_OQ);
            /* Compressed in a register and stored whole (the output has 16 entries of slack). */
            const __m512i pos = _mm512_add_epi32(_mm512_set1_epi32((int)i), iota);
            _mm512_storeu_si512((void *)(out + c), _mm512_maskz_compress_epi32(m, pos));
            c += (size_t)__builtin_popcount(m);
        }
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
