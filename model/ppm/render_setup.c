// SPDX-License-Identifier: Apache-2.0
/* render_setup.c: the session's eye pass (render_eye_pass, render.h), in its steps (see
 * render_setup.h): the BVH and the eye pass, then the grid: the initial radius, the hit points in
 * spatial order with their initial state, their owning threads (and ranks, render_round.h) and
 * the grid of their cells; then the photon pass's counters (render_step.h) and a resume
 * (render_checkpoint.h). */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "checkpoint.h"
#include "cpu_features.h"
#include "hp_order.h"
#include "mem_check.h"
#include "render_checkpoint.h"
#include "render_round.h"
#include "render_setup.h"
#include "render_step.h"
#include "render_test_hook.h"

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

/* A set-up step begins: *phase names it (an interrupt's message says where it stopped), the test
 * hook may stop the render there, and the step's start time is returned. */
static double step_begin(const char **phase, const char *name, const char *hook)
{
    *phase = name;
    render_test_interrupt(hook);
    return omp_get_wtime();
}

int render_setup_eye(render_session_t *s, const char **phase, char *err, size_t errlen)
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
    const eye_pass_opts_t eo = {opt->width, opt->height, opt->eye_rays, !opt->hide_lights, 1};
    if (eye_pass(s->scene, s->tr, &eo, &res->hp, &res->emitted, &es, opt->interrupt, err, errlen)) return -1;
    if (opt->checkpoint || opt->resume) s->fingerprint = checkpoint_fingerprint(s->scene, opt, &res->hp);
    st->sec_eye = omp_get_wtime() - t;
    st->hit_points = res->hp.n;
    if (mem_check((uint64_t)res->hp.n * MEM_HIT_POINT_BYTES, opt->max_memory, "the hit points' state and grid",
                  err, errlen))
        return -1;
    st->eye_rays = es.rays;
    st->glass_splits = es.glass_splits;
    st->emitter_hits = es.emitter_hits;
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

int render_setup_grid(render_session_t *s, const char **phase, char *err, size_t errlen)
{
    const render_options_t *opt = &s->opt;
    render_result_t *res = s->res;
    render_stats_t *st = &res->stats;
    const double t = step_begin(phase, "grid build", "grid");
    st->r0 = opt->initial_radius > 0 ? opt->initial_radius : grid_initial_radius(&res->hp, opt->width, opt->height);
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

int render_eye_pass(render_session_t *s, char *err, size_t errlen)
{
    const char *phase = "set-up";
    if (render_setup_eye(s, &phase, err, errlen) ||    /* BVH build, eye pass */
        render_setup_grid(s, &phase, err, errlen) ||   /* spatial order, initial state, owners, grid */
        render_photon_pass_open(s, err, errlen) ||
        (s->opt.resume && render_checkpoint_resume(s, err, errlen))) {
        if (stop_requested(s->opt.interrupt)) snprintf(err, errlen, STOP_MESSAGE " during the %s", phase);
        s->failed = 1;
        return -1;
    }
    s->t_photons = omp_get_wtime();
    return 0;
}
