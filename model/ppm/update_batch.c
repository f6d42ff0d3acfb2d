// SPDX-License-Identifier: Apache-2.0
/* update_batch.c: the photon pass's update of a whole block of photon hits in two phases.
 *
 * Phase 1 (screen) groups the block's hits by grid bucket and tests every candidate of a
 * bucket against all of its hits while the bucket's entries and radii sit in cache. It changes
 * nothing: it counts the candidates and normal tests exactly as the photon-major scan does, and
 * keeps the candidates whose distance passes against the radius at the start of the block. As
 * radii only shrink (double: r2 * g with g < 1; binary32: the rounded product is <= r2), every
 * candidate that the photon-major scan would accept is kept.
 * Phase 2 (apply) replays the kept candidates in photon order against the current radius, with
 * the same distance value the photon-major scan computes, so every hit point receives the same
 * updates in the same order: the result is identical to the bit (tests/checks/engine_scan_order.sh). */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>
#include "cpu_features.h"
#include "grow.h"
#include "update_batch.h"
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAVE_SCREEN_AVX2 1
#endif

#define RADIX_BITS 11
#define APPLY_AHEAD 8   /* kept candidates prefetched ahead in the apply phase */
#define RADIX_SIZE (1u << RADIX_BITS)
#define RADIX_PARALLEL_MIN 32768   /* keys below which a radix pass runs on one thread */
#define SCREEN_PREFETCH_GROUPS 2   /* buckets prefetched ahead in the screening */
#define SCREEN_PREFETCH_MAX 64     /* entries of a bucket prefetched at most */
#define SCREEN_STAGE_MAX 65536     /* entries a group's prefiltered lists hold at most, all hits together */
/* The AVX2 screening gathers a hit point's position and normal (hp_hot_t's first six doubles) at
 * the 32-bit signed double index hp * HOT_DOUBLES: up to HOT_GATHER_MAX hit points. */
#define HOT_DOUBLES (sizeof(hp_hot_t) / sizeof(double))
#define HOT_GATHER_MAX ((size_t)INT32_MAX / HOT_DOUBLES)
_Static_assert(sizeof(hp_hot_t) % sizeof(double) == 0 && offsetof(hp_hot_t, px) == 0 &&
               offsetof(hp_hot_t, nz) == 5 * sizeof(double), "hp_hot_t: the position and normal lead, in doubles");

void update_batch_free(update_batch_t *b)
{
    free(b->hit);
    free(b->key);
    free(b->tmp);
    free(b->sorted);
    free(b->group);
    free(b->hist);
    memset(b, 0, sizeof *b);
}

/* One stable counting pass of the radix sort, key -> tmp, on the digit at shift: each thread
 * counts a contiguous range of keys, and scatters it after the lower digits' and the earlier
 * ranges' keys, so the order is the serial one whatever the thread count. 0 or -1 (memory). */
static int radix_pass(update_batch_t *b, size_t m, unsigned shift)
{
    const int nt = m >= RADIX_PARALLEL_MIN ? omp_get_max_threads() : 1;
    if (grow_array((void **)&b->hist, &b->hist_cap, (size_t)nt * RADIX_SIZE, sizeof *b->hist)) return -1;
    uint32_t *hist = b->hist;
    const uint64_t *src = b->key;
    uint64_t *dst = b->tmp;
#pragma omp parallel num_threads(nt)
    {
        const int t = omp_get_thread_num(), T = omp_get_num_threads();
        const size_t lo = m * (size_t)t / (size_t)T, hi = m * (size_t)(t + 1) / (size_t)T;
        uint32_t *h = hist + (size_t)t * RADIX_SIZE;
        memset(h, 0, RADIX_SIZE * sizeof *h);
        for (size_t i = lo; i < hi; i++) h[(src[i] >> shift) & (RADIX_SIZE - 1)]++;
#pragma omp barrier
#pragma omp single
        {
            uint32_t sum = 0;
            for (unsigned d = 0; d < RADIX_SIZE; d++)
                for (int u = 0; u < T; u++) {
                    uint32_t c = hist[(size_t)u * RADIX_SIZE + d];
                    hist[(size_t)u * RADIX_SIZE + d] = sum;
                    sum += c;
                }
        }
        for (size_t i = lo; i < hi; i++) dst[h[(src[i] >> shift) & (RADIX_SIZE - 1)]++] = src[i];
    }
    return 0;
}

