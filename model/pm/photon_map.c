// SPDX-License-Identifier: Apache-2.0
/* photon_map.c: photons traced in task units by a thread pool into the photon map. */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "photon_map.h"
#include "photon_pass.h"
#include "pm_estimate.h"

typedef struct {
    photon_hits_t hits;
    unsigned path_max;   /* segments of its longest photon path */
    int failed;
} unit_t;

/* Trace unit u unless interrupted (done[u] set when traced): the thread's CPU seconds it took. */
static double trace_unit(const scene_t *scene, const tracer_t *tr, const photon_map_opts_t *o, uint64_t u,
                         uint64_t units, unit_t *out, unsigned char *done)
{
    if (o->interrupt && *o->interrupt) return 0;
    const double t = pm_thread_cpu_now();
    uint64_t first = u * o->task, last = u + 1 == units ? o->photons : first + o->task;
    for (uint64_t k = first; k < last && !out->failed; k++) {
        const unsigned long long before = out->hits.segments;
        if (photon_trace(scene, tr, o->offset + k, &out->hits)) out->failed = 1;
        const unsigned len = (unsigned)(out->hits.segments - before);
        if (len > out->path_max) out->path_max = len;
    }
    done[u] = 1;
    return pm_thread_cpu_now() - t;
}

/* The balance figures of units [0, done) and of the threads' busy CPU seconds (busy[t] < 0:
 * thread t took no part). */
static void balance(const unit_t *u, uint64_t done, const double *busy, int threads, photon_map_t *map)
{
    for (uint64_t k = 0; k < done; k++) {
        if (u[k].hits.segments > map->unit_segments_max) map->unit_segments_max = u[k].hits.segments;
        if (u[k].path_max > map->path_segments_max) map->path_segments_max = u[k].path_max;
    }
    map->thread_busy_min = -1;
    for (int t = 0; t < threads; t++) {
        if (busy[t] < 0) continue;
        if (busy[t] > map->thread_busy_max) map->thread_busy_max = busy[t];
        if (map->thread_busy_min < 0 || busy[t] < map->thread_busy_min) map->thread_busy_min = busy[t];
    }
    if (map->thread_busy_min < 0) map->thread_busy_min = 0;
}

/* Copy the hits of units [0, done) of photons below offset + emitted into the map, in unit order. */
static int gather(unit_t *units, uint64_t done, uint64_t offset, photon_map_t *map)
{
    size_t n = 0;
    for (uint64_t u = 0; u < done; u++) n += units[u].hits.n;
    map->p = malloc((n ? n : 1) * sizeof *map->p);
    if (!map->p) return -1;
    for (uint64_t u = 0; u < done; u++) {
        const photon_hits_t *h = &units[u].hits;
        for (size_t i = 0; i < h->n; i++) {
            const photon_hit_t *s = &h->hits[i];
            if (s->photon - offset >= map->emitted) continue;
            pm_photon_t *p = &map->p[map->n++];
            *p = (pm_photon_t){.x = {s->x.x, s->x.y, s->x.z}, .n = {(float)s->n.x, (float)s->n.y, (float)s->n.z},
                               .flux = {s->flux.x, s->flux.y, s->flux.z}};
        }
        map->segments += h->segments;
    }
    return 0;
}

int photon_map_build(const scene_t *scene, const tracer_t *tr, const photon_map_opts_t *o,
                     photon_map_t *map, char *err, size_t errlen)
{
    memset(map, 0, sizeof *map);
    const uint64_t units = (o->photons + o->task - 1) / o->task;
    const int threads = o->threads > 0 ? o->threads : omp_get_max_threads();
    unit_t *u = calloc(units ? units : 1, sizeof *u);
    unsigned char *done = calloc(units ? units : 1, 1);
    double *busy = malloc((size_t)threads * sizeof *busy);
    if (!u || !done || !busy) { free(u); free(done); free(busy); snprintf(err, errlen, "out of memory"); return -1; }
    for (int t = 0; t < threads; t++) busy[t] = -1;
#pragma omp parallel num_threads(threads)
    {
        double mine = 0;
        if (o->dynamic) {
#pragma omp for schedule(dynamic, 1) nowait
            for (uint64_t k = 0; k < units; k++) mine += trace_unit(scene, tr, o, k, units, &u[k], done);
        } else {
#pragma omp for schedule(static) nowait
            for (uint64_t k = 0; k < units; k++) mine += trace_unit(scene, tr, o, k, units, &u[k], done);
        }
        busy[omp_get_thread_num()] = mine;
    }
    /* Interrupted: keep the longest prefix of finished units, cut to whole 1000s of photons. */
    uint64_t prefix = 0;
    int failed = 0;
    while (prefix < units && done[prefix]) prefix++;
    for (uint64_t k = 0; k < units; k++) failed |= u[k].failed;
    int rc = failed ? -1 : prefix < units ? 1 : 0;
    map->emitted = rc == 1 ? prefix * o->task / 1000 * 1000 : o->photons;
    if (rc >= 0 && gather(u, prefix, o->offset, map)) rc = -1;
    if (rc >= 0) balance(u, prefix, busy, threads, map);
    free(busy);
    for (uint64_t k = 0; k < units; k++) photon_hits_free(&u[k].hits);
    free(u);
    free(done);
    if (rc < 0) { photon_map_free(map); snprintf(err, errlen, "out of memory"); }
    return rc;
}

void photon_map_free(photon_map_t *map)
{
    free(map->p);
    memset(map, 0, sizeof *map);
}
