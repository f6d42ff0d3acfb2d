/* hitpoints.h: the measurement points of progressive photon mapping and their state.
 *
 * Geometry (position, normal, weight, pixel) comes from the eye pass, in creation order
 * (pixel order, then path order). The state (radius squared, photon count, flux) is held in
 * double for the double mode and, for the fp32 mode, as binary32 words in the PREU's layout
 * (model/pree/preu_fp32.h) or, with the stable datapath, in its layout (model/pree/preu_stable.h).
 * Index i is the hit point's address in the PREE hit-point memory. */
#ifndef PREE_HITPOINTS_H
#define PREE_HITPOINTS_H

#include <stddef.h>
#include <stdint.h>
#include "preu_fp32.h"
#include "preu_stable.h"
#include "vec3.h"

/* Geometry of a hit point and its photon count (double mode). */
typedef struct {
    double px, py, pz;   /* position */
    double nx, ny, nz;   /* outward surface normal */
    uint32_t count;      /* accepted photons (double mode) */
    uint32_t object;     /* the object it lies on (hit_t.object) */
} hp_hot_t;

typedef struct {
    size_t n, cap;
    hp_hot_t *hot;
    vec3 *weight;      /* BRDF colour times eye-path throughput */
    vec3 *flux;        /* accumulated flux tau (double mode) */
    double *r2;        /* radius squared (double mode), compact for the distance test */
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
void hitpoints_free(hitpoints_t *h);
/* Bytes held per hit point by the arrays h has (geometry, weight, pixel, double and fp32 state). */
size_t hitpoints_bytes_each(const hitpoints_t *h);

#endif
