// SPDX-License-Identifier: Apache-2.0
/* render.c: the render driver: the session's set-up (phases in order, threads, the grid), the
 * radiance pass and the close.
 *
 * The photon pass (render_step.c) runs in blocks: photons of a block are traced in parallel into
 * ordered chunk buffers, then each thread updates the hit points it owns from all of the block's
 * (or the screening batch's) hits in photon order. So every hit point sees its photons in index
 * order, and the result does not depend on the number of threads. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "hp_order.h"
#include "cpu_features.h"
#include "grid_refilter.h"
#include "mem_check.h"
#include "photon_pass.h"
#include "radiance.h"
#include "checkpoint.h"
#include "render_check.h"
#include "render_dist.h"
#include "render_session.h"

/* Hit-point state before the first photon: radius r0, no photons, no flux; the update rule's
 * alpha and, in fp32 mode, the datapath's state layout, which holds the weight (so the double
 * weight is dropped). */
static int init_state(hitpoints_t *h, const render_options_t *opt, double r0)
{
    h->alpha = render_alpha(opt);
    h->alpha32 = preu_f32(h->alpha);
    h->kappa32 = preu_kappa(h->alpha32);
    if (opt->precision != PRECISION_FP32) return hitpoints_init_double(h, r0);
    const int stable = opt->datapath == DATAPATH_STABLE;
    const size_t n = h->n ? h->n : 1;
    if (stable) h->stable = malloc(n * sizeof *h->stable);
    else h->fp32 = malloc(n * sizeof *h->fp32);
    h->r2_f32 = malloc(n * sizeof *h->r2_f32);
    if (!(stable ? (void *)h->stable : (void *)h->fp32) || !h->r2_f32) return -1;
    const uint32_t r2 = preu_f32(r0 * r0);
    for (size_t i = 0; i < h->n; i++) {
        const hp_hot_t *p = &h->hot[i];
        const uint32_t pos[3] = {preu_f32(p->px), preu_f32(p->py), preu_f32(p->pz)};
        const uint32_t f[3] = {preu_f32(h->weight[i].x), preu_f32(h->weight[i].y), preu_f32(h->weight[i].z)};
        if (stable) {
            preu_shp_t *s = &h->stable[i];
            memcpy(s->pos, pos, sizeof pos);
            memcpy(s->f, f, sizeof f);
            preu_stable_init(s, r0 * r0);
            h->r2_f32[i] = preu_stable_screen_r2(s->w);
        } else {
            preu_hp_t *s = &h->fp32[i];
            memcpy(s->pos, pos, sizeof pos);
            memcpy(s->f, f, sizeof f);
            s->tau[0] = s->tau[1] = s->tau[2] = 0;
            s->r2 = r2;
            s->n = 0;
            h->r2_f32[i] = r2;
        }
    }
    return hitpoints_drop_weight(h);
}

/* What only the photon pass uses: the grid, the traced hits and the candidate lists (freed before
 * the radiance pass, so that its peak does not add to theirs). */
static void free_photon_pass(render_session_t *s)
{
    if (s->bb)
        for (unsigned c = 0; c < TRACE_CHUNKS * SCREEN_BLOCKS_MAX; c++) photon_hits_free(&s->bb->chunk[c]);
    grid_free(&s->grid);
    update_prefilter_free(&s->prefilter);
    update_batch_free(&s->batch);
    if (s->scratch)
        for (int p = 0; p < s->T; p++) update_batch_scratch_free(&s->scratch[p]);
}

static void session_free(render_session_t *s)
{
    free_photon_pass(s);
    free(s->bb);
    free(s->perm);
    free(s->owner);
    free(s->owner_end);
    free(s->scratch);
    free(s->ust);
    update_ops_free(&s->ops);
    tracer_destroy(s->tr);
    free(s->own_lo);
    free(s->counts);
    render_dist_exchange_wait(s->pending);   /* a failed or stopped render's exchange in flight */
    for (int k = 0; k < 2; k++) {
        free(s->slot[k].send);
        free(s->slot[k].recv);
        free(s->slot[k].sendcounts);
        free(s->slot[k].recvcounts);
    }
    free(s->rank_of);
    update_batch_scratch_free(&s->xs);
    free(s->rhits);
    free(s->rhit_ptr);
    free(s->recvbuf);
    free(s);
}

/* A set-up step begins: *phase names it (an interrupt's message says where it stopped), the test
 * hook may stop the render there, and the step's start time is returned. */
static double step_begin(const char **phase, const char *name, const char *hook)
{
    *phase = name;
    render_test_interrupt(hook);
    return omp_get_wtime();
}

/* render_open's BVH build and eye pass: the hit points, their figures, the memory check with
 * their true count. *phase names the step under way. Returns 0 or -1 (err filled). */
