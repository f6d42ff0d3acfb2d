// SPDX-License-Identifier: Apache-2.0
/* emitters.h: the area lights as the camera sees them: the emitted radiance an eye ray segment
 * meets on its way to the surface it hits (docs/scene_format.md, "Lights").
 *
 * An area light's triangles are not geometry (the tracer does not hold them): a segment
 * o + t d, epsilon < t <= t_max + epsilon (t_max: the distance to the surface the tracer hit,
 * INFINITY for a miss), sees the nearest of them whose front face it meets, and takes its
 * radiance. The epsilon beyond t_max makes an emitting triangle that coincides with the surface
 * (a mesh's emissive material is both light and geometry) count as on it. Double precision,
 * Moller-Trumbore; each light's triangles are skipped as one when the segment misses their box. */
#ifndef PREE_EMITTERS_H
#define PREE_EMITTERS_H

#include "scene.h"

typedef struct {
    const light_t *light;
    vec3 lo, hi;   /* the bounding box of its triangles */
} emitter_t;

typedef struct {
    emitter_t *e;
    int n;          /* the scene's area lights (0: nothing to see) */
    double eps;     /* the scene's epsilon */
} emitters_t;

/* The scene's area lights: 0 (n may be 0), or -1 (out of memory). */
int emitters_init(emitters_t *em, const scene_t *scene);
void emitters_free(emitters_t *em);

/* 1 and the radiance in *L when the segment (d unit length) meets an area light's front face
 * as above; else 0. */
int emitters_seen(const emitters_t *em, vec3 o, vec3 d, double t_max, vec3 *L);

#endif
