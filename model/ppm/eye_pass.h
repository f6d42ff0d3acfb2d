// SPDX-License-Identifier: Apache-2.0
/* eye_pass.h: the ray-tracing pass: one ray through each pixel centre (or N jittered rays a
 * pixel, each of weight 1/N), followed through mirror and glass chains (glass branches into
 * reflected then refracted paths) to the first diffuse surface, where a hit point is stored,
 * even one of weight zero. With see_lights, each segment
 * of the path that meets an area light's front face on its way (model/trace/emitters.h) adds
 * that light's radiance, times the path's throughput, to the pixel's emitted radiance: what the
 * camera sees of the lights directly and through mirrors and glass. The hit points do not
 * depend on see_lights.
 *
 * With N > 1, ray k (0 <= k < N) of pixel (x, y) passes through the point (x + f(H(0, k) + s),
 * y + f(H(1, k) + t)) of the image plane, f the fractional part, H the Halton sequence
 * (model/ppm/halton.h) and (s, t) in [0, 1)^2 from the pixel's index (eye_jitter_shift: a
 * Cranley-Patterson rotation, so that neighbouring pixels do not share one pattern).
 *
 * The result is in the reference program's creation order (pixels row by row from the top,
 * then path order) for any thread count. Returns 0, or -1 with err filled (out of memory, or
 * STOP_MESSAGE when stop was set: rows are polled, so a stop is seen within a few rows). */
#ifndef PREE_EYE_PASS_H
#define PREE_EYE_PASS_H

#include "hitpoints.h"
#include "scene.h"
#include "stop.h"
#include "tracer.h"

typedef struct {
    unsigned long long rays;          /* eye ray segments traced */
    unsigned long long glass_splits;  /* glass hits that branched into two paths */
    unsigned long long emitter_hits;  /* segments that met an area light's front face */
} eye_stats_t;

#define EYE_RAYS_MAX 256

typedef struct {
    int width, height;   /* the image */
    int rays;            /* eye rays a pixel, 1..EYE_RAYS_MAX (0 or 1: one, through the centre) */
    int see_lights;      /* 1: the emitted radiance the eye paths meet (*emitted) */
    int stride;          /* 0 or 1: every pixel; s > 1: the pixels (x, y) with x mod s = y mod s = s / 2
                          * only, a sample (pree check's hit-point estimate) */
} eye_pass_opts_t;

/* 0 when every eye ray of a width x height image starts within +-1e17 and has a direction
 * (what the tracer takes), else -1 with a one-line message in err. */
int eye_camera_check(const camera_t *cam, int width, int height, char *err, size_t errlen);

/* The hit points into out; *emitted: 3 doubles a pixel (malloc'd, the caller frees), or NULL
 * when see_lights is 0 or no eye path met a light. */
int eye_pass(const scene_t *scene, const tracer_t *tr, const eye_pass_opts_t *opts, hitpoints_t *out,
             double **emitted, eye_stats_t *stats, const stop_flag_t *stop, char *err, size_t errlen);

#endif