static int open_eye(render_session_t *s, const char **phase, char *err, size_t errlen)
{
    const render_options_t *opt = &s->opt;
    render_result_t *res = s->res;
    render_stats_t *st = &res->stats;
    double t = step_begin(phase, "BVH build", "bvh");
    s->tr = tracer_create(s->scene, opt->interrupt, err, errlen);
    if (!s->tr) return -1;
    st->sec_bvh = omp_get_wtime() - t;
    t = step_begin(phase, "eye pass", "eye");
    eye_stats_t es;
    if (eye_pass(s->scene, s->tr, opt->width, opt->height, &res->hp, &es, opt->interrupt, err, errlen)) return -1;
    if (opt->checkpoint || opt->resume) s->fingerprint = checkpoint_fingerprint(s->scene, opt, &res->hp);
    st->sec_eye = omp_get_wtime() - t;
    st->hit_points = res->hp.n;
    if (mem_check((uint64_t)res->hp.n * MEM_HIT_POINT_BYTES, opt->max_memory, "the hit points' state and grid",
                  err, errlen))
        return -1;
    st->eye_rays = es.rays;
    st->glass_splits = es.glass_splits;
    for (size_t i = 0; i < res->hp.n; i++) st->hit_points_zero_weight += hitpoints_zero_weight(&res->hp, i);
    return 0;
}

/* The spatial order sorts the hit points by owning part first, so the owners are ranges: the
 * screening's routing compares with their ends instead of reading owner[] (a miss a kept
 * candidate at 1600x1200), and one rank frees owner[] (2 bytes a hit point). 0, or -1 (memory). */
static int owner_ranges(render_session_t *s)
{
    const size_t n = s->res->hp.n;
    s->owner_end = malloc((size_t)s->T * sizeof *s->owner_end);
    if (!s->owner_end) return -1;
    size_t i = 0;
    for (int p = 0; p < s->T; p++) {
        while (i < n && s->owner[i] == p) i++;
        s->owner_end[p] = (uint32_t)i;
    }
    if (i < n) {   /* not sorted by part: keep owner[] */
        free(s->owner_end);
        s->owner_end = NULL;
    } else if (s->nranks <= 1) {   /* the ranges say it all (the distributed render reads owner[]) */
        free(s->owner);
        s->owner = NULL;
    }
    return 0;
}

/* render_open's grid step: the initial radius, the spatial order of the hit points, their
 * state, the owners and the grid. *phase names the step under way. Returns 0 or -1 (err filled). */
