/* stats_json.c: render statistics in JSON (keys: docs/engine.md, "Statistics"). */
#include "json_file.h"
#include "stats_json.h"

static const char *grid_name(grid_kind_t g)
{
    return g == GRID_SMALLPPM ? "smallppm" : g == GRID_BRUTE ? "brute" : "cells";
}

static json_t *scene_contents(const render_stats_t *st)
{
    json_t *o = json_object();
    json_set_u64(o, "spheres", st->scene_spheres);
    json_set_u64(o, "triangles", st->scene_triangles);
    json_set_u64(o, "lights", st->scene_lights);
    json_set_bool(o, "mirror", st->scene_mirror);
    json_set_bool(o, "glass", st->scene_glass);
    return o;
}

static json_t *phase_seconds(const render_stats_t *st)
{
    json_t *o = json_object();
    json_set_real(o, "bvh", st->sec_bvh);
    json_set_real(o, "eye", st->sec_eye);
    json_set_real(o, "grid", st->sec_grid);
    json_set_real(o, "trace", st->sec_trace);
    json_set_real(o, "update", st->sec_update);
    json_set_real(o, "radiance", st->sec_radiance);
    json_set_real(o, "total", st->sec_total);
    return o;
}

static void set_hash(json_t *o, const char *key, uint64_t h)
{
    char s[17];
    snprintf(s, sizeof s, "%016llx", (unsigned long long)h);
    json_set_str(o, key, s);
}

json_t *stats_json(const char *scene, const render_options_t *opt, const render_stats_t *st, int interrupted)
{
    json_t *o = json_object();
    if (!o) return NULL;
    json_set_str(o, "scene", scene);
    json_set_u64(o, "width", (uint64_t)opt->width);
    json_set_u64(o, "height", (uint64_t)opt->height);
    json_set_str(o, "precision", opt->precision == PRECISION_FP32 ? "fp32" : "double");
    json_set_str(o, "grid", grid_name(opt->grid));
    json_set_bool(o, "skips", !opt->no_skip && opt->grid == GRID_CELLS);
    json_set_u64(o, "threads", (uint64_t)st->threads);
    json_set_u64(o, "hit_points_saturated", st->hit_points_saturated);
    json_set_str(o, "datapath", opt->precision != PRECISION_FP32 ? "none"
                                : opt->datapath == DATAPATH_STABLE ? "stable" : "paper");
    json_set_real(o, "alpha", render_alpha(opt));
    json_set_bool(o, "interrupted", interrupted);
    json_set_bool(o, "time_limited", st->time_limited);
    json_set_u64(o, "photons_resumed", st->photons_resumed);
    json_object_set_new(o, "scene_contents", scene_contents(st));
    json_set_u64(o, "hit_points", st->hit_points);
    json_set_u64(o, "hit_points_zero_weight", st->hit_points_zero_weight);
    json_set_u64(o, "eye_rays", st->eye_rays);
    json_set_u64(o, "glass_splits", st->glass_splits);
    json_set_real(o, "initial_radius", st->r0);
    json_set_real(o, "safe_radius", st->r_safe);
    json_set_u64(o, "grid_entries", st->grid_entries);
    json_set_u64(o, "photons_emitted", st->photons_emitted);
    json_set_u64(o, "photon_offset", opt->photon_offset);
    json_set_u64(o, "photon_segments", st->photon_segments);
    json_set_u64(o, "photon_hits", st->photon_hits);
    json_set_u64(o, "skip_photon_hits_no_cell", st->photon_hits_no_cell);
    json_set_u64(o, "hpuo_candidates", st->upd.candidates);
    json_set_u64(o, "skip_candidates_outside_radius", st->upd.skipped_radius);
    json_set_u64(o, "hpuo_normal_passed", st->upd.normal_passed);
    json_set_u64(o, "hpuo_accepted", st->upd.accepted);
    json_set_u64(o, "skip_radiance_zero_weight", st->radiance_skipped);
    json_object_set_new(o, "peak_rss_kib", json_integer(st->peak_rss_kb));
    set_hash(o, "image_hash", st->image_hash);
    set_hash(o, "state_hash", st->state_hash);
    json_set_real(o, "update_mcand_per_s", st->sec_update > 0 ? st->upd.candidates / st->sec_update / 1e6 : 0.0);
    json_object_set_new(o, "seconds", phase_seconds(st));
    return o;
}

int stats_json_write(const char *path, const char *scene, const render_options_t *opt,
                     const render_stats_t *st, int interrupted, char *err, size_t errlen)
{
    return json_file_write(path, stats_json(scene, opt, st, interrupted), err, errlen);
}
