/* stats_json.c: render statistics in JSON. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "stats_json.h"

static const char *grid_name(grid_kind_t g)
{
    return g == GRID_SMALLPPM ? "smallppm" : g == GRID_BRUTE ? "brute" : "cells";
}

void stats_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\') fprintf(f, "\\%c", *s);
        else if ((unsigned char)*s < 0x20) fprintf(f, "\\u%04x", *s);
        else fputc(*s, f);
    }
    fputc('"', f);
}

void stats_json_print(FILE *f, const char *scene, const render_options_t *opt,
                      const render_stats_t *st, int interrupted)
{
    fprintf(f, "{\n  \"scene\": ");
    stats_json_string(f, scene);
    fprintf(f, ",\n  \"width\": %d,\n  \"height\": %d,\n", opt->width, opt->height);
    fprintf(f, "  \"precision\": \"%s\",\n  \"grid\": \"%s\",\n  \"skips\": %s,\n  \"threads\": %d,\n",
            opt->precision == PRECISION_FP32 ? "fp32" : "double", grid_name(opt->grid),
            (!opt->no_skip && opt->grid == GRID_CELLS) ? "true" : "false", st->threads);
    fprintf(f, "  \"hit_points_saturated\": %llu,\n", st->hit_points_saturated);
    fprintf(f, "  \"datapath\": \"%s\",\n  \"alpha\": %.17g,\n",
            opt->precision != PRECISION_FP32 ? "none" : opt->datapath == DATAPATH_STABLE ? "stable" : "paper",
            render_alpha(opt));
    fprintf(f, "  \"interrupted\": %s,\n", interrupted ? "true" : "false");
    fprintf(f, "  \"time_limited\": %s,\n  \"photons_resumed\": %llu,\n", st->time_limited ? "true" : "false",
            st->photons_resumed);
    fprintf(f, "  \"scene_contents\": {\"spheres\": %llu, \"triangles\": %llu, \"lights\": %llu, "
               "\"mirror\": %s, \"glass\": %s},\n", st->scene_spheres, st->scene_triangles, st->scene_lights,
            st->scene_mirror ? "true" : "false", st->scene_glass ? "true" : "false");
    fprintf(f, "  \"hit_points\": %llu,\n  \"hit_points_zero_weight\": %llu,\n", st->hit_points, st->hit_points_zero_weight);
    fprintf(f, "  \"eye_rays\": %llu,\n  \"glass_splits\": %llu,\n", st->eye_rays, st->glass_splits);
    fprintf(f, "  \"initial_radius\": %.17g,\n  \"safe_radius\": %.17g,\n  \"grid_entries\": %zu,\n",
            st->r0, st->r_safe, st->grid_entries);
    fprintf(f, "  \"photons_emitted\": %llu,\n  \"photon_offset\": %llu,\n  \"photon_segments\": %llu,\n", st->photons_emitted,
            (unsigned long long)opt->photon_offset, st->photon_segments);
    fprintf(f, "  \"photon_hits\": %llu,\n  \"skip_photon_hits_no_cell\": %llu,\n", st->photon_hits, st->photon_hits_no_cell);
    fprintf(f, "  \"hpuo_candidates\": %llu,\n  \"skip_candidates_outside_radius\": %llu,\n",
            st->upd.candidates, st->upd.skipped_radius);
    fprintf(f, "  \"hpuo_normal_passed\": %llu,\n  \"hpuo_accepted\": %llu,\n", st->upd.normal_passed, st->upd.accepted);
    fprintf(f, "  \"skip_radiance_zero_weight\": %llu,\n", st->radiance_skipped);
    fprintf(f, "  \"peak_rss_kib\": %ld,\n", st->peak_rss_kb);
    fprintf(f, "  \"image_hash\": \"%016llx\",\n  \"state_hash\": \"%016llx\",\n",
            (unsigned long long)st->image_hash, (unsigned long long)st->state_hash);
    fprintf(f, "  \"update_mcand_per_s\": %.3f,\n", st->sec_update > 0 ? st->upd.candidates / st->sec_update / 1e6 : 0.0);
    fprintf(f, "  \"seconds\": {\"bvh\": %.6f, \"eye\": %.6f, \"grid\": %.6f, \"trace\": %.6f, \"update\": %.6f, "
               "\"radiance\": %.6f, \"total\": %.6f}\n}\n",
            st->sec_bvh, st->sec_eye, st->sec_grid, st->sec_trace, st->sec_update, st->sec_radiance, st->sec_total);
}

int stats_json_write(const char *path, const char *scene, const render_options_t *opt,
                     const render_stats_t *st, int interrupted, char *err, size_t errlen)
{
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) { snprintf(err, errlen, "%s: %s", path, strerror(errno)); return -1; }
    stats_json_print(f, scene, opt, st, interrupted);
    if (fclose(f) != 0 || rename(tmp, path) != 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        unlink(tmp);
        return -1;
    }
    return 0;
}
