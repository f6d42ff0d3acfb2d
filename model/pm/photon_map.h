// SPDX-License-Identifier: Apache-2.0
/* photon_map.h: Jensen's photon map for the photon-mapping estimator (--estimator pm): every
 * diffuse hit of photons offset .. offset + n - 1, traced exactly as the PPM photon pass traces
 * them (photon_trace), held in photon order whatever the thread count.
 *
 * Tracing is split into task units of `task` photons that a pool of threads takes from a
 * shared queue (paper 001: basic task units, a thread pool, load balance): OpenMP's dynamic
 * schedule is that queue; the static schedule (each thread a fixed share) is kept to compare.
 * Each unit's hits land in its own buffer, concatenated in unit order afterwards. */
#ifndef PREE_PHOTON_MAP_H
#define PREE_PHOTON_MAP_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>
#include "scene.h"
#include "tracer.h"

typedef struct {
    double x[3];       /* position */
    float n[3];        /* surface normal at the hit (outward, as the PPM update sees it) */
    float pad;
    double flux[3];    /* photon flux arriving */
} pm_photon_t;

typedef struct {
    pm_photon_t *p;
    size_t n;
    uint64_t emitted;                /* photons emitted (the estimator's N) */
    unsigned long long segments;     /* ray segments traced */
    /* The tracing's load balance (paper 001): the work of the longest task unit and photon
     * path (segments; they repeat exactly), and the CPU seconds the busiest and the least busy
     * thread spent tracing (the schedule's balance; they vary from run to run). */
    unsigned long long unit_segments_max;
    unsigned path_segments_max;
    double thread_busy_max, thread_busy_min;
} photon_map_t;

typedef struct {
    uint64_t photons, offset;        /* photons offset .. offset + photons - 1 */
    uint32_t task;                   /* photons per task unit (>= 1) */
    int dynamic;                     /* 1: units from a shared queue; 0: static shares */
    int threads;                     /* 0: OpenMP's default */
    volatile sig_atomic_t *interrupt; /* polled between units; NULL: never */
} photon_map_opts_t;

/* Trace and store. 0, 1 when interrupted (the map holds whole units of 1000 photons traced so
 * far, emitted set to match), or -1 with err filled (out of memory). */
int photon_map_build(const scene_t *scene, const tracer_t *tr, const photon_map_opts_t *opt,
                     photon_map_t *map, char *err, size_t errlen);
void photon_map_free(photon_map_t *map);

#endif
