// SPDX-License-Identifier: Apache-2.0
/* update.h: the progressive update of hit points by photon hits (Eq. 1-2 of paper 000 with
 * M = 1 and the hit points' alpha, default 0.7), for one owned part of the hit points, in
 * photon order.
 *
 * Double mode: the reference program's test and arithmetic. fp32 mode: the host keeps the
 * normal test in double; every candidate that passes it goes to the PREU model
 * (model/pree/preu_fp32.h), which does the distance test and the update in binary32. */
#ifndef PREE_UPDATE_H
#define PREE_UPDATE_H

#include "grid.h"
#include "hitpoints.h"
#include "photon_pass.h"

#define UPDATE_ALPHA 0.7   /* the default alpha (smallppm's) */
#define UPDATE_NORMAL_COS 1e-3

typedef struct {
    unsigned long long candidates;      /* hit points examined (paper: hit-point update operations) */
    unsigned long long skipped_radius;  /* candidates farther than the safe initial radius (GRID_CELLS) */
    unsigned long long normal_passed;   /* candidates passing the normal test: sent to the PREE */
    unsigned long long accepted;        /* updates applied */
} update_stats_t;

typedef enum { PRECISION_DOUBLE = 0, PRECISION_FP32 = 1 } precision_t;
/* fp32 mode: the paper's PREU datapath, or the stable one (model/pree/preu_stable.h). */
typedef enum { DATAPATH_PAPER = 0, DATAPATH_STABLE = 1 } datapath_t;

/* The hit-point update operations as the PREE must see them, in photon order: per photon hit,
 * its binary32 photon and the hit points (photon-pass indices) that passed the host's tests
 * (the candidates streamed to the PREUs; the PREU's own distance test decides). */
typedef struct {
    size_t n_hits, cap_hits;
    preu_photon_t *ph;        /* photon hit i */
    size_t *end;              /* its operations are hp[update_ops_begin(i) .. end[i]) */
    size_t n_ops, cap_ops;
    uint32_t *hp;
    int failed;               /* out of memory while recording */
} update_ops_t;

void update_ops_clear(update_ops_t *o);
void update_ops_free(update_ops_t *o);
static inline size_t update_ops_begin(const update_ops_t *o, size_t i) { return i ? o->end[i - 1] : 0; }

/* Apply hits[0..n) to the hit points of part p; with ops (fp32 only), record the operations. */
void update_part(hitpoints_t *h, grid_t *g, int p, precision_t prec, int skip_radius,
                 const photon_hit_t *hits, size_t n, update_stats_t *st, update_ops_t *ops);

/* The reference program's double update of one hit point by flux F. */
static inline void update_accept_double(hitpoints_t *h, size_t e, vec3 F)
{
    hp_acc_t *acc = &h->acc[e];
    const double a = h->alpha;
    double g = (acc->count * a + a) / (acc->count * a + 1.0);
    h->r2[e] = h->r2[e] * g;
    acc->count++;
    acc->flux = v3_scale(v3_add(acc->flux, v3_scale(v3_mul(h->weight[e], F), 1. / PREE_PI)), g);
}

/* The photon at the PREE boundary: rounded once to binary32. */
static inline preu_photon_t update_photon_fp32(const photon_hit_t *ph)
{
    preu_photon_t p = {{preu_f32(ph->x.x), preu_f32(ph->x.y), preu_f32(ph->x.z)},
                       {preu_f32(ph->flux.x), preu_f32(ph->flux.y), preu_f32(ph->flux.z)}};
    return p;
}

/* fp32 mode: the datapath's own distance test and write-back for a candidate at binary32
 * distance squared d2 that passed d2 <= r2_f32[e]; keeps r2_f32[e] up to date. 1 when
 * accepted. (For the stable datapath, r2_f32 is a bound that the exact test refines.) */
static inline int update_apply_fp32(hitpoints_t *h, uint32_t e, const preu_photon_t *ph32, float d2)
{
    if (h->stable) {
        preu_shp_t *s = &h->stable[e];
        if (!preu_stable_accepts(fp32_to_bits(d2), s->w)) return 0;
        preu_stable_update_accepted(s, ph32, h->kappa32);
        h->r2_f32[e] = preu_stable_screen_r2(s->w);
        return 1;
    }
    preu_update_accepted(&h->fp32[e], ph32, h->alpha32);
    h->r2_f32[e] = h->fp32[e].r2;
    return 1;
}

#endif