int update_batch_prepare(update_batch_t *b, const photon_hits_t *chunks, unsigned nchunks, size_t num_buckets)
{
    size_t n = 0;
    for (unsigned c = 0; c < nchunks; c++) n += chunks[c].n;
    if (grow_array((void **)&b->hit, &b->hit_cap, n, sizeof *b->hit) ||
        grow_array((void **)&b->key, &b->key_cap, n, sizeof *b->key) ||
        grow_array((void **)&b->tmp, &b->tmp_cap, n, sizeof *b->tmp))
        return -1;
    /* Keys: bucket in the high half, hit index (photon order) in the low half; chunk c's hits
     * start at hit index first[c] and its keys at key index kfirst[c]. */
    size_t first[UPDATE_BATCH_MAX_CHUNKS + 1], kfirst[UPDATE_BATCH_MAX_CHUNKS + 1];
    if (nchunks > UPDATE_BATCH_MAX_CHUNKS) return -1;
    first[0] = kfirst[0] = 0;
#pragma omp parallel for schedule(dynamic, 1)
    for (unsigned c = 0; c < nchunks; c++) {
        size_t keyed = 0;
        for (size_t i = 0; i < chunks[c].n; i++) keyed += chunks[c].hits[i].bucket != GRID_NO_BUCKET;
        kfirst[c + 1] = keyed;
    }
    for (unsigned c = 0; c < nchunks; c++) {
        first[c + 1] = first[c] + chunks[c].n;
        kfirst[c + 1] += kfirst[c];
    }
#pragma omp parallel for schedule(dynamic, 1)
    for (unsigned c = 0; c < nchunks; c++) {
        size_t k = first[c], m = kfirst[c];
        for (size_t i = 0; i < chunks[c].n; i++, k++) {
            const photon_hit_t *ph = &chunks[c].hits[i];
            b->hit[k] = ph;
            if (ph->bucket != GRID_NO_BUCKET) b->key[m++] = (uint64_t)ph->bucket << 32 | k;
        }
    }
    const size_t m = kfirst[nchunks];
    b->n = n;
    b->n_keyed = m;
    /* Stable LSD radix sort on the bucket bits only. */
    unsigned bits = 0;
    while (bits < 32 && ((size_t)1 << bits) < num_buckets) bits++;
    for (unsigned shift = 32; shift < 32 + bits; shift += RADIX_BITS) {
        if (radix_pass(b, m, shift)) return -1;
        uint64_t *t = b->key; b->key = b->tmp; b->tmp = t;
        size_t tc = b->key_cap; b->key_cap = b->tmp_cap; b->tmp_cap = tc;
    }
    /* Groups: runs of one bucket. */
    if (grow_array((void **)&b->group, &b->group_cap, m + 1, sizeof *b->group)) return -1;
    size_t ng = 0;
    for (size_t i = 0; i < m; i++)
        if (i == 0 || (b->key[i] >> 32) != (b->key[i - 1] >> 32)) b->group[ng++] = (uint32_t)i;
    b->group[ng] = (uint32_t)m;
    b->n_groups = ng;
#ifdef HAVE_SCREEN_AVX2
    b->avx2 = cpu_simd_level() >= SIMD_AVX2;
#endif
    /* Gather the hits in key order: independent loads, which the processor overlaps. */
    if (grow_array((void **)&b->sorted, &b->sorted_cap, m, sizeof *b->sorted)) return -1;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < m; i++) {
        const uint32_t hit = (uint32_t)b->key[i];
        const photon_hit_t *ph = b->hit[hit];
        b->sorted[i] = (batch_hit_t){ph->x.x, ph->x.y, ph->x.z, ph->n.x, ph->n.y, ph->n.z, hit, (uint32_t)(b->key[i] >> 32)};
    }
    return 0;
}

