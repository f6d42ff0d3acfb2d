// SPDX-License-Identifier: Apache-2.0
/* preu_stable.h: the bit-exact model of the stable PREU datapath (docs/preu_datapath.md,
 * "The stable datapath"; rtl/pree_preu.v with Datapath = 1).
 *
 * The same estimator as the paper's datapath (Eq. 6-9, M = 1, the same alpha, accept rule and
 * photon order), held so that it stays accurate for any number of photons:
 *   k       the accepted-photon count, an exact 64-bit integer (N = alpha * k is never formed);
 *   w       1 / r2 in the wide format (model/pree/wide_acc.h): w' = w + w * kappa / (k + 1), with
 *           kappa = (1 - alpha) / alpha, which is r2' = r2 * (N + alpha) / (N + 1) exactly;
 *   T[c]    tau_c / r2 times PI, wide: T' = T + f * phi * w. The factor g cancels, so T only
 *           grows by additions; radiance = T / (PI^2 * N_emitted) needs no r2.
 * The distance test is d2 * w <= 1 in binary32 (d2 <= r2 with r2 = 1 / w).
 *
 * API
 *   preu_shp_t                  the stable hit point: constant part as preu_hp_t, state k, w, T
 *   preu_kappa(alpha)           the run-time constant: fl(fl(1 - alpha) / alpha)
 *   preu_stable_init(hp, r2)    state before the first photon for radius squared r2 (double)
 *   preu_stable_update(hp, ph, kappa)   one update; 1 and the new state when accepted, else 0
 *   preu_stable_update_trace(tr, hp, ph, kappa)   every datapath value, accepted or not
 *   preu_stable_radiance(L, hp, ne)     one radiance step: L += T * (1 / ((PI * PI) * NE))
 *   preu_stable_r2(hp), preu_stable_tau(hp, c)   host views in double: 1 / w and T * r2 / PI */
#ifndef PREE_PREU_STABLE_H
#define PREE_PREU_STABLE_H

#include <stdint.h>
#include "fp32_ops.h"
#include "preu_fp32.h"
#include "wide_acc.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    uint32_t pos[3]; /* hit-point position x, y, z (binary32)       */
    uint32_t f[3];   /* weight r, g, b (binary32)                   */
    uint64_t T[3];   /* PI * tau / r2, r, g, b (wide)                */
    uint64_t w;      /* 1 / r2 (wide)                                */
    uint64_t k;      /* accepted photons                             */
} preu_shp_t;

/* Every value the stable update datapath computes, by stage (docs/preu_datapath.md). */
typedef struct {
    uint32_t d[3], m[3], w32, kf; /* S1-S2 (kn = k + 1 is an integer add)   */
    uint64_t kn;
    uint32_t q[3], t[3], e;       /* S3-S4 (e: divider S3-S6)             */
    uint32_t s;                   /* S5-S6                                */
    uint64_t Tn[3];               /* S5-S6 wide accumulators              */
    uint32_t d2, p;               /* S7-S8                                */
    uint32_t d2w;                 /* S9-S10                               */
    uint64_t wn;                  /* S9-S10 wide accumulator              */
    int accept;                   /* S11                                  */
} preu_strace_t;

uint32_t preu_kappa(uint32_t alpha);
void preu_stable_init(preu_shp_t *hp, double r2);
int preu_stable_update(preu_shp_t *hp, const preu_photon_t *ph, uint32_t kappa);
void preu_stable_update_trace(preu_strace_t *tr, const preu_shp_t *hp, const preu_photon_t *ph, uint32_t kappa);
void preu_stable_radiance(uint32_t L[3], const preu_shp_t *hp, uint32_t n_emitted_f32);
double preu_stable_r2(const preu_shp_t *hp);
double preu_stable_tau(const preu_shp_t *hp, int c);

/* The distance test of the stable datapath for a binary32 distance squared d2 (the same value
 * as the paper's datapath computes): d2 * w32 <= 1, false on NaN. */
static inline int preu_stable_accepts(uint32_t d2, uint64_t w)
{
    return fp32_cmp(fp32_mul(d2, wide_f32(w)), PREU_ONE).le;
}

/* A binary32 radius squared rho with: preu_stable_accepts(d2, w) implies d2 <= rho, and rho
 * never grows as w grows. The engine screens candidates with it as with the paper's r2.
 * d2 * w32 rounds to <= 1 only if d2 * w32 <= 1 + 2^-24; rho covers (1 + 2^-22) / w32. */
static inline uint32_t preu_stable_screen_r2(uint64_t w)
{
    const uint32_t w32 = wide_f32(w);
    if (fp32_is_nan(w32)) return w32;
    const double wd = (double)fp32_from_bits(w32);
    if (wd == 0) return 0x7F800000u;
    return fp32_to_bits((float)((1.0 + 0x1p-22) / wd));
}

/* Write-back of an accepted photon, in datapath order (kappa: preu_kappa(alpha)). */
static inline void preu_stable_update_accepted(preu_shp_t *hp, const preu_photon_t *ph, uint32_t kappa)
{
    const uint32_t w32 = wide_f32(hp->w);
    const uint64_t kn = hp->k + 1;
    const uint32_t e = fp32_div(kappa, u64_to_f32(kn));                /* S3-S6  */
    for (int c = 0; c < 3; c++) {
        const uint32_t m = fp32_mul(hp->f[c], ph->phi[c]);             /* S1-S2  */
        hp->T[c] = wide_add(hp->T[c], fp32_mul(m, w32));               /* S3-S6  */
    }
    hp->w = wide_add(hp->w, fp32_mul(w32, e));                         /* S7-S10 */
    hp->k = kn;
}

/* One update operation; the distance in plain float, as preu_update_inline. */
static inline int preu_stable_update_inline(preu_shp_t *hp, const preu_photon_t *ph, uint32_t kappa)
{
    if (!preu_stable_accepts(fp32_to_bits(preu_distance2(hp->pos, ph)), hp->w)) return 0;
    preu_stable_update_accepted(hp, ph, kappa);
    return 1;
}

#ifdef __cplusplus
}
#endif

#endif
