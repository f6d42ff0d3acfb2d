// SPDX-License-Identifier: Apache-2.0
/* update_prefilter.c: the screening's binary32 prefilter (update_prefilter.h).
 *
 * The bound. Let u = 2^-24 (binary32 round-to-nearest), eta = 2^-150 (half the smallest
 * subnormal), eps = 2^-53, M = max_abs >= |every coordinate| of a hit point q and a photon p,
 * D = |q - p| exactly, and R the safe radius, rs2 = fl64(R * R) the screening's limit.
 * - The exact test skips when v2 > rs2, v2 = fl64(fl64(vx*vx + vy*vy) + vz*vz) with
 *   vx = fl64(qx - px): v2 >= (1 - eps)^5 D^2 - 3 * 2^-1075. So when it does NOT skip,
 *   D <= R' = sqrt((rs2 + 2^-1070) / (1 - eps)^5).
 * - The prefilter rounds q and p to binary32 (|qf - q| <= u M + eta per coordinate, the same for
 *   p), so the binary32 difference before its rounding, a = qf - pf, is within E = 2 (u M + eta)
 *   of q - p per axis and |a| <= D + sqrt(3) E. Then dxf = fl32(ax) <= |ax| (1 + u) (a difference
 *   that underflows is exact), each square fl32(dxf^2) <= dxf^2 (1 + u) + eta, and the two sums
 *   multiply by (1 + u) each (sums are exact when they underflow):
 *   d2f <= (1 + u)^5 |a|^2 + 4 eta <= (1 + u)^5 (D + sqrt(3) E)^2 + 4 eta.
 *   No step overflows while M <= 2^60.
 * - So a candidate the exact test keeps has d2f <= t2 = (1 + u)^5 (R' + sqrt(3) E)^2 + 4 eta,
 *   which is computed in double with every factor enlarged by 2^-40 (far more than the dozen
 *   double roundings) and rounded up to binary32. The prefilter rejects when d2f > t2, an
 *   ordered comparison: a NaN distance (a NaN coordinate) goes to the exact tests.
 * Rejected candidates are counted with skip_candidates_outside_radius, which the exact test would
 * have done: every count and kept candidate is the same as without the prefilter.
 *
 * The kernels gather each lane's binary32 position (three floats at 3 * hit-point index), compute
 * d2f with separate multiplies and adds (the bound covers either order of rounding but the
 * scalar expression's order is kept), and write the kept entries packed, in entry order:
 * AVX-512F with its compress instruction, AVX2 with a permutation looked up by the lane mask.
 * The build lists no prefilter for scalar; the caller then runs the exact tests alone. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "update_prefilter.h"
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAVE_PREFILTER_X86 1
#endif

#define PREFILTER_MAX_ABS 0x1p60

float update_prefilter_bound(double r_safe, double max_abs)
{
    if (!(max_abs <= PREFILTER_MAX_ABS) || !(r_safe >= 0) || !(r_safe <= PREFILTER_MAX_ABS)) return INFINITY;
    const double slack = 1 + 0x1p-40, u = 0x1p-24, eta = 0x1p-150;
    const double rs2 = r_safe * r_safe;
    const double r = sqrt(rs2 + 0x1p-1070) * slack;              /* >= R' */
    const double e = 2 * (u * max_abs + eta) * slack;              /* >= E */
    const double g = (1 + u) * (1 + u) * (1 + u) * (1 + u) * (1 + u) * slack;
    const double s = r + 1.7320508075688774 * e;                   /* sqrt(3) rounded up */
    const double t = g * s * s * slack + 4 * eta;
    float f = (float)t;
    if ((double)f < t) f = nextafterf(f, INFINITY);
    return f;
}

int update_prefilter_build(update_prefilter_t *pf, const hitpoints_t *h, const grid_t *g, simd_level_t level)
{
    memset(pf, 0, sizeof *pf);
#ifdef HAVE_PREFILTER_X86
    if (level == SIMD_SCALAR || g->kind != GRID_CELLS || !h->n || h->n > INT32_MAX / 3) return 0;
    pf->t2 = update_prefilter_bound(g->r_safe, g->max_abs_coord);
    if (!(pf->t2 < INFINITY)) return 0;
    pf->xyz = malloc(3 * h->n * sizeof *pf->xyz);
    if (!pf->xyz) return -1;
    pf->n = h->n;
    pf->max_abs = g->max_abs_coord;
    pf->level = level;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < h->n; i++) {
        pf->xyz[3 * i] = (float)h->hot[i].px;
        pf->xyz[3 * i + 1] = (float)h->hot[i].py;
        pf->xyz[3 * i + 2] = (float)h->hot[i].pz;
    }
#else
    (void)h; (void)g; (void)level;
#endif
    return 0;
}

void update_prefilter_free(update_prefilter_t *pf)
{
    free(pf->xyz);
    memset(pf, 0, sizeof *pf);
}

