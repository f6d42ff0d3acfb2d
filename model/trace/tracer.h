// SPDX-License-Identifier: Apache-2.0
/* tracer.h: ray casting for the engine through Embree 3.
 * Spheres are Embree user geometry whose callbacks intersect the double-precision ray
 * (carried in an extended intersect context) exactly as the reference program does;
 * triangles are Embree's native triangle geometry. A scene of at most SPHERE_GROUP_MAX spheres
 * and no triangles needs no Embree: its rays test the sphere group directly, to the same hit.
 *
 * tracer_create() returns NULL with a one-line message in err on failure, STOP_MESSAGE when
 * stop was set during the build (Embree's progress monitor polls it). */
#ifndef PREE_TRACER_H
#define PREE_TRACER_H

#include <stddef.h>
#include "scene.h"
#include "stop.h"

/* Rays start this far along their direction from a surface (triangles), and a sphere hit
 * closer than this is ignored, as in the reference program: the scene's `epsilon` (scene_t),
 * this by default. An absolute distance, so a scene scaled by s wants epsilon 1e-4 * s. */
#define TRACER_EPSILON 1e-4

typedef struct tracer tracer_t;

typedef struct {
    double t;
    vec3 x;         /* hit position o + d * t */
    vec3 n;         /* unit normal: outward for spheres; facing the ray for triangles */
    int material;
    int object;     /* sphere s: s; mesh m: num_spheres + m (the photon-map estimator groups by it) */
} hit_t;

tracer_t *tracer_create(const scene_t *scene, const stop_flag_t *stop, char *err, size_t errlen);
void tracer_destroy(tracer_t *tr);

/* Closest hit along o + t d, t > epsilon; returns 1 and fills *hit, or 0 on a miss.
 * d need not be unit length for spheres but must be for consistent epsilons. Thread-safe. */
int tracer_intersect(const tracer_t *tr, vec3 o, vec3 d, hit_t *hit);

/* Seconds spent building the acceleration structure, and its triangle count. */
double tracer_build_seconds(const tracer_t *tr);

#endif
