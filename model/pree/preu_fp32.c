// SPDX-License-Identifier: Apache-2.0
/* preu_fp32.c: the PREU's binary32 datapath, operation by operation (docs/preu_datapath.md).
 * Compiled with -ffp-contract=off and no fast-math: each fp32_ops call rounds exactly once. */
#include "preu_fp32.h"

uint32_t preu_f32(double x)
{
    /* The default rounding mode (round to nearest, ties to even) is never changed in PREE. */
    return fp32_to_bits((float)x);
}

uint32_t preu_n_emitted(uint64_t count)
{
    /* Exact up to 2^24; above, the nearest binary32 (relative error at most 2^-24). */
    return preu_f32((double)count);
}

int preu_update(preu_hp_t *hp, const preu_photon_t *ph, uint32_t alpha)
{
    return preu_update_inline(hp, ph, alpha);
}

void preu_update_trace(preu_trace_t *tr, const preu_hp_t *hp, const preu_photon_t *ph, uint32_t alpha)
{
    for (int k = 0; k < 3; k++) {
        tr->d[k] = fp32_sub(hp->pos[k], ph->pos[k]);       /* S1-S2 subtractors SUB0..2 */
        tr->m[k] = fp32_mul(hp->f[k], ph->phi[k]);         /* S1-S2 multipliers MUL0..2 */
    }
    tr->na = fp32_add(hp->n, alpha);                       /* S1-S2 adder ADD5 */
    tr->n1 = fp32_add(hp->n, PREU_ONE);                    /* S1-S2 adder ADD6 */
    for (int k = 0; k < 3; k++) {
        tr->q[k] = fp32_sqr(tr->d[k]);                     /* S3-S4 squarers SQR0..2 */
        tr->t[k] = fp32_mul(tr->m[k], PREU_INV_PI);        /* S3-S4 multipliers MUL3..5 */
    }
    tr->g = fp32_div(tr->na, tr->n1);                      /* S3-S6 divider DIV */
    tr->s = fp32_add(tr->q[0], tr->q[1]);                  /* S5-S6 adder ADD3 */
    for (int k = 0; k < 3; k++)
        tr->u[k] = fp32_add(hp->tau[k], tr->t[k]);         /* S5-S6 adders ADD0..2 */
    tr->d2 = fp32_add(tr->s, tr->q[2]);                    /* S7-S8 adder ADD4 */
    tr->r2n = fp32_mul(hp->r2, tr->g);                     /* S7-S8 multiplier MUL9 */
    for (int k = 0; k < 3; k++)
        tr->tau_n[k] = fp32_mul(tr->u[k], tr->g);          /* S7-S8 multipliers MUL6..8 */
    tr->accept = fp32_cmp(tr->d2, hp->r2).le;              /* S9 comparator CMP */
}

void preu_radiance(uint32_t L[3], const preu_hp_t *hp, uint32_t n_emitted_f32)
{
    uint32_t a = fp32_mul(PREU_PI, hp->r2);                /* S1-S2  MUL0 */
    uint32_t b = fp32_mul(a, n_emitted_f32);               /* S3-S4  MUL3 */
    uint32_t k = fp32_div(PREU_ONE, b);                    /* S5-S8  DIV  */
    for (int c = 0; c < 3; c++) {
        uint32_t v = fp32_mul(hp->tau[c], k);              /* S9-S10  MUL6..8 */
        L[c] = fp32_add(L[c], v);                          /* S11-S12 ADD0..2 */
    }
}