#ifdef HAVE_PREFILTER_X86
/* AVX-512F: 16 entries a vector; the last vector's lanes beyond count are masked out of the
 * loads, the gathers and the result. */
__attribute__((target("avx512f,popcnt")))
static size_t near_avx512(const update_prefilter_t *pf, const uint32_t *hp, size_t count, const float p[3], uint32_t *out)
{
    const __m512 x = _mm512_set1_ps(p[0]), y = _mm512_set1_ps(p[1]), z = _mm512_set1_ps(p[2]);
    const __m512 t2 = _mm512_set1_ps(pf->t2);
    size_t n = 0;
    for (size_t c = 0; c < count; c += 16) {
        const __mmask16 valid = count - c >= 16 ? (__mmask16)0xFFFF : (__mmask16)((1u << (count - c)) - 1);
        const __m512i idx = _mm512_maskz_loadu_epi32(valid, hp + c);
        const __m512i at = _mm512_add_epi32(idx, _mm512_slli_epi32(idx, 1));   /* 3 * idx < 2^31 */
        const __m512 dx = _mm512_sub_ps(_mm512_mask_i32gather_ps(_mm512_setzero_ps(), valid, at, pf->xyz, 4), x);
        const __m512 dy = _mm512_sub_ps(_mm512_mask_i32gather_ps(_mm512_setzero_ps(), valid, at, pf->xyz + 1, 4), y);
        const __m512 dz = _mm512_sub_ps(_mm512_mask_i32gather_ps(_mm512_setzero_ps(), valid, at, pf->xyz + 2, 4), z);
        const __m512 d2 = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz));
        const __mmask16 keep = _mm512_mask_cmp_ps_mask(valid, d2, t2, _CMP_NGT_UQ);
        _mm512_storeu_si512((void *)(out + n), _mm512_maskz_compress_epi32(keep, idx));
        n += (size_t)__builtin_popcount((unsigned)keep);
    }
    return n;
}

/* Lane mask m -> the indices of its set lanes, lowest first, three bits each. */
static const uint32_t pack_lanes[256] = {
    0x000000, 0x000000, 0x000001, 0x000008, 0x000002, 0x000010, 0x000011, 0x000088,
    0x000003, 0x000018, 0x000019, 0x0000c8, 0x00001a, 0x0000d0, 0x0000d1, 0x000688,
    0x000004, 0x000020, 0x000021, 0x000108, 0x000022, 0x000110, 0x000111, 0x000888,
    0x000023, 0x000118, 0x000119, 0x0008c8, 0x00011a, 0x0008d0, 0x0008d1, 0x004688,
    0x000005, 0x000028, 0x000029, 0x000148, 0x00002a, 0x000150, 0x000151, 0x000a88,
    0x00002b, 0x000158, 0x000159, 0x000ac8, 0x00015a, 0x000ad0, 0x000ad1, 0x005688,
    0x00002c, 0x000160, 0x000161, 0x000b08, 0x000162, 0x000b10, 0x000b11, 0x005888,
    0x000163, 0x000b18, 0x000b19, 0x0058c8, 0x000b1a, 0x0058d0, 0x0058d1, 0x02c688,
    0x000006, 0x000030, 0x000031, 0x000188, 0x000032, 0x000190, 0x000191, 0x000c88,
    0x000033, 0x000198, 0x000199, 0x000cc8, 0x00019a, 0x000cd0, 0x000cd1, 0x006688,
    0x000034, 0x0001a0, 0x0001a1, 0x000d08, 0x0001a2, 0x000d10, 0x000d11, 0x006888,
    0x0001a3, 0x000d18, 0x000d19, 0x0068c8, 0x000d1a, 0x0068d0, 0x0068d1, 0x034688,
    0x000035, 0x0001a8, 0x0001a9, 0x000d48, 0x0001aa, 0x000d50, 0x000d51, 0x006a88,
    0x0001ab, 0x000d58, 0x000d59, 0x006ac8, 0x000d5a, 0x006ad0, 0x006ad1, 0x035688,
    0x0001ac, 0x000d60, 0x000d61, 0x006b08, 0x000d62, 0x006b10, 0x006b11, 0x035888,
    0x000d63, 0x006b18, 0x006b19, 0x0358c8, 0x006b1a, 0x0358d0, 0x0358d1, 0x1ac688,
    0x000007, 0x000038, 0x000039, 0x0001c8, 0x00003a, 0x0001d0, 0x0001d1, 0x000e88,
    0x00003b, 0x0001d8, 0x0001d9, 0x000ec8, 0x0001da, 0x000ed0, 0x000ed1, 0x007688,
    0x00003c, 0x0001e0, 0x0001e1, 0x000f08, 0x0001e2, 0x000f10, 0x000f11, 0x007888,
    0x0001e3, 0x000f18, 0x000f19, 0x0078c8, 0x000f1a, 0x0078d0, 0x0078d1, 0x03c688,
    0x00003d, 0x0001e8, 0x0001e9, 0x000f48, 0x0001ea, 0x000f50, 0x000f51, 0x007a88,
    0x0001eb, 0x000f58, 0x000f59, 0x007ac8, 0x000f5a, 0x007ad0, 0x007ad1, 0x03d688,
    0x0001ec, 0x000f60, 0x000f61, 0x007b08, 0x000f62, 0x007b10, 0x007b11, 0x03d888,
    0x000f63, 0x007b18, 0x007b19, 0x03d8c8, 0x007b1a, 0x03d8d0, 0x03d8d1, 0x1ec688,
    0x00003e, 0x0001f0, 0x0001f1, 0x000f88, 0x0001f2, 0x000f90, 0x000f91, 0x007c88,
    0x0001f3, 0x000f98, 0x000f99, 0x007cc8, 0x000f9a, 0x007cd0, 0x007cd1, 0x03e688,
    0x0001f4, 0x000fa0, 0x000fa1, 0x007d08, 0x000fa2, 0x007d10, 0x007d11, 0x03e888,
    0x000fa3, 0x007d18, 0x007d19, 0x03e8c8, 0x007d1a, 0x03e8d0, 0x03e8d1, 0x1f4688,
    0x0001f5, 0x000fa8, 0x000fa9, 0x007d48, 0x000faa, 0x007d50, 0x007d51, 0x03ea88,
    0x000fab, 0x007d58, 0x007d59, 0x03eac8, 0x007d5a, 0x03ead0, 0x03ead1, 0x1f5688,
    0x000fac, 0x007d60, 0x007d61, 0x03eb08, 0x007d62, 0x03eb10, 0x03eb11, 0x1f5888,
    0x007d63, 0x03eb18, 0x03eb19, 0x1f58c8, 0x03eb1a, 0x1f58d0, 0x1f58d1, 0xfac688,
};

