// SPDX-License-Identifier: Apache-2.0
/* preu_stable.c: the stable PREU datapath, operation by operation (docs/preu_datapath.md,
 * "The stable datapath"). Compiled with -ffp-contract=off and no fast-math. */
#include "preu_stable.h"

uint32_t preu_kappa(uint32_t alpha)
{
    return fp32_div(fp32_sub(PREU_ONE, alpha), alpha);
}

void preu_stable_init(preu_shp_t *hp, double r2)
{
    hp->T[0] = hp->T[1] = hp->T[2] = WIDE_ZERO;
    hp->w = wide_from_double(1.0 / r2);
    hp->k = 0;
}

int preu_stable_update(preu_shp_t *hp, const preu_photon_t *ph, uint32_t kappa)
{
    return preu_stable_update_inline(hp, ph, kappa);
}

void preu_stable_update_trace(preu_strace_t *tr, const preu_shp_t *hp, const preu_photon_t *ph, uint32_t kappa)
{
    tr->w32 = wide_f32(hp->w);
    for (int k = 0; k < 3; k++) {
        tr->d[k] = fp32_sub(hp->pos[k], ph->pos[k]);        /* S1-S2  SUB0..2           */
        tr->m[k] = fp32_mul(hp->f[k], ph->phi[k]);          /* S1-S2  MUL0..2           */
    }
    tr->kn = hp->k + 1;                                     /* S1     count incrementer */
    tr->kf = u64_to_f32(tr->kn);                            /* S1-S2  I2F               */
    for (int k = 0; k < 3; k++) {
        tr->q[k] = fp32_sqr(tr->d[k]);                      /* S3-S4  SQR0..2           */
        tr->t[k] = fp32_mul(tr->m[k], tr->w32);             /* S3-S4  MUL3..5           */
    }
    tr->e = fp32_div(kappa, tr->kf);                        /* S3-S6  DIV               */
    tr->s = fp32_add(tr->q[0], tr->q[1]);                   /* S5-S6  ADD3              */
    for (int k = 0; k < 3; k++)
        tr->Tn[k] = wide_add(hp->T[k], tr->t[k]);           /* S5-S6  WACC0..2          */
    tr->d2 = fp32_add(tr->s, tr->q[2]);                     /* S7-S8  ADD4              */
    tr->p = fp32_mul(tr->w32, tr->e);                       /* S7-S8  MUL9              */
    tr->d2w = fp32_mul(tr->d2, tr->w32);                    /* S9-S10 MUL6              */
    tr->wn = wide_add(hp->w, tr->p);                        /* S9-S10 WACC3             */
    tr->accept = fp32_cmp(tr->d2w, PREU_ONE).le;            /* S11    CMP               */
}

void preu_stable_radiance(uint32_t L[3], const preu_shp_t *hp, uint32_t n_emitted_f32)
{
    uint32_t a = fp32_mul(PREU_PI, PREU_PI);                /* S1-S2   MUL0     */
    uint32_t b = fp32_mul(a, n_emitted_f32);                /* S3-S4   MUL3     */
    uint32_t k = fp32_div(PREU_ONE, b);                     /* S5-S8   DIV      */
    for (int c = 0; c < 3; c++) {
        uint32_t v = fp32_mul(wide_f32(hp->T[c]), k);       /* S9-S10  MUL6..8  */
        L[c] = fp32_add(L[c], v);                           /* S11-S12 ADD0..2  */
    }
}

double preu_stable_r2(const preu_shp_t *hp)
{
    return 1.0 / wide_to_double(hp->w);
}

double preu_stable_tau(const preu_shp_t *hp, int c)
{
    return wide_to_double(hp->T[c]) * preu_stable_r2(hp) / 3.14159265358979;
}