/* A kept candidate: hit index in the block, hit-point index, and its distance squared
 * (double mode) or binary32 distance squared (fp32 mode). */
typedef struct { uint32_t hit, hp; double v2; } kept_t;

size_t update_batch_kept_bytes(void)
{
    return 2 * sizeof(kept_t);
}

size_t update_batch_kept(const update_scratch_t *all, int nthreads)
{
    size_t n = 0;
    for (int t = 0; t < nthreads; t++)
        for (int p = 0; p < all[t].num_lists; p++) n += all[t].list[p].n;
    return n;
}

void update_batch_scratch_free(update_scratch_t *s)
{
    for (int p = 0; p < s->num_lists; p++) free(s->list[p].v);
    free(s->list);
    free(s->sorted);
    free(s->start);
    for (int k = 0; k < 2; k++) {
        free(s->stage[k].hp);
        free(s->stage[k].at);
    }
    memset(s, 0, sizeof *s);
}

int update_batch_scratch_reset(update_scratch_t *s, int num_parts)
{
    if (s->num_lists != num_parts) {
        for (int p = 0; p < s->num_lists; p++) free(s->list[p].v);
        free(s->list);
        s->list = calloc((size_t)num_parts, sizeof *s->list);
        s->num_lists = s->list ? num_parts : 0;
        if (!s->list) return -1;
    }
    for (int p = 0; p < num_parts; p++) s->list[p].n = 0;
    return 0;
}

int update_batch_keep_in(update_scratch_t *s, int q, uint32_t hit, uint32_t hp, double v2)
{
    kept_list_t *l = &s->list[q];
    if (l->n == l->cap && grow_array(&l->v, &l->cap, l->n + 1, sizeof(kept_t))) return -1;
    ((kept_t *)l->v)[l->n++] = (kept_t){hit, hp, v2};
    return 0;
}

/* The part that owns hit point hp: from the ranges (comparisons, no branch on the owner, which
 * alternates within a bucket), else from owner[]. */
static inline int owner_of(const update_batch_t *b, uint32_t hp)
{
    if (b->owner_end) {
        int q = 0;
        for (int p = 0; p + 1 < b->parts; p++) q += hp >= b->owner_end[p];
        return q;
    }
    return b->owner ? b->owner[hp] : 0;
}

/* Keep a candidate in the list of the part that owns its hit point. */
static int keep(update_scratch_t *s, const update_batch_t *b, uint32_t hit, uint32_t hp, double v2)
{
    return update_batch_keep_in(s, owner_of(b, hp), hit, hp, v2);
}

/* Phase 1 for one hit against its bucket's entries (double mode). */
static int screen_double(const hitpoints_t *h, double rs2, int skip_radius, const batch_hit_t *ph,
                         const grid_cands_t *e, update_stats_t *st, update_scratch_t *s, const update_batch_t *b)
{
    const double x = ph->x, y = ph->y, z = ph->z;
    const double nx = ph->nx, ny = ph->ny, nz = ph->nz;
    for (size_t c = 0; c < e->count; c++) {
        const hp_hot_t *q = &e->hot[e->hp[c]];
        double vx = q->px - x, vy = q->py - y, vz = q->pz - z;
        double v2 = vx * vx + vy * vy + vz * vz;
        if (skip_radius && v2 > rs2) { st->skipped_radius++; continue; }
        if (!(q->nx * nx + q->ny * ny + q->nz * nz > UPDATE_NORMAL_COS)) continue;
        st->normal_passed++;
        if (v2 <= h->r2[e->hp[c]] && keep(s, b, ph->hit, e->hp[c], v2)) return -1;
    }
    return 0;
}

