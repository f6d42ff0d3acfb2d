// SPDX-License-Identifier: Apache-2.0
/* render_radiance.c: the session's radiance phase (render_radiance, render.h) and the series'
 * images (render_radiance.h): under MPI the ranks' state gathered to rank 0 (render_round.h), the
 * photon pass's memory freed (render_step.h), then the photon pass's totals, the hit points back
 * in address order, the radiance of each into its pixel through the PREE's radiance pass
 * (model/ppm/radiance.h), the result checks and the hashes. */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include "hp_order.h"
#include "radiance.h"
#include "render_check.h"
#include "render_radiance.h"
#include "render_round.h"
#include "render_step.h"

/* The PREE (or board) whose radiance pass the fp32 image reproduces (opt: preu, pipe_fast, layout,
 * prees). With
 * the spatial layout its address a holds the a-th hit point of the spatial order of one part, the
 * co-simulation's (its photon pass runs on one thread): s->perm when this photon pass ran on one
 * thread too, else that order made here into *made (the caller frees it), so that the image does
 * not depend on the thread count. 0, or -1 (memory). */
static int radiance_pree(const render_session_t *s, radiance_pree_t *pree, uint32_t **made)
{
    const hitpoints_t *h = &s->res->hp;
    *pree = (radiance_pree_t){.preu = s->opt.preu ? s->opt.preu : 4, .stages = radiance_depth(s->opt.pipe_fast),
                              .n = h->n, .prees = s->opt.prees};
    *made = NULL;
    if (s->opt.precision != PRECISION_FP32 || (s->opt.layout == HP_LAYOUT_PIXEL && s->opt.prees <= 1)) return 0;
    if (s->T == 1) {
        pree->at = s->perm;
        return 0;
    }
    pree->at = *made = hp_order_spatial(h, s->opt.width, 1, s->res->stats.r0);
    return *made ? 0 : -1;
}

/* The radiance of res->hp (in address order) for `photons` photons into res->rgb, and the
 * hashes: 0, or -1 with err. */
static int evaluate(render_session_t *s, uint64_t photons, char *err, size_t errlen)
{
    render_result_t *res = s->res;
    render_stats_t *st = &res->stats;
    double t = omp_get_wtime();
    radiance_pree_t pree;
    uint32_t *made;
    const int rad = radiance_pree(s, &pree, &made) ? -1
                  : radiance_evaluate_preu(&res->hp, s->opt.precision, &pree, photons, s->skip, res->rgb, s->npix,
                                           &st->radiance_skipped);
    free(made);
    if (rad) {
        snprintf(err, errlen, "out of memory in radiance evaluation");
        return -1;
    }
    radiance_add_emitted(res->rgb, res->emitted, s->npix, s->opt.precision);   /* what the camera sees of the lights */
    st->sec_radiance = omp_get_wtime() - t;
    if (s->opt.precision == PRECISION_FP32 && render_fp32_result_check(res, err, errlen)) return -1;
    render_hash_results(res, s->opt.precision);
    return 0;
}

/* The counters the statistics report at the end of the photon pass (or at a series' point). */
static void pass_totals(render_session_t *s)
{
    render_stats_t *st = &s->res->stats;
    if (s->nranks <= 1) st->upd = render_session_update_totals(s);   /* MPI: render_round_close's sums */
    st->photon_hits_no_cell = s->bb->no_cell;
    st->photon_hits += s->bb->no_cell;
    st->photons_emitted = s->res->hp.n ? s->done_photons : s->emitted_target;
}

int render_radiance_snapshot(render_session_t *s, char *err, size_t errlen)
{
    render_result_t *res = s->res;
    const render_stats_t keep = res->stats;
    pass_totals(s);
    if (hp_order_restore(&res->hp, s->perm)) {
        snprintf(err, errlen, "out of memory for hit points");
        return -1;
    }
    int rc = evaluate(s, res->stats.photons_emitted, err, errlen);
    res->stats.sec_total = omp_get_wtime() - s->t_start;
    res->stats.sec_cpu = render_cpu_seconds() - s->cpu_start;
    res->stats.peak_rss_kb = render_peak_rss_kb();
    if (rc == 0 && s->opt.snapshot) rc = s->opt.snapshot(s->opt.snapshot_ctx, res, err, errlen);
    if (hp_order_apply(&res->hp, s->perm) && rc == 0) {
        snprintf(err, errlen, "out of memory for hit points");
        rc = -1;
    }
    res->stats = keep;
    return rc;
}

/* The end of the photon pass: its counters into the statistics, the hit points back in address
 * order, their radiance into res->rgb, the hashes. 0, or -1 with err. */
static int radiance_pass(render_session_t *s, char *err, size_t errlen)
{
    render_result_t *res = s->res;
    pass_totals(s);
    if (hp_order_restore(&res->hp, s->perm)) {
        snprintf(err, errlen, "out of memory for hit points");
        return -1;
    }
    return evaluate(s, res->stats.photons_emitted, err, errlen);
}

int render_radiance(render_session_t *s, char *err, size_t errlen)
{
    if (s->failed) return -1;
    if (s->interrupted && !s->done_photons) {
        snprintf(err, errlen, STOP_MESSAGE " during the first photon block");
        s->failed = 1;
        return -1;
    }
    if (s->nranks > 1) {
        s->res->stats.upd = render_session_update_totals(s);
        render_round_close(s);
        if (s->rank) return 0;   /* rank 0 evaluates and writes */
    }
    render_photon_pass_free(s);
    if (radiance_pass(s, err, errlen)) {
        s->failed = 1;
        return -1;
    }
    return 0;
}
