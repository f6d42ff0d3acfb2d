// SPDX-License-Identifier: Apache-2.0
/* pm_render.c: the photon-map render: eye pass, photon map, search, image (see pm_render.h). */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fnv1a.h"
#include "grid.h"
#include "pm_estimate.h"
#include "pm_render.h"
#include "radiance.h"

static void phase(const render_options_t *opt, const char *what)
{
    if (opt->progress) fprintf(stderr, "pree render: pm: %s\n", what);
}

/* Eye pass and photon map. 0, 1 (interrupted while tracing), -1. */
static int trace(const scene_t *scene, const render_options_t *opt, tracer_t *tr, render_result_t *res,
                 photon_map_t *map, char *err, size_t errlen)
{
    render_stats_t *st = &res->stats;
    double t = omp_get_wtime();
    eye_stats_t es;
    phase(opt, "eye pass");
    res->hp.with_object = 1;   /* the clusters group by object */
    const eye_pass_opts_t eo = {opt->width, opt->height, opt->eye_rays, !opt->hide_lights, 1};
    if (eye_pass(scene, tr, &eo, &res->hp, &res->emitted, &es, opt->interrupt, err, errlen)) return -1;
    st->sec_eye = omp_get_wtime() - t;
    st->hit_points = res->hp.n;
    st->eye_rays = es.rays;
    st->glass_splits = es.glass_splits;
    st->emitter_hits = es.emitter_hits;
    st->r0 = opt->initial_radius > 0 ? opt->initial_radius : res->hp.n ? grid_initial_radius(&res->hp, opt->width, opt->height) : 0;
    t = omp_get_wtime();
    double c0 = pm_cpu_now();
    photon_map_opts_t mo = {render_emitted(opt->photons), opt->photon_offset,
                            (uint32_t)(opt->task_photons > 0 ? opt->task_photons : 1000), !opt->task_static,
                            st->threads, opt->interrupt};
    phase(opt, "photon map");
    int rc = photon_map_build(scene, tr, &mo, map, err, errlen);
    st->pm.sec_map = st->sec_trace = omp_get_wtime() - t;
    st->pm.cpu_map = pm_cpu_now() - c0;
    st->photons_emitted = map->emitted;
    st->photon_hits = map->n;
    st->photon_segments = map->segments;
    st->pm.unit_segments_max = map->unit_segments_max;
    st->pm.path_segments_max = map->path_segments_max;
    st->pm.thread_busy_max = map->thread_busy_max;
    st->pm.thread_busy_min = map->thread_busy_min;
    return rc;
}

int pm_render(const scene_t *scene, const render_options_t *opt, render_result_t *res, char *err, size_t errlen)
{
    memset(res, 0, sizeof *res);
    render_stats_t *st = &res->stats;
    const double t0 = omp_get_wtime(), cpu0 = render_cpu_seconds();
    if (opt->precision != PRECISION_DOUBLE) {
        snprintf(err, errlen, "the photon-map estimator runs in double precision only (--precision fp32 is the PREE's)");
        return -1;
    }
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
    st->threads = omp_get_max_threads();
    render_stats_scene(st, scene);
    const size_t npix = (size_t)opt->width * (size_t)opt->height;
    res->width = opt->width;
    res->height = opt->height;
    res->rgb = calloc(npix * 3, sizeof *res->rgb);
    if (!res->rgb) { snprintf(err, errlen, "out of memory for a %dx%d image", opt->width, opt->height); return -1; }
    double t = omp_get_wtime();
    tracer_t *tr = tracer_create(scene, opt->interrupt, err, errlen);
    if (!tr) return -1;
    st->sec_bvh = omp_get_wtime() - t;
    photon_map_t map = {0};
    int rc = trace(scene, opt, tr, res, &map, err, errlen);
    tracer_destroy(tr);
    double *L = rc < 0 ? NULL : malloc((res->hp.n ? res->hp.n : 1) * 3 * sizeof *L);
    if (rc >= 0 && !L) { snprintf(err, errlen, "out of memory for hit points"); rc = -1; }
    if (rc >= 0) {
        pm_estimate_opts_t eo = {opt->knn_k > 0 ? (size_t)opt->knn_k : 50, opt->max_radius > 0 ? opt->max_radius : st->r0,
                                 opt->knn_search, opt->cluster_bundle > 0 ? (size_t)opt->cluster_bundle : 2000,
                                 st->threads, opt->knn_kernel, opt->knn_bench,
                                 opt->knn_bench_oracle < 0 ? 0 : opt->knn_bench_oracle ? opt->knn_bench_oracle : -1};
        static const char *const what[] = {"search (clustered)", "search (naive: nanoflann, the oracle)",
                                           "search (kdtree: single pass)"};
        phase(opt, what[eo.search]);
        t = omp_get_wtime();
        if (pm_estimate(&res->hp, &map, &eo, L, &st->pm, err, errlen)) rc = -1;
        st->sec_update = omp_get_wtime() - t;
    }
    if (rc >= 0) {
        /* Pixels summed in hit-point order: the same bits for any thread count. */
        for (size_t i = 0; i < res->hp.n; i++)
            for (int a = 0; a < 3; a++) res->rgb[(size_t)res->hp.pixel[i] * 3 + a] += L[3 * i + a];
        radiance_add_emitted(res->rgb, res->emitted, npix, PRECISION_DOUBLE);
        st->image_hash = fnv1a(FNV1A_BASIS, res->rgb, npix * 3 * sizeof *res->rgb);
        st->state_hash = fnv1a(FNV1A_BASIS, L, res->hp.n * 3 * sizeof *L);
    }
    free(L);
    photon_map_free(&map);
    st->sec_total = omp_get_wtime() - t0;
    st->sec_cpu = render_cpu_seconds() - cpu0;
    st->peak_rss_kb = render_peak_rss_kb();
    return rc;
}