#ifdef HAVE_SCREEN_AVX2
/* All-ones in the first min(rem, 4) lanes. The last vector of a bucket reads up to three entries
 * beyond it (the next bucket's, or the grid's padding: grid.c allocates GRID_ENTRY_PAD more);
 * their lanes are masked out of every count, gather and kept candidate. */
__attribute__((target("avx2")))
static inline __m256d valid_lanes(size_t rem)
{
    static const int64_t ones[8] = {-1, -1, -1, -1, 0, 0, 0, 0};
    return _mm256_loadu_pd((const double *)(const void *)(ones + 4 - (rem < 4 ? rem : 4)));
}

/* The same tests four entries at a time, in either precision. The host's double tests are
 * shared: every lane computes the scalar expressions with the same operations in the same order
 * (separate IEEE multiplies and adds, no fused ones), and the ordered comparisons are false for
 * NaN exactly like the scalar ones. Then the distance that decides: double v2 against r2, or the
 * PREU's binary32 distance (RNE conversions of the double coordinates, float multiplies and adds
 * in the scalar order) against the binary32 radius. Kept candidates come out in entry order. */
__attribute__((target("avx2,popcnt")))
static int screen_avx2(const hitpoints_t *h, double rs2, int skip_radius, const batch_hit_t *ph, int fp32,
                       const grid_cands_t *e, update_stats_t *st, update_scratch_t *s, const update_batch_t *b)
{
    const __m256d x = _mm256_set1_pd(ph->x), y = _mm256_set1_pd(ph->y), z = _mm256_set1_pd(ph->z);
    const __m256d nx = _mm256_set1_pd(ph->nx), ny = _mm256_set1_pd(ph->ny), nz = _mm256_set1_pd(ph->nz);
    const __m128 fx = _mm_set1_ps(fp32 ? fp32_from_bits(preu_f32(ph->x)) : 0.0f),
                 fy = _mm_set1_ps(fp32 ? fp32_from_bits(preu_f32(ph->y)) : 0.0f),
                 fz = _mm_set1_ps(fp32 ? fp32_from_bits(preu_f32(ph->z)) : 0.0f);
    const __m256d far_lim = _mm256_set1_pd(skip_radius ? rs2 : INFINITY);
    const __m256d cosl = _mm256_set1_pd(UPDATE_NORMAL_COS);
    const float *r2f = (const float *)(const void *)h->r2_f32;
    unsigned long long skipped = 0, passed = 0;
    const double *hot = (const double *)(const void *)e->hot;   /* HOT_DOUBLES doubles per hit point */
    const __m128i stride = _mm_set1_epi32((int)HOT_DOUBLES);
    for (size_t c = 0; c < e->count; c += 4) {
        const __m256d valid = valid_lanes(e->count - c);
        const __m128i idx = _mm_loadu_si128((const __m128i *)(e->hp + c));
        const __m128i at = _mm_mullo_epi32(idx, stride);   /* < 2^31: h->n <= HOT_GATHER_MAX */
#define HOT_LOAD(field) _mm256_mask_i32gather_pd(_mm256_setzero_pd(), hot + offsetof(hp_hot_t, field) / sizeof(double), at, valid, 8)
        const __m256d px = HOT_LOAD(px), py = HOT_LOAD(py), pz = HOT_LOAD(pz);
        __m256d vx = _mm256_sub_pd(px, x), vy = _mm256_sub_pd(py, y), vz = _mm256_sub_pd(pz, z);
        __m256d v2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(vx, vx), _mm256_mul_pd(vy, vy)), _mm256_mul_pd(vz, vz));
        __m256d dot = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(HOT_LOAD(nx), nx), _mm256_mul_pd(HOT_LOAD(ny), ny)),
                                    _mm256_mul_pd(HOT_LOAD(nz), nz));
