// SPDX-License-Identifier: Apache-2.0
/* stats_json.c: render statistics in JSON (keys: docs/engine.md, "Statistics"). */
#include <stdio.h>
#include "cpu_features.h"
#include "json_file.h"
#include "knn_kernel.h"
#include "stats_json.h"

#define S(member, kind) JSON_FIELD(render_stats_t, member, kind)
#define SK(member, kind, key) JSON_FIELD_AS(render_stats_t, member, kind, key)
#define N(a) (sizeof a / sizeof a[0])

static const json_field_t counts[] = {
    S(hit_points_saturated, JF_U64), S(hit_points, JF_U64), S(hit_points_zero_weight, JF_U64),
    S(eye_rays, JF_U64), S(glass_splits, JF_U64), S(emitter_hits, JF_U64), SK(r0, JF_REAL, "initial_radius"),
    SK(hp_coord_max, JF_REAL, "hit_point_coord_max"),
    SK(r_safe, JF_REAL, "safe_radius"), S(grid_entries, JF_U64), S(grid_entries_final, JF_U64),
    S(grid_refilters, JF_U64), S(photons_emitted, JF_U64),
    S(photon_segments, JF_U64), S(photon_hits, JF_U64), SK(photon_hits_no_cell, JF_U64, "skip_photon_hits_no_cell"),
    SK(upd.candidates, JF_U64, "hpuo_candidates"), SK(upd.skipped_radius, JF_U64, "skip_candidates_outside_radius"),
    SK(upd.normal_passed, JF_U64, "hpuo_normal_passed"), SK(upd.accepted, JF_U64, "hpuo_accepted"),
    SK(radiance_skipped, JF_U64, "skip_radiance_zero_weight"), SK(peak_rss_kb, JF_LONG, "peak_rss_kib"),
    S(peak_bytes_per_hit_point, JF_REAL), S(hit_point_bytes, JF_U64), S(grid_entry_bytes, JF_U64),
    S(image_hash, JF_HEX64), S(state_hash, JF_HEX64), S(time_limited, JF_BOOL), S(photons_resumed, JF_U64),
    S(mpi_ranks, JF_INT), S(mpi_bytes_sent, JF_U64), S(mpi_kept, JF_U64), S(mpi_kept_foreign, JF_U64),
};
static const json_field_t contents[] = {
    SK(scene_spheres, JF_U64, "spheres"), SK(scene_triangles, JF_U64, "triangles"),
    SK(scene_lights, JF_U64, "lights"), SK(scene_mirror, JF_BOOL, "mirror"), SK(scene_glass, JF_BOOL, "glass"),
};
static const json_field_t seconds[] = {
    SK(sec_bvh, JF_REAL, "bvh"), SK(sec_eye, JF_REAL, "eye"), SK(sec_grid, JF_REAL, "grid"),
    SK(sec_trace, JF_REAL, "trace"), SK(sec_update, JF_REAL, "update"), SK(sec_refilter, JF_REAL, "refilter"), SK(sec_radiance, JF_REAL, "radiance"),
    SK(sec_total, JF_REAL, "total"), SK(sec_cpu, JF_REAL, "cpu"),
};

#define P(member, kind) JSON_FIELD_AS(render_stats_t, pm.member, kind, #member)
static const json_field_t pm_fields[] = {
    P(photons_stored, JF_U64), P(k, JF_U64), P(max_radius, JF_REAL), P(clusters, JF_U64),
    P(clusters_sparse, JF_U64), P(widened, JF_U64), P(fallback, JF_U64), P(scope_photons, JF_U64), P(kernel_tests, JF_U64),
    P(distance_tests, JF_U64), P(selection, JF_U64), P(neighbours, JF_U64),
    P(short_of_k, JF_U64), P(coherent_fraction, JF_REAL), P(sec_map, JF_REAL), P(sec_tree, JF_REAL),
    P(sec_cluster, JF_REAL), P(sec_search, JF_REAL), P(cpu_map, JF_REAL), P(cpu_tree, JF_REAL),
    P(cpu_cluster, JF_REAL), P(cpu_search, JF_REAL), P(cpu_estimate, JF_REAL), P(cpu_query, JF_REAL),
    P(sec_query, JF_REAL), P(unit_segments_max, JF_U64), P(path_segments_max, JF_U64),
    P(thread_busy_max, JF_REAL), P(thread_busy_min, JF_REAL),
};

