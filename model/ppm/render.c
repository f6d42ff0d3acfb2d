// SPDX-License-Identifier: Apache-2.0
/* render.c: the render session's open and close (render.h), the first and last of its phases,
 * which render_run.c and a caller that steps the session itself (the co-simulation) both call:
 * render_open takes the session's own set-up (the options only it checks, the threads, the memory
 * estimate, the image); render_close the times and peak memory of the whole and the release. The
 * phases between are each in their module: the eye pass (render_eye_pass, render_setup.c), the
 * photon rounds (render_step.c) and the radiance (render_radiance, render_radiance.c).
 *
 * The photon pass (render_step.c) runs in blocks: photons of a block are traced in parallel into
 * ordered chunk buffers, then each thread updates the hit points it owns from all of the block's
 * (or the screening batch's) hits in photon order. So every hit point sees its photons in index
 * order, and the result does not depend on the number of threads. */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mem_check.h"
#include "render_round.h"
#include "render_step.h"

static void session_free(render_session_t *s)
{
    render_photon_pass_free(s);
    free(s->bb);
    free(s->perm);
    free(s->owner);
    free(s->owner_end);
    free(s->scratch);
    free(s->ust);
    update_ops_free(&s->ops);
    tracer_destroy(s->tr);
    render_round_free(s);
    free(s);
}

/* The session's own set-up: the options that only it checks, the threads, the memory estimate
 * with one hit point a pixel, the image and the block buffers. 0, or -1 with err. */
static int open_session(render_session_t *s, char *err, size_t errlen)
{
    const render_options_t *opt = &s->opt;
    render_result_t *res = s->res;
    render_stats_t *st = &res->stats;
    if (!(opt->alpha == 0 || (opt->alpha > 0 && opt->alpha <= 1))) {
        snprintf(err, errlen, "alpha %g is not in (0, 1]", opt->alpha);
        return -1;
    }
    if (opt->eye_rays < 0 || opt->eye_rays > EYE_RAYS_MAX) {
        snprintf(err, errlen, "%d eye rays a pixel is not in 1..%d", opt->eye_rays, EYE_RAYS_MAX);
        return -1;
    }
    if (opt->record_ops && opt->precision != PRECISION_FP32) {
        snprintf(err, errlen, "recording the PREE operations needs --precision fp32");
        return -1;
    }
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
    s->T = opt->record_ops ? 1 : omp_get_max_threads();
    render_stats_scene(st, s->scene);
    st->threads = s->T;
    s->skip = !opt->no_skip && opt->grid == GRID_CELLS;
    s->npix = (size_t)opt->width * (size_t)opt->height;
    /* Memory: before anything large, with one hit point an eye ray; again with the true count. */
    if (mem_check(mem_estimate_start(st->scene_triangles, s->npix, opt->eye_rays > 1 ? (uint64_t)opt->eye_rays : 1),
                  opt->max_memory, MEM_START_WHAT, err, errlen))
        return -1;
    s->bb = calloc(1, sizeof *s->bb);
    res->rgb = calloc(s->npix * 3, sizeof *res->rgb);
    if (!s->bb || !res->rgb) {
        snprintf(err, errlen, "out of memory for a %dx%d image", opt->width, opt->height);
        return -1;
    }
    res->width = opt->width;
    res->height = opt->height;
    return 0;
}

render_session_t *render_open(const scene_t *scene, const render_options_t *opt, render_result_t *res,
                              char *err, size_t errlen)
{
    memset(res, 0, sizeof *res);
    render_session_t *s = calloc(1, sizeof *s);
    if (!s) { snprintf(err, errlen, "out of memory"); return NULL; }
    s->scene = scene;
    s->opt = *opt;
    s->res = res;
    s->t_start = omp_get_wtime();
    s->cpu_start = render_cpu_seconds();
    if (open_session(s, err, errlen)) {
        if (stop_requested(opt->interrupt)) snprintf(err, errlen, STOP_MESSAGE " during the set-up");
        session_free(s);
        return NULL;
    }
    return s;
}

const update_ops_t *render_block_ops(const render_session_t *s) { return &s->ops; }

const uint32_t *render_hp_address(const render_session_t *s) { return s->perm; }

int render_close(render_session_t *s)
{
    render_stats_t *st = &s->res->stats;
    const int rc = s->failed ? -1 : s->interrupted ? 1 : 0;
    st->sec_total = omp_get_wtime() - s->t_start;
    st->sec_cpu = render_cpu_seconds() - s->cpu_start;
    session_free(s);
    st->peak_rss_kb = render_peak_rss_kb();
    if (st->hit_points) st->peak_bytes_per_hit_point = 1024.0 * (double)st->peak_rss_kb / (double)st->hit_points;
    return rc;
}
