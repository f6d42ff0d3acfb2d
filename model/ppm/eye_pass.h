// SPDX-License-Identifier: Apache-2.0
/* eye_pass.h: the ray-tracing pass: one ray through each pixel centre, followed through
 * mirror and glass chains (glass branches into reflected then refracted paths) to the first
 * diffuse surface, where a hit point is stored, even one of weight zero.
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
} eye_stats_t;

/* 0 when every eye ray of a width x height image starts within +-1e17 and has a direction
 * (what the tracer takes), else -1 with a one-line message in err. */
int eye_camera_check(const camera_t *cam, int width, int height, char *err, size_t errlen);

int eye_pass(const scene_t *scene, const tracer_t *tr, int width, int height,
             hitpoints_t *out, eye_stats_t *stats, const stop_flag_t *stop, char *err, size_t errlen);

#endif
