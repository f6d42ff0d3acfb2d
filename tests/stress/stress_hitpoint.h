// SPDX-License-Identifier: Apache-2.0
/* stress_hitpoint.h: what the parts of the single-hit-point stress program share
 * (tests/stress/stress_hitpoint.c: its use and options): the options, the double and long-double
 * references and the closed form (stress_refs.c), and each run (stress_decades.c, the decade
 * run; stress_tables.c, the non-finite, N_emitted, self-test and decomposition tables). */
#ifndef STRESS_HITPOINT_H
#define STRESS_HITPOINT_H

#include <stddef.h>
#include <stdint.h>

#include "preu_fp32.h"
#include "preu_stable.h"

#define PI_D  3.14159265358979      /* smallppm's pi (model/scene/scene.h PREE_PI)            */
#define PI_LD 3.14159265358979L     /* the same truncated pi in long double              */
#define MAX_AT 32
#define MAX_CP 512
#define CLOSED_K0 64                /* closed_lnR: the product below, Stirling's series above */

typedef struct {
    uint64_t accepts;
    double alpha, r2, flux, weight, epa;
    int flux_random, paper, stable, ld, per_decade, n_at;
    uint64_t at[MAX_AT];
    const char *csv, *label;
} opts_t;

static inline double f32v(uint32_t b) { return (double)fp32_from_bits(b); }

/* Relative error of x against ref: 0 when equal (also both 0 or both inf), +-inf when ref is 0
 * and x is not, NaN when either is NaN. */
double relerr(long double x, long double ref);
/* An error as the tables print it: "0", "nan" or a signed %.2e. */
void fmt_err(char *b, size_t n, double e);
uint64_t splitmix64(uint64_t *s);
/* ln of r2_k / r2_0 after k accepts with c = 1 / alpha (stress_refs.c: the closed form). */
long double closed_lnR(uint64_t k, long double c);

/* The references: smallppm's update in double and in long double, with an integer count. */
typedef struct {
    double r2, tau;
    uint64_t count;
} ref_d_t;
typedef struct {
    long double r2, tau;
    uint64_t count;
} ref_ld_t;

static inline void ref_d_update(ref_d_t *s, double a, double f, double phi)
{
    /* model/ppm/update.h update_accept_double: g = (n a + a) / (n a + 1); r2 *= g; n++;
     * tau = (tau + f phi (1 / PI)) g. */
    double g = ((double)s->count * a + a) / ((double)s->count * a + 1.0);
    s->r2 = s->r2 * g;
    s->count++;
    s->tau = (s->tau + (f * phi) * (1. / PI_D)) * g;
}

static inline void ref_ld_update(ref_ld_t *s, long double a, long double f, long double phi)
{
    long double g = ((long double)s->count * a + a) / ((long double)s->count * a + 1.0L);
    s->r2 = s->r2 * g;
    s->count++;
    s->tau = (s->tau + (f * phi) * (1.0L / PI_LD)) * g;
}


int run_decades(const opts_t *o);   /* the decade run (0, or 2 when the CSV cannot be written) */
int run_nonfinite(void);
int run_ne_table(void);             /* 1 when an NE rounds beyond 2^-24 */
int run_selftest(void);             /* 1 when the references disagree */
int run_decompose(uint64_t K);

#endif