#undef HOT_LOAD
        __m256d far = _mm256_and_pd(valid, _mm256_cmp_pd(v2, far_lim, _CMP_GT_OQ));
        __m256d pass = _mm256_and_pd(valid, _mm256_andnot_pd(far, _mm256_cmp_pd(dot, cosl, _CMP_GT_OQ)));
        const int mf = _mm256_movemask_pd(far), mp = _mm256_movemask_pd(pass);
        skipped += (unsigned)__builtin_popcount((unsigned)mf);
        passed += (unsigned)__builtin_popcount((unsigned)mp);
        if (!mp) continue;
        double dist[4];
        int ma;
        if (!fp32) {
            __m256d r2 = _mm256_mask_i32gather_pd(_mm256_setzero_pd(), h->r2, idx, pass, 8);
            ma = _mm256_movemask_pd(_mm256_and_pd(pass, _mm256_cmp_pd(v2, r2, _CMP_LE_OQ)));
            _mm256_storeu_pd(dist, v2);
        } else {
            __m128 dx = _mm_sub_ps(_mm256_cvtpd_ps(px), fx), dy = _mm_sub_ps(_mm256_cvtpd_ps(py), fy),
                   dz = _mm_sub_ps(_mm256_cvtpd_ps(pz), fz);
            __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
            __m128 pass4 = _mm_castsi128_ps(_mm256_cvtpd_epi32(_mm256_and_pd(pass, _mm256_set1_pd(-1.0))));
            __m128 r2 = _mm_mask_i32gather_ps(_mm_setzero_ps(), r2f, idx, pass4, 4);
            ma = mp & _mm_movemask_ps(_mm_cmp_ps(d2, r2, _CMP_LE_OQ));
            _mm256_storeu_pd(dist, _mm256_cvtps_pd(d2));   /* exact: binary32 values widened */
        }
        for (; ma; ma &= ma - 1) {
            const int l = __builtin_ctz((unsigned)ma);
            if (keep(s, b, ph->hit, e->hp[c + l], dist[l])) return -1;
        }
    }
    st->skipped_radius += skipped;
    st->normal_passed += passed;
    return 0;
}
#endif

/* Phase 1 for one hit (fp32 mode): the host's tests in double, the PREU's distance in binary32
 * (the same expressions as update.c's photon-major scan). */
static int screen_fp32(const hitpoints_t *h, double rs2, int skip_radius, const batch_hit_t *ph,
                       const grid_cands_t *e, update_stats_t *st, update_scratch_t *s, const update_batch_t *b)
{
    const float fx = fp32_from_bits(preu_f32(ph->x)), fy = fp32_from_bits(preu_f32(ph->y)), fz = fp32_from_bits(preu_f32(ph->z));
    const double nx = ph->nx, ny = ph->ny, nz = ph->nz;
    for (size_t c = 0; c < e->count; c++) {
        const hp_hot_t *q = &e->hot[e->hp[c]];
        if (skip_radius) {
            double vx = q->px - ph->x, vy = q->py - ph->y, vz = q->pz - ph->z;
            if (vx * vx + vy * vy + vz * vz > rs2) { st->skipped_radius++; continue; }
        }
        if (!(q->nx * nx + q->ny * ny + q->nz * nz > UPDATE_NORMAL_COS)) continue;
        st->normal_passed++;
        float dx = (float)q->px - fx, dy = (float)q->py - fy, dz = (float)q->pz - fz;
        float d2 = (dx * dx + dy * dy) + dz * dz;
        if (d2 <= fp32_from_bits(h->r2_f32[e->hp[c]]) && keep(s, b, ph->hit, e->hp[c], d2)) return -1;
    }
    return 0;
}

/* Group part p's kept candidates of every screening thread by hit (counting sort). A hit's
 * candidates all come from one thread (one bucket, screened whole), in entry order. */
