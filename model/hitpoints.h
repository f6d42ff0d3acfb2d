/* hitpoints.h: the measurement points of progressive photon mapping and their state.
 *
 * Geometry (position, normal, weight, pixel) comes from the eye pass, in creation order
 * (pixel order, then path order). The state (radius squared, photon count, flux) is held in
 * double for the double mode and, for the fp32 mode, as binary32 words in the PREU's layout
 * (model/preu_fp32.h). Index i is the hit point's address in the PREE hit-point memory. */
#ifndef PREE_HITPOINTS_H
#define PREE_HITPOINTS_H

#include <stddef.h>
#include <stdint.h>
#include "preu_fp32.h"
#include "vec3.h"

/* What the update loop reads for every candidate, kept together (one cache line). */
typedef struct {
    double px, py, pz;   /* position */
    double nx, ny, nz;   /* outward surface normal */
    double r2;           /* radius squared (double mode); initial radius squared (fp32 mode) */
    uint32_t count;      /* accepted photons (double mode) */
    uint32_t pad;
} hp_hot_t;

typedef struct {
    size_t n, cap;
    hp_hot_t *hot;
    vec3 *weight;      /* BRDF colour times eye-path throughput */
    vec3 *flux;        /* accumulated flux tau (double mode) */
    int32_t *pixel;    /* pixel index y * width + x */
    preu_hp_t *fp32;   /* PREU state (fp32 mode only; NULL otherwise) */
} hitpoints_t;

int hitpoints_push(hitpoints_t *h, vec3 pos, vec3 nrm, vec3 weight, int32_t pixel);
int hitpoints_append(hitpoints_t *dst, const hitpoints_t *src);
void hitpoints_free(hitpoints_t *h);

#endif