static int open_grid(render_session_t *s, const char **phase, char *err, size_t errlen)
{
    const render_options_t *opt = &s->opt;
    render_result_t *res = s->res;
    render_stats_t *st = &res->stats;
    const double t = step_begin(phase, "grid build", "grid");
    st->r0 = grid_initial_radius(&res->hp, opt->width, opt->height);
    for (size_t i = 0; i < res->hp.n; i++) {   /* fp32 holds positions to about |x| 2^-24 */
        const hp_hot_t *p = &res->hp.hot[i];
        const double m = fmax(fabs(p->px), fmax(fabs(p->py), fabs(p->pz)));
        if (m > st->hp_coord_max) st->hp_coord_max = m;
    }
    if (res->hp.n && !(st->r0 > 0)) {   /* e.g. a 1x1 image: one hit point, a box of size 0 */
        snprintf(err, errlen, "the %zu hit point(s) lie at one place, so the initial radius (from their "
                 "bounding box) is 0: use a larger image", res->hp.n);
        return -1;
    }
    /* The photon pass holds the hit points in spatial order (model/ppm/hp_order.c); the state is
     * set per hit point, so it is made after the reordering, which then moves fewer arrays. */
    s->perm = hp_order_spatial(&res->hp, opt->width, s->T, st->r0);
    if (!s->perm || hp_order_apply(&res->hp, s->perm)) { snprintf(err, errlen, "out of memory for hit points"); return -1; }
    if (init_state(&res->hp, opt, st->r0)) { snprintf(err, errlen, "out of memory for hit points"); return -1; }
    /* The photon-major scan reads a grid part per thread; the bucket-major screening reads one
     * grid of every hit point and routes what it keeps to the owning part. */
    s->photon_major = opt->record_ops || opt->scan == SCAN_PHOTON;
    if (render_screen_blocks_set(s, err, errlen)) return -1;
    s->owner = malloc((res->hp.n ? res->hp.n : 1) * sizeof *s->owner);
    if (!s->owner) { snprintf(err, errlen, "out of memory for hit points"); return -1; }
    for (size_t i = 0; i < res->hp.n; i++) s->owner[i] = (uint16_t)grid_owner(&res->hp, i, opt->width, s->T);
    if (render_round_open(s, err, errlen)) return -1;
    if (owner_ranges(s)) { snprintf(err, errlen, "out of memory for hit points"); return -1; }
    if (res->hp.n && grid_build(&s->grid, opt->grid, &res->hp, st->r0, opt->width, s->photon_major ? s->T : 1,
                                !s->skip, opt->interrupt, err, errlen))
        return -1;
    /* The screening's prefilter: bucket-major with the skips, at the chosen vector level. */
    if (!s->photon_major && s->skip && update_prefilter_build(&s->prefilter, &res->hp, &s->grid, cpu_simd_level())) {
        snprintf(err, errlen, "out of memory for the grid");
        return -1;
    }
    st->r_safe = s->grid.r_safe;
    for (int p = 0; p < s->grid.num_parts; p++) st->grid_entries += s->grid.parts[p].num_entries;
    st->grid_entries_final = st->grid_entries;
    st->hit_point_bytes = hitpoints_bytes_each(&res->hp);
    st->grid_entry_bytes = GRID_ENTRY_BYTES;
    st->sec_grid = omp_get_wtime() - t;
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
    render_stats_t *st = &res->stats;
    s->t_start = omp_get_wtime();
    s->cpu_start = render_cpu_seconds();
    const char *phase = "set-up";
    if (!(opt->alpha == 0 || (opt->alpha > 0 && opt->alpha <= 1))) {
        snprintf(err, errlen, "alpha %g is not in (0, 1]", opt->alpha);
        goto fail;
    }
    if (opt->record_ops && opt->precision != PRECISION_FP32) {
        snprintf(err, errlen, "recording the PREE operations needs --precision fp32");
        goto fail;
    }
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
    s->T = opt->record_ops ? 1 : omp_get_max_threads();
    render_stats_scene(st, scene);
    st->threads = s->T;
    s->skip = !opt->no_skip && opt->grid == GRID_CELLS;
    s->npix = (size_t)opt->width * (size_t)opt->height;
    /* Memory: before anything large, with one hit point a pixel; again with the true count. */
    if (mem_check(mem_estimate_start(st->scene_triangles, s->npix), opt->max_memory, MEM_START_WHAT, err, errlen))
        goto fail;
    s->bb = calloc(1, sizeof *s->bb);
    res->rgb = calloc(s->npix * 3, sizeof *res->rgb);
    if (!s->bb || !res->rgb) { snprintf(err, errlen, "out of memory for a %dx%d image", opt->width, opt->height); goto fail; }
    res->width = opt->width;
    res->height = opt->height;

    if (open_eye(s, &phase, err, errlen) || open_grid(s, &phase, err, errlen)) goto fail;

    s->emitted_target = render_emitted(opt->photons);
    s->ust = calloc((size_t)s->T, sizeof *s->ust);
    s->scratch = calloc((size_t)s->T, sizeof *s->scratch);
    if (!s->ust || !s->scratch) { snprintf(err, errlen, "out of memory"); goto fail; }
    if (opt->resume && render_session_resume(s, err, errlen)) goto fail;
    s->t_photons = omp_get_wtime();
    return s;
fail:
    if (stop_requested(opt->interrupt)) snprintf(err, errlen, STOP_MESSAGE " during the %s", phase);
    session_free(s);
    return NULL;
}

const update_ops_t *render_block_ops(const render_session_t *s) { return &s->ops; }

const uint32_t *render_hp_address(const render_session_t *s) { return s->perm; }

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

int render_session_snapshot(render_session_t *s, char *err, size_t errlen)
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

int render_close(render_session_t *s, char *err, size_t errlen)
{
    render_result_t *res = s->res;
    render_stats_t *st = &res->stats;
    int rc = -1;
    if (s->failed) goto done;
    if (s->interrupted && !s->done_photons) { snprintf(err, errlen, STOP_MESSAGE " during the first photon block"); goto done; }
    if (s->nranks > 1) {
        st->upd = render_session_update_totals(s);
        render_round_close(s);
        if (s->rank) {   /* rank 0 evaluates and writes */
            rc = s->interrupted ? 1 : 0;
            goto done;
        }
    }
    free_photon_pass(s);
    pass_totals(s);
    if (hp_order_restore(&res->hp, s->perm)) { snprintf(err, errlen, "out of memory for hit points"); goto done; }
    if (evaluate(s, st->photons_emitted, err, errlen)) goto done;
    rc = s->interrupted ? 1 : 0;
done:
    st->sec_total = omp_get_wtime() - s->t_start;
    st->sec_cpu = render_cpu_seconds() - s->cpu_start;
    session_free(s);
    st->peak_rss_kb = render_peak_rss_kb();
    if (st->hit_points) st->peak_bytes_per_hit_point = 1024.0 * (double)st->peak_rss_kb / (double)st->hit_points;
    return rc;
}

update_stats_t render_session_update_totals(const render_session_t *s)
{
    update_stats_t u = {0, 0, 0, 0};
    for (int p = 0; p < s->T; p++) {
        u.candidates += s->ust[p].candidates;
        u.skipped_radius += s->ust[p].skipped_radius;
        u.normal_passed += s->ust[p].normal_passed;
        u.accepted += s->ust[p].accepted;
    }
    return u;
}