int update_batch_gather(update_scratch_t *out, update_scratch_t *all, int nthreads, int p, size_t n_hits)
{
    size_t total = 0;
    for (int t = 0; t < nthreads; t++) total += all[t].list[p].n;
    if (grow_array(&out->sorted, &out->sorted_cap, total, sizeof(kept_t)) ||
        grow_array((void **)&out->start, &out->start_cap, n_hits + 1, sizeof *out->start))
        return -1;
    kept_t *dst = out->sorted;
    uint32_t *start = out->start;
    memset(start, 0, (n_hits + 1) * sizeof *start);
    for (int t = 0; t < nthreads; t++) {
        const kept_t *k = all[t].list[p].v;
        for (size_t i = 0; i < all[t].list[p].n; i++) start[k[i].hit + 1]++;
    }
    for (size_t i = 0; i < n_hits; i++) start[i + 1] += start[i];
    for (int t = 0; t < nthreads; t++) {
        const kept_t *k = all[t].list[p].v;
        for (size_t i = 0; i < all[t].list[p].n; i++) dst[start[k[i].hit]++] = k[i];
    }
    out->n_sorted = total;
    return 0;
}

void update_batch_sorted_at(const update_scratch_t *s, size_t i, uint32_t *hit, uint32_t *hp, double *v2)
{
    const kept_t *k = (const kept_t *)s->sorted + i;
    *hit = k->hit;
    *hp = k->hp;
    *v2 = k->v2;
}

/* Phase 1 for one hit against candidates e: in AVX2 lanes where chosen, else scalar. */
static int screen_one(const hitpoints_t *h, double rs2, int skip_radius, precision_t prec, const batch_hit_t *ph,
                      const grid_cands_t *e, update_stats_t *st, update_scratch_t *s, const update_batch_t *b)
{
#ifdef HAVE_SCREEN_AVX2
    if (b->avx2 && h->n <= HOT_GATHER_MAX) return screen_avx2(h, rs2, skip_radius, ph, prec != PRECISION_DOUBLE, e, st, s, b);
#endif
    if (prec != PRECISION_DOUBLE) return screen_fp32(h, rs2, skip_radius, ph, e, st, s, b);
    return screen_double(h, rs2, skip_radius, ph, e, st, s, b);
}

/* Ask for the first lines of a bucket's entries: buckets are screened in memory order but
 * far apart, too short for the hardware prefetcher to follow. */
static void prefetch_cands(const grid_cands_t *c)
{
    const size_t n = c->count < SCREEN_PREFETCH_MAX ? c->count : SCREEN_PREFETCH_MAX;
    for (size_t k = 0; k < n; k += 16) __builtin_prefetch(c->hp + k);
}

/* The entries of cand that the prefilter keeps for hit ph, into out (cand.count +
 * PREFILTER_OUT_PAD entries); every entry for a photon beyond the bound's coordinates. */
static size_t prefilter_hit(const update_prefilter_t *pf, const grid_cands_t *cand, const batch_hit_t *ph, uint32_t *out)
{
    if (update_prefilter_covers(pf, ph->x, ph->y, ph->z))
        return update_prefilter_near(pf, cand->hp, cand->count, ph->x, ph->y, ph->z, out);
    memcpy(out, cand->hp, cand->count * sizeof *out);
    return cand->count;
}

/* Prefilter group `group`'s hits against their bucket into st, and ask for the hit points and
 * radii of the entries kept, which its exact tests will read; a group of more than
 * SCREEN_STAGE_MAX entries and hits together is left to be prefiltered hit by hit (st->direct).
 * 0 or -1 (memory). */
