// SPDX-License-Identifier: Apache-2.0
/* update_prefilter.h: the screening's binary32 prefilter (update_prefilter.c): per photon hit, the
 * entries of its bucket that can lie within the safe radius, 8 (AVX2) or 16 (AVX-512F) a vector.
 * It rejects only candidates whose double distance test against the safe radius is certain to
 * fail, so the exact tests that follow on the rest keep every candidate and count every skip
 * that the screening without it would. */
#ifndef PREE_UPDATE_PREFILTER_H
#define PREE_UPDATE_PREFILTER_H

#include <stddef.h>
#include <stdint.h>
#include "cpu_features.h"
#include "grid.h"
#include "hitpoints.h"

/* Entries beyond a list's count that update_prefilter_near may write. */
#define PREFILTER_OUT_PAD 16

typedef struct {
    float *xyz;             /* hit point i's position rounded to binary32 at xyz[3i .. 3i+2] (NULL:
                             * no prefilter): one line holds five, as a bucket's neighbours lie */
    size_t n;
    double max_abs;         /* every coordinate the bound covers: hit points' and photons' */
    float t2;               /* reject when the binary32 distance squared exceeds this */
    simd_level_t level;     /* SIMD_AVX2 or SIMD_AVX512 */
} update_prefilter_t;

/* The bound t2 for safe radius r_safe and coordinates of magnitude at most max_abs (derivation in
 * update_prefilter.c); +infinity (nothing rejected) when max_abs is too large to bound. */
float update_prefilter_bound(double r_safe, double max_abs);

/* Set pf up for grid g over hit points h at level (forcing, for tests, a level the processor
 * has): nothing (pf->xyz NULL) for SIMD_SCALAR or a grid other than GRID_CELLS. 0, or -1 (memory). */
int update_prefilter_build(update_prefilter_t *pf, const hitpoints_t *h, const grid_t *g, simd_level_t level);
void update_prefilter_free(update_prefilter_t *pf);

/* Whether a photon at (x, y, z) lies within the coordinates the bound covers. */
static inline int update_prefilter_covers(const update_prefilter_t *pf, double x, double y, double z)
{
    return pf->xyz && __builtin_fabs(x) <= pf->max_abs && __builtin_fabs(y) <= pf->max_abs && __builtin_fabs(z) <= pf->max_abs;
}

/* Ask for the cache line of hit point i's binary32 position. */
static inline void update_prefilter_prefetch(const update_prefilter_t *pf, uint32_t i)
{
    __builtin_prefetch(pf->xyz + 3 * (size_t)i);
}

/* The entries hp[0 .. count) of a photon at (x, y, z) (covered) that the bound keeps, in order,
 * into out (count + PREFILTER_OUT_PAD entries); returns how many. */
size_t update_prefilter_near(const update_prefilter_t *pf, const uint32_t *hp, size_t count, double x, double y,
                             double z, uint32_t *out);

#endif