/* AVX2: 8 entries a vector, the same tests; the kept lanes are moved to the front by the
 * permutation pack_lanes gives for their mask, and the whole vector stored. */
__attribute__((target("avx2,popcnt")))
static size_t near_avx2(const update_prefilter_t *pf, const uint32_t *hp, size_t count, const float p[3], uint32_t *out)
{
    const __m256 x = _mm256_set1_ps(p[0]), y = _mm256_set1_ps(p[1]), z = _mm256_set1_ps(p[2]);
    const __m256 t2 = _mm256_set1_ps(pf->t2);
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), shift = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
    size_t n = 0;
    for (size_t c = 0; c < count; c += 8) {
        const __m256i valid = _mm256_cmpgt_epi32(_mm256_set1_epi32(count - c >= 8 ? 8 : (int)(count - c)), lane);
        const __m256 vf = _mm256_castsi256_ps(valid);
        const __m256i idx = _mm256_maskload_epi32((const int *)(const void *)(hp + c), valid);
        const __m256i at = _mm256_add_epi32(idx, _mm256_slli_epi32(idx, 1));
        const __m256 dx = _mm256_sub_ps(_mm256_mask_i32gather_ps(_mm256_setzero_ps(), pf->xyz, at, vf, 4), x);
        const __m256 dy = _mm256_sub_ps(_mm256_mask_i32gather_ps(_mm256_setzero_ps(), pf->xyz + 1, at, vf, 4), y);
        const __m256 dz = _mm256_sub_ps(_mm256_mask_i32gather_ps(_mm256_setzero_ps(), pf->xyz + 2, at, vf, 4), z);
        const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
        const unsigned keep = (unsigned)_mm256_movemask_ps(_mm256_and_ps(vf, _mm256_cmp_ps(d2, t2, _CMP_NGT_UQ)));
        const __m256i perm = _mm256_and_si256(_mm256_srlv_epi32(_mm256_set1_epi32((int)pack_lanes[keep]), shift),
                                              _mm256_set1_epi32(7));
        _mm256_storeu_si256((__m256i *)(void *)(out + n), _mm256_permutevar8x32_epi32(idx, perm));
        n += (size_t)__builtin_popcount(keep);
    }
    return n;
}
#endif

size_t update_prefilter_near(const update_prefilter_t *pf, const uint32_t *hp, size_t count, double x, double y,
                             double z, uint32_t *out)
{
#ifdef HAVE_PREFILTER_X86
    const float p[3] = {(float)x, (float)y, (float)z};
    return pf->level == SIMD_AVX512 ? near_avx512(pf, hp, count, p, out) : near_avx2(pf, hp, count, p, out);
#else
    (void)pf; (void)x; (void)y; (void)z;
    memcpy(out, hp, count * sizeof *hp);
    return count;
#endif
}