static int prefilter_group(const update_prefilter_t *pf, const grid_t *g, const update_batch_t *b, size_t group,
                           const char *radii, size_t radius_size, screen_stage_t *st)
{
    const batch_hit_t *sh = b->sorted;
    const size_t i = b->group[group], end = b->group[group + 1];
    const grid_cands_t cand = grid_bucket_cands(g, 0, sh[i].bucket);
    st->count = cand.count;
    st->direct = cand.count * (end - i) > SCREEN_STAGE_MAX;
    const size_t cap = st->direct ? cand.count : cand.count * (end - i);
    if (grow_array((void **)&st->hp, &st->hp_cap, cap + PREFILTER_OUT_PAD + GRID_ENTRY_PAD, sizeof *st->hp) ||
        grow_array((void **)&st->at, &st->at_cap, end - i + 1, sizeof *st->at))
        return -1;
    if (st->direct) return 0;
    size_t n = 0;
    st->at[0] = 0;
    for (size_t j = i; j < end; j++) {
        uint32_t *out = st->hp + n;
        const size_t k = prefilter_hit(pf, &cand, &sh[j], out);
        for (size_t c = 0; c < k; c++) {
            __builtin_prefetch(&cand.hot[out[c]]);
            __builtin_prefetch(radii + radius_size * out[c]);
        }
        n += k;
        st->at[j - i + 1] = (uint32_t)n;
    }
    memset(st->hp + n, 0, GRID_ENTRY_PAD * sizeof *st->hp);   /* the four-wide loads' padding */
    return 0;
}

/* update_batch_screen with the prefilter, as a pipeline over the groups: group + 3's entries and
 * group + 2's binary32 positions are asked for, group + 1 is prefiltered (asking for the hit
 * points its lists keep), and group's lists get the exact tests. An entry the prefilter drops is
 * counted as skipped beyond the safe radius, which is what the exact test would have found. */
static int screen_prefiltered(const hitpoints_t *h, const grid_t *g, precision_t prec, const update_prefilter_t *pf,
                              const update_batch_t *b, size_t first, size_t last, update_stats_t *t, update_scratch_t *s)
{
    const double rs2 = g->r_safe * g->r_safe;
    const batch_hit_t *sh = b->sorted;
    const char *radii = prec == PRECISION_DOUBLE ? (const char *)h->r2 : (const char *)h->r2_f32;
    const size_t radius_size = prec == PRECISION_DOUBLE ? sizeof *h->r2 : sizeof *h->r2_f32;
    if (last > b->n_groups) last = b->n_groups;
    if (first >= last) return 0;
    if (prefilter_group(pf, g, b, first, radii, radius_size, &s->stage[first & 1])) return -1;
    for (size_t group = first; group < last; group++) {
        if (group + 3 < b->n_groups) {
            const grid_cands_t far = grid_bucket_cands(g, 0, sh[b->group[group + 3]].bucket);
            prefetch_cands(&far);
        }
        if (group + 2 < b->n_groups) {
            const grid_cands_t next = grid_bucket_cands(g, 0, sh[b->group[group + 2]].bucket);
            const size_t n = next.count < SCREEN_PREFETCH_MAX ? next.count : SCREEN_PREFETCH_MAX;
            for (size_t k = 0; k < n; k++) update_prefilter_prefetch(pf, next.hp[k]);
        }
        if (group + 1 < last && prefilter_group(pf, g, b, group + 1, radii, radius_size, &s->stage[(group + 1) & 1]))
            return -1;
        screen_stage_t *st = &s->stage[group & 1];
        const size_t i = b->group[group], end = b->group[group + 1];
        const grid_cands_t cand = grid_bucket_cands(g, 0, sh[i].bucket);
        t->candidates += cand.count * (end - i);
        for (size_t j = i; j < end; j++) {
            grid_cands_t near = {g->hot, st->hp, 0};
            if (st->direct) {
                near.count = prefilter_hit(pf, &cand, &sh[j], st->hp);
                memset(st->hp + near.count, 0, GRID_ENTRY_PAD * sizeof *st->hp);
            } else {
                near.hp = st->hp + st->at[j - i];
                near.count = st->at[j - i + 1] - st->at[j - i];
            }
            t->skipped_radius += cand.count - near.count;
            if (near.count && screen_one(h, rs2, 1, prec, &sh[j], &near, t, s, b)) return -1;
        }
    }
    return 0;
}