/* --knn-bench: each method's tree build, query seconds of every repetition, work and hash. */
static json_t *pm_bench_json(const pm_stats_t *st)
{
    static const char *const names[] = {"clustered", "naive", "kdtree"};
    json_t *o = json_object();
    json_set_u64(o, "reps", (uint64_t)st->bench_reps);
    for (int m = 0; m < 3; m++) {
        const pm_method_stats_t *b = &st->bench[m];
        if (!b->runs) continue;
        json_t *j = json_object(), *sec = json_array(), *cpu = json_array();
        char hash[17];
        for (int r = 0; r < b->runs; r++) {
            json_array_append_new(sec, json_real(b->sec[r]));
            json_array_append_new(cpu, json_real(b->cpu[r]));
        }
        json_set_real(j, "sec_tree", b->sec_tree);
        json_set_real(j, "cpu_tree", b->cpu_tree);
        json_object_set_new(j, "sec_query", sec);
        json_object_set_new(j, "cpu_query", cpu);
        json_set_u64(j, "distance_tests", b->distance_tests);
        json_set_u64(j, "kernel_tests", b->kernel_tests);
        json_set_u64(j, "selection", b->selection);
        json_set_u64(j, "clusters_sparse", b->clusters_sparse);
        json_set_u64(j, "widened", b->widened);
        json_set_u64(j, "fallback", b->fallback);
        snprintf(hash, sizeof hash, "%016llx", (unsigned long long)b->state_hash);
        json_set_str(j, "state_hash", hash);
        json_object_set_new(o, names[m], j);
    }
    return o;
}

const char *stats_grid_name(grid_kind_t g)
{
    return g == GRID_SMALLPPM ? "smallppm" : g == GRID_BRUTE ? "brute" : "cells";
}

const char *stats_datapath_name(const render_options_t *opt)
{
    return opt->precision != PRECISION_FP32 ? "none" : opt->datapath == DATAPATH_STABLE ? "stable" : "paper";
}

json_t *stats_json(const char *scene, const render_options_t *opt, const render_stats_t *st, int interrupted)
{
    json_t *o = json_object();
    if (!o) return NULL;
    json_set_str(o, "scene", scene);
    json_set_u64(o, "width", (uint64_t)opt->width);
    json_set_u64(o, "height", (uint64_t)opt->height);
    json_set_str(o, "precision", opt->precision == PRECISION_FP32 ? "fp32" : "double");
    json_set_str(o, "grid", stats_grid_name(opt->grid));
    json_set_bool(o, "skips", !opt->no_skip && opt->grid == GRID_CELLS);
    json_set_u64(o, "threads", (uint64_t)st->threads);
    json_set_str(o, "simd", cpu_simd_name(cpu_simd_level()));
    json_set_str(o, "datapath", stats_datapath_name(opt));
    json_set_real(o, "alpha", render_alpha(opt));
    if (opt->precision == PRECISION_FP32) {   /* the PREE whose radiance pass the image reproduces */
        json_set_u64(o, "preu", (uint64_t)(opt->preu ? opt->preu : 4));
        json_set_u64(o, "pipe_fast", (uint64_t)opt->pipe_fast);
        json_set_str(o, "hp_layout", opt->layout == HP_LAYOUT_PIXEL && opt->prees <= 1 ? "pixel" : "spatial");
        json_set_u64(o, "prees", (uint64_t)(opt->prees > 1 ? opt->prees : 1));
    }
    json_set_bool(o, "interrupted", interrupted);
    json_set_u64(o, "photon_offset", opt->photon_offset);
    json_set_u64(o, "max_bounces", (uint64_t)st->max_bounces);
    json_object_set_new(o, "scene_contents", json_fields(st, contents, N(contents)));
    json_set_fields(o, st, counts, N(counts));
    json_set_real(o, "update_mcand_per_s", st->sec_update > 0 ? st->upd.candidates / st->sec_update / 1e6 : 0.0);
    json_object_set_new(o, "seconds", json_fields(st, seconds, N(seconds)));
    if (opt->estimator == ESTIMATOR_PM) {
        json_t *pm = json_fields(st, pm_fields, N(pm_fields));
        static const char *const searches[] = {"clustered", "naive", "kdtree"};
        json_set_str(pm, "knn_search", searches[opt->knn_search]);
        if (opt->knn_search == KNN_CLUSTERED || st->pm.bench_reps) {
            json_t *calls = json_object();
            for (int i = KNN_KERNEL_SCALAR; i <= KNN_KERNEL_AVX512; i++)
                json_set_u64(calls, knn_kernel_name((knn_kernel_id_t)i), st->pm.kernel_calls[i]);
            json_set_str(pm, "kernel", knn_kernel_name(st->pm.kernel));
            json_object_set_new(pm, "kernel_calls", calls);
        }
        if (st->pm.bench_reps) json_object_set_new(pm, "bench", pm_bench_json(&st->pm));
        json_object_set_new(o, "pm", pm);
    }
    json_set_str(o, "estimator", opt->estimator == ESTIMATOR_PM ? "pm" : "ppm");
    return o;
}

int stats_json_write(const char *path, const char *scene, const render_options_t *opt,
                     const render_stats_t *st, int interrupted, char *err, size_t errlen)
{
    return json_file_write(path, stats_json(scene, opt, st, interrupted), err, errlen);
}
