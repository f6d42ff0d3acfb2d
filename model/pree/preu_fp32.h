// SPDX-License-Identifier: Apache-2.0
/* preu_fp32.h: the bit-exact binary32 model of one PREU (hit-point update and radiance evaluation).
 *
 * The golden model of rtl/pree_preu.v and of the renderer's fp32 mode. Every operation is one
 * model/pree/fp32_ops.h operation (IEEE binary32, round to nearest even, x86-64 SSE NaN rules made
 * explicit) in exactly the order, with exactly the operands, written in docs/preu_datapath.md.
 *
 * API
 *   preu_hp_t, preu_photon_t    hit-point state and photon at the PREE boundary (binary32 bits)
 *   preu_f32(x)                 the one rounding at the PREE boundary: double -> binary32 (RNE)
 *   preu_update(hp, ph, alpha)  one hit-point update operation (Eq. 6-8, M = 1; alpha a binary32
 *                               run-time constant, PREU_ALPHA = (float)0.7 by default);
 *                               returns 1 and writes tau, r2, n back when accepted, else 0 and
 *                               leaves *hp unchanged
 *   preu_update_inline          the same, inline, for the renderer's hot loop
 *   preu_update_trace(tr, hp, ph, alpha)      every datapath value of one update, as the RTL computes it
 *                               whether or not the photon is accepted (for the RTL scoreboard)
 *   preu_radiance(L, hp, ne)    one radiance evaluation step (Eq. 9): L += tau * (1/((PI*r2)*NE))
 *   preu_n_emitted(count)       NE = the photon count rounded once to binary32
 *
 * Bit-exactness needs binary32 evaluation with no contraction: build with -ffp-contract=off and
 * no fast-math (the project's flags), also in C++ harnesses that include this header.
 * None of these can fail; NaN and infinity inputs give the results documented in the datapath
 * document (a NaN distance or radius never accepts). */
#ifndef PREE_PREU_FP32_H
#define PREE_PREU_FP32_H

#include <stdint.h>
#include "fp32_ops.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Datapath constants, binary32 bit patterns (docs/preu_datapath.md, "Constants"). */
#define PREU_ALPHA  0x3F333333u /* (float)0.7                      */
#define PREU_ONE    0x3F800000u /* 1.0f                            */
#define PREU_INV_PI 0x3EA2F983u /* (float)(1.0 / 3.14159265358979) */
#define PREU_PI     0x40490FDBu /* (float)3.14159265358979         */

typedef struct {
    uint32_t pos[3]; /* hit-point position x, y, z                             */
    uint32_t f[3];   /* weight: BRDF colour times eye-path throughput, r, g, b */
    uint32_t tau[3]; /* accumulated flux r, g, b                               */
    uint32_t r2;     /* radius squared                                         */
    uint32_t n;      /* N = alpha * accepted photons, accumulated as N + alpha */
} preu_hp_t;

typedef struct {
    uint32_t pos[3]; /* photon position x, y, z */
    uint32_t phi[3]; /* photon flux r, g, b     */
} preu_photon_t;

/* Every value the update datapath computes, named as in docs/preu_datapath.md. */
typedef struct {
    uint32_t d[3], m[3], na, n1;   /* S1-S2 */
    uint32_t q[3], t[3], g;        /* S3-S4 (g: divider S3-S6) */
    uint32_t s, u[3];              /* S5-S6 */
    uint32_t d2, r2n, tau_n[3];    /* S7-S8 */
    int accept;                    /* S9    */
} preu_trace_t;

uint32_t preu_f32(double x);
uint32_t preu_n_emitted(uint64_t count);
int preu_update(preu_hp_t *hp, const preu_photon_t *ph, uint32_t alpha);
void preu_update_trace(preu_trace_t *tr, const preu_hp_t *hp, const preu_photon_t *ph, uint32_t alpha);
void preu_radiance(uint32_t L[3], const preu_hp_t *hp, uint32_t n_emitted_f32);

/* Write-back of an accepted photon: S1-S8 of the radius/flux/count path, explicit fp32_ops. */
static inline void preu_update_accepted(preu_hp_t *hp, const preu_photon_t *ph, uint32_t alpha)
{
    uint32_t na = fp32_add(hp->n, alpha);   /* S1-S2 */
    uint32_t n1 = fp32_add(hp->n, PREU_ONE);     /* S1-S2 */
    uint32_t g = fp32_div(na, n1);               /* S3-S6 */
    for (int c = 0; c < 3; c++) {
        uint32_t m = fp32_mul(hp->f[c], ph->phi[c]); /* S1-S2 */
        uint32_t t = fp32_mul(m, PREU_INV_PI);       /* S3-S4 */
        uint32_t u = fp32_add(hp->tau[c], t);        /* S5-S6 */
        hp->tau[c] = fp32_mul(u, g);                 /* S7-S8 */
    }
    hp->r2 = fp32_mul(hp->r2, g);                /* S7-S8 */
    hp->n = na;
}

/* One update operation. The distance (preu_distance2, shared with the stable datapath) runs as
 * plain float arithmetic: every non-NaN result
 * equals the fp32_ops result bit for bit, and whether a result is NaN does not depend on which
 * NaN came in, so d2 <= r2 decides exactly as fp32_cmp(d2, r2).le does (NaN: not accepted).
 * Only the written-back values need fp32_ops' NaN rules. */
static inline float preu_distance2(const uint32_t hp_pos[3], const preu_photon_t *ph)
{
    float dx = fp32_from_bits(hp_pos[0]) - fp32_from_bits(ph->pos[0]);
    float dy = fp32_from_bits(hp_pos[1]) - fp32_from_bits(ph->pos[1]);
    float dz = fp32_from_bits(hp_pos[2]) - fp32_from_bits(ph->pos[2]);
    return (dx * dx + dy * dy) + dz * dz;
}

static inline int preu_update_inline(preu_hp_t *hp, const preu_photon_t *ph, uint32_t alpha)
{
    const float d2 = preu_distance2(hp->pos, ph);
    if (!(d2 <= fp32_from_bits(hp->r2)))
        return 0;
    preu_update_accepted(hp, ph, alpha);
    return 1;
}

#ifdef __cplusplus
}
#endif

#endif
