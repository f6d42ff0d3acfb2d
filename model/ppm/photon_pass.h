// SPDX-License-Identifier: Apache-2.0
/* photon_pass.h: photon emission from the scene's lights and tracing with Russian roulette,
 * recording every diffuse hit (the grid look-ups) in path order.
 *
 * Photon i is emitted by light i mod L with flux scaled by L (one light: the reference
 * program exactly); its random numbers are Halton dimensions keyed by i and the path depth,
 * so the photon's path never depends on thread timing. */
#ifndef PREE_PHOTON_PASS_H
#define PREE_PHOTON_PASS_H

#include <stddef.h>
#include <stdint.h>
#include "scene.h"
#include "tracer.h"

typedef struct {
    vec3 x;           /* hit position */
    vec3 n;           /* outward normal at the hit (not flipped toward the photon) */
    vec3 flux;        /* photon flux arriving */
    uint64_t photon;  /* photon index */
    uint32_t bucket;  /* grid bucket (filled after tracing), or GRID_NO_BUCKET */
} photon_hit_t;

typedef struct {
    photon_hit_t *hits;
    size_t n, cap;
    unsigned long long segments;   /* ray segments traced */
} photon_hits_t;

/* Trace photon i and append its diffuse hits. Returns 0, or -1 when out of memory. */
int photon_trace(const scene_t *scene, const tracer_t *tr, uint64_t i, photon_hits_t *out);
void photon_hits_free(photon_hits_t *h);

#endif
