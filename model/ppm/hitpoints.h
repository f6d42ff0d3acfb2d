// SPDX-License-Identifier: Apache-2.0
/* hitpoints.h: the measurement points of progressive photon mapping and their state.
 *
 * Geometry (position, normal, weight, pixel) comes from the eye pass, in creation order
 * (pixel order, then path order). Each mode then adds only the arrays its state needs:
 *   double  r2 and flux in double (hitpoints_init_double), the count in hp_hot_t, the weight;
 *   fp32    binary32 words in the PREU's layout (model/pree/preu_fp32.h) or, with the stable
 *           datapath, in its layout (model/pree/preu_stable.h), which hold the weight too, so the
 *           double weight is dropped (hitpoints_drop_weight) for a byte that says it was zero.
 * Index i is the hit point's address in the PREE hit-point memory. */
#ifndef PREE_HITPOINTS_H
#define PREE_HITPOINTS_H

#include <stddef.h>
#include <stdint.h>
#include "preu_fp32.h"
#include "preu_stable.h"
#include "vec3.h"

/* Geometry of a hit point: what the screening reads. */
typedef struct {
    double px, py, pz;   /* position */
    double nx, ny, nz;   /* outward surface normal */
} hp_hot_t;

/* The double mode's accumulated state besides the radius, in one aligned 32 bytes: what an
 * accepted photon writes, so an accept touches this line, the radius and the weight. */
typedef struct {
    vec3 flux;           /* accumulated flux tau */
    uint32_t count;      /* accepted photons */
    uint32_t pad;
} hp_acc_t;

typedef struct {
    size_t n, cap;
    hp_hot_t *hot;
    vec3 *weight;      /* BRDF colour times eye-path throughput (NULL in fp32 mode after its set-up) */
    uint8_t *dark;     /* fp32 mode: 1 where the weight was zero in every channel (else NULL) */
    hp_acc_t *acc;     /* flux and count (double mode; else NULL) */
    uint32_t *object;  /* the object each lies on (hit_t.object), kept only with_object */
    int with_object;    /* set before the first push: keep object[] (the photon-map estimator
                         * groups by it; the PPM passes never read it) */
    double *r2;        /* radius squared (double mode; else NULL), compact for the distance test */
    uint32_t *r2_f32;  /* fp32 mode: a compact copy of fp32[i].r2 for the distance test; stable
                        * datapath: a binary32 bound on the accepted d2 (preu_stable_screen_r2) */
    int32_t *pixel;    /* pixel index y * width + x */
    preu_hp_t *fp32;   /* PREU state (fp32 mode, paper datapath; NULL otherwise) */
    preu_shp_t *stable; /* PREU state (fp32 mode, stable datapath; NULL otherwise) */
    double alpha;       /* the radius reduction parameter (double mode) */
    uint32_t alpha32;   /* fp32: alpha rounded once (paper datapath's run-time constant) */
    uint32_t kappa32;   /* fp32: preu_kappa(alpha32) (stable datapath's run-time constant) */
} hitpoints_t;

int hitpoints_push(hitpoints_t *h, vec3 pos, vec3 nrm, vec3 weight, int32_t pixel, uint32_t object);
int hitpoints_append(hitpoints_t *dst, const hitpoints_t *src);
/* Give back the growth margin: the arrays hold exactly n. 0 or -1. */
int hitpoints_trim(hitpoints_t *h);
/* The double mode's state before the first photon: r2 = r0^2, flux 0, count 0. 0 or -1. */
int hitpoints_init_double(hitpoints_t *h, double r0);
/* fp32 mode, once its state words hold the weight: free the double weight, keeping whether it
 * was zero (dark). 0 or -1. */
int hitpoints_drop_weight(hitpoints_t *h);
void hitpoints_free(hitpoints_t *h);
/* Whether hit point i's weight is zero in every channel (it can add no radiance). */
static inline int hitpoints_zero_weight(const hitpoints_t *h, size_t i)
{
    if (!h->weight) return h->dark[i];
    return h->weight[i].x == 0 && h->weight[i].y == 0 && h->weight[i].z == 0;
}
/* Bytes held per hit point by the arrays h has (geometry, weight, pixel, double and fp32 state). */
size_t hitpoints_bytes_each(const hitpoints_t *h);

#endif