int update_batch_screen(const hitpoints_t *h, const grid_t *g, precision_t prec, int skip_radius,
                        const update_batch_t *b, size_t first, size_t last, update_stats_t *st, update_scratch_t *s)
{
    const double rs2 = g->r_safe * g->r_safe;
    const batch_hit_t *sh = b->sorted;
    update_stats_t t = *st;
    if (skip_radius && b->prefilter && b->prefilter->xyz) {
        if (screen_prefiltered(h, g, prec, b->prefilter, b, first, last, &t, s)) return -1;
        *st = t;
        return 0;
    }
    /* The radii the distance test reads: prefetched one bucket ahead. */
    const char *radii = prec == PRECISION_DOUBLE ? (const char *)h->r2 : (const char *)h->r2_f32;
    const size_t radius_size = prec == PRECISION_DOUBLE ? sizeof *h->r2 : sizeof *h->r2_f32;
    for (size_t group = first; group < last && group < b->n_groups; group++) {
        const size_t i = b->group[group], end = b->group[group + 1];
        /* Two buckets on, the entries; one bucket on (its hit-point indices have arrived), the radii
         * and the geometry. */
        if (group + SCREEN_PREFETCH_GROUPS < b->n_groups) {
            const grid_cands_t far = grid_bucket_cands(g, 0, sh[b->group[group + SCREEN_PREFETCH_GROUPS]].bucket);
            prefetch_cands(&far);
        }
        if (group + 1 < b->n_groups) {
            const grid_cands_t next = grid_bucket_cands(g, 0, sh[b->group[group + 1]].bucket);
            const size_t n = next.count < SCREEN_PREFETCH_MAX ? next.count : SCREEN_PREFETCH_MAX;
            for (size_t k = 0; k < n; k++) {
                __builtin_prefetch(radii + radius_size * next.hp[k]);
                __builtin_prefetch(&next.hot[next.hp[k]]);
            }
        }
        const grid_cands_t cand = grid_bucket_cands(g, 0, sh[i].bucket);
        t.candidates += cand.count * (end - i);
        if (!cand.count) continue;
        for (size_t j = i; j < end; j++)
            if (screen_one(h, rs2, skip_radius, prec, &sh[j], &cand, &t, s, b)) return -1;
    }
    *st = t;
    return 0;
}

int update_batch_apply(hitpoints_t *h, precision_t prec, const update_batch_t *b, int p,
                       update_scratch_t *all, int nthreads, update_stats_t *st)
{
    update_scratch_t *s = &all[p];
    if (update_batch_gather(s, all, nthreads, p, b->n)) return -1;
    const kept_t *k = s->sorted;
    unsigned long long accepted = 0;
    for (size_t i = 0; i < s->n_sorted; i++) {
        if (i + APPLY_AHEAD < s->n_sorted) {
            /* The state an update a few candidates on may touch: independent misses overlap. */
            const uint32_t f = k[i + APPLY_AHEAD].hp;
            if (prec == PRECISION_DOUBLE) {
                __builtin_prefetch(&h->r2[f], 1);
                __builtin_prefetch(&h->acc[f], 1);
                __builtin_prefetch(&h->weight[f]);
            } else {
                __builtin_prefetch(&h->r2_f32[f], 1);
                if (h->stable) __builtin_prefetch(&h->stable[f], 1);
                else __builtin_prefetch(&h->fp32[f], 1);
            }
        }
        const photon_hit_t *ph = b->hit[k[i].hit];
        const uint32_t e = k[i].hp;
        if (prec == PRECISION_DOUBLE) {
            if (!(k[i].v2 <= h->r2[e])) continue;
            update_accept_double(h, e, ph->flux);
            accepted++;
        } else {
            if (!((float)k[i].v2 <= fp32_from_bits(h->r2_f32[e]))) continue;
            const preu_photon_t ph32 = update_photon_fp32(ph);
            accepted += (unsigned long long)update_apply_fp32(h, e, &ph32, (float)k[i].v2);
        }
    }
    st->accepted += accepted;
    return 0;
}
