// SPDX-License-Identifier: Apache-2.0
/* cosim_main.c: `pree cosim SCENE [options]` (the program build/pree-cosim-<config>, which
 * `pree cosim` runs): the renderer in fp32 mode as the host of the Verilated PREE
 * (rtl/pree_top.v), the engine and the RTL driven from one loop. Every photon hit's operations
 * are streamed into the RTL in photon order; after the last photon the RTL's hit-point memory is compared word for word with
 * the fp32 model, the radiance pass runs in RTL, and its pixel memory (the image) is compared
 * with the model's radiance in the same order. A double-precision render of the same scene
 * gives SSIM and SNR. Under mpirun with N ranks, N PREEs (cosim_part_t): each rank runs the same
 * engine and drives a PREE that holds its partition of the hit points. Exit status: 0 when both
 * comparisons show 0 differing words, 1 otherwise or on a failure, 2 on a usage error. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "cli.h"
#include "cosim_args.h"
#include "cosim_compare.h"
#include "cosim_dist.h"
#include "cosim_drv.h"
#include "cosim_layout.h"
#include "cosim_outputs.h"
#include "cosim_refilter.h"
#include "cosim_report.h"
#include "cosim_sched.h"
#include "cosim_shadow.h"
#include "fail_trace.h"
#include "fp32_ops.h"
#include "render.h"
#include "render_dist.h"

/* 1 in the AXI program (build/pree-cosim-axi-*: host/cosim_axi.c through rtl/pree_axi.v). */
#ifndef COSIM_DRV_AXI
#define COSIM_DRV_AXI 0
#endif

typedef struct {
    cosim_drv_t *drv;
    double sec_rtl, cpu_rtl;     /* wall and CPU time spent clocking the RTL in the update phase */
    unsigned long long photons_sent, photons_empty;
    unsigned long long photons_other;   /* photons with candidates, none of them this rank's */
} cosim_ctx_t;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The hit points with their initial state into the RTL's memory, each at its address (the
 * session holds them in photon-pass order), n_local of them (another rank's: none). 0, or -1
 * with a message. */
static int load_hit_points(cosim_ctx_t *c, const hitpoints_t *hp, const uint32_t *addr, size_t n_local,
                           char *err, size_t errlen)
{
    if (n_local > (1u << COSIM_HPAW)) {
        snprintf(err, errlen, "%zu hit points, more than the RTL's hit-point memory (%u)", n_local, 1u << COSIM_HPAW);
        return -1;
    }
    preu_hpw_t *w = malloc((n_local ? n_local : 1) * sizeof *w);
    int32_t *px = malloc((n_local ? n_local : 1) * sizeof *px);
    if (!w || !px) { free(w); free(px); snprintf(err, errlen, "out of memory"); return -1; }
    for (size_t j = 0; j < hp->n; j++) {
        if (addr[j] == OTHER_RANK) continue;
        cosim_model_words(hp, j, &w[addr[j]]);
        px[addr[j]] = hp->pixel[j];
    }
    cosim_drv_load_hp(c->drv, w, px, n_local);
    free(w);
    free(px);
    return 0;
}

/* A block's operations into the RTL, photon by photon, hit points by address (those of another
 * rank's PREE left out). 0 or -1. */
static int stream_block(cosim_ctx_t *c, const update_ops_t *ops, const uint32_t *addr, uint32_t **buf, size_t *cap)
{
    for (size_t i = 0; i < ops->n_hits; i++) {
        const size_t b = update_ops_begin(ops, i), n = ops->end[i] - b;
        if (n == 0) { c->photons_empty++; continue; }
        if (n > *cap) {
            uint32_t *q = realloc(*buf, n * sizeof *q);
            if (!q) return -1;
            *buf = q;
            *cap = n;
        }
        size_t m = 0;
        for (size_t k = 0; k < n; k++)
            if (addr[ops->hp[b + k]] != OTHER_RANK) (*buf)[m++] = addr[ops->hp[b + k]];
        if (m == 0) { c->photons_other++; continue; }
        double t0 = now(), c0 = cpu_now();
        int rc = cosim_drv_photon(c->drv, &ops->ph[i], *buf, m);
        c->sec_rtl += now() - t0;
        c->cpu_rtl += cpu_now() - c0;
        c->photons_sent++;
        if (rc) return -1;
    }
    return 0;
}

/* A failing run without --trace runs itself again (tb/lib/fail_trace.h) with a trace of the
 * cycles around its first mismatch: the last operation on the first differing hit point, or
 * else (only the image differs) the radiance pass; and says where. */
static void leave_fail_trace(int argc, char **argv, const cosim_drv_t *drv, size_t first_hp, int win)
{
    uint64_t first, from, to;
    const char *what;
    if (first_hp != SIZE_MAX) {
        first = cosim_drv_hp_cycle(drv, (uint32_t)first_hp);
        fail_trace_window(first, 32, (uint64_t)win + 32, &from, &to);
        what = "the last operation on the first differing hit point";
    } else {
        cosim_drv_radiance_cycles(drv, &from, &to);
        first = from;
        what = "the radiance pass";
    }
    if (first == UINT64_MAX) {
        fprintf(stderr, "pree cosim: no trace of the mismatch: this driver does not know the cycle of %s\n", what);
        return;
    }
    char path[4096], win_arg[64];
    fail_trace_path(path, sizeof path, NULL, first);
    snprintf(win_arg, sizeof win_arg, "%llu:%llu", (unsigned long long)from, (unsigned long long)to);
    const char *extra[] = {"--trace", path, "--trace-window", win_arg, "--quiet", "--no-reference"};
    if (fail_trace_rerun(argc, argv, extra, 6, path) == 0)
        fprintf(stderr, "pree cosim: %s at cycle %llu; cycles %llu..%llu traced in %s\n", what, (unsigned long long)first,
                (unsigned long long)from, (unsigned long long)to, path);
    else
        fprintf(stderr, "pree cosim: %s at cycle %llu; the traced rerun wrote no %s\n", what,
                (unsigned long long)first, path);
}

/* The RTL model of the run with its run-time constants, its trace window set and the host's
 * tables (--model-only's window, the reference's radiance order) checked against it; NULL with a
 * message printed. */
static cosim_rtl_t *open_rtl(const render_options_t *opt, const cosim_args_t *c, int dp, uint32_t alpha, int win)
{
    char err[1024];
    cosim_rtl_t *rtl = cosim_rtl_new(opt->preu, dp, c->pipefast, c->trace, err, sizeof err);
    if (!rtl) { fprintf(stderr, "pree cosim: %s\n", err); return NULL; }
    cosim_rtl_in(rtl)->alpha = alpha;
    cosim_rtl_in(rtl)->kappa = preu_kappa(alpha);
    cosim_rtl_trace_window(rtl, c->win_from, c->win_to);
    if (cosim_rtl_update_window(rtl) != win || cosim_rtl_radiance_depth(rtl) != cosim_radiance_depth(c->pipefast)) {
        fprintf(stderr, "pree cosim: the RTL's update window and radiance depth are %d and %d cycles, the host's "
                "tables say %d and %d\n", cosim_rtl_update_window(rtl), cosim_rtl_radiance_depth(rtl), win,
                cosim_radiance_depth(c->pipefast));
        cosim_rtl_free(rtl);
        return NULL;
    }
    if (cosim_rtl_reg_flow(rtl) != cosim_reg_flow(c->pipefast)) {
        fprintf(stderr, "pree cosim: the RTL's registered flow is %d, the host's table says %d\n", cosim_rtl_reg_flow(rtl),
                cosim_reg_flow(c->pipefast));
        cosim_rtl_free(rtl);
        return NULL;
    }
    return rtl;
}

/* One run: its command line, the engine's result, the RTL and its driver, the report and the
 * buffers the comparisons fill. */
typedef struct {
    render_options_t opt;
    cosim_args_t c;
    scene_t scene;
    int have_scene;
    cosim_part_t part;
    int dist;                   /* under mpirun with more than one rank */
    int dp, win;
    uint32_t alpha;
    size_t npix;
    cosim_rtl_t *rtl;
    cosim_ctx_t ctx;
    render_result_t res;
    cosim_report_t rep;
    uint32_t *Lr, *Lm, *L1, *abuf;
    size_t acap;
    hp_read_t *got;
    cosim_rank_t *figs;
    double *rgb;
    size_t first_hp;            /* the first differing hit point (its address), SIZE_MAX: none */
} cosim_run_t;

/* The command line, the scene, the RTL (or, with --model-only, its configuration) and the
 * driver: -1 to go on, else the exit status. */
static int run_open(cosim_run_t *r, int argc, char **argv)
{
    r->opt = (render_options_t){.width = 320, .height = 240, .photons = 768000, .precision = PRECISION_FP32,
                                .grid = GRID_CELLS, .preu = 4, .progress = 1};
    r->first_hp = SIZE_MAX;
    int st = cosim_parse_args(argc, argv, COSIM_DRV_AXI, &r->opt, &r->c);
    if (st >= 0) return st;
    const cosim_args_t *c = &r->c;
    r->npix = (size_t)r->opt.width * (size_t)r->opt.height;
    r->part = (cosim_part_t){.nranks = render_dist_size(), .rank = render_dist_rank(), .spatial = !c->pixel_layout};
    r->dist = r->part.nranks > 1;
    if (r->dist && (c->model_only || c->trace || c->axi || c->pixel_layout)) {
        if (r->part.rank == 0)
            fprintf(stderr, "pree cosim: under mpirun with %d ranks: --model-only, --trace, --axi and --layout pixel "
                    "are not supported\n", r->part.nranks);
        return 2;
    }
    if (r->dist && r->part.rank > 0) r->opt.progress = 0;   /* rank 0 prints the engine's progress and the report */
    char err[1024];
    if (scene_load(c->scene, &r->scene, err, sizeof err)) { fprintf(stderr, "pree cosim: %s\n", err); return 1; }
    r->have_scene = 1;
    if (r->opt.initial_radius == 0) r->opt.initial_radius = r->scene.film_radius;   /* a pbrt file's sppm radius */
    r->dp = r->opt.datapath == DATAPATH_STABLE;
    /* The update rule's run-time constants, as the render derives them (model/ppm/render_setup.c). */
    r->alpha = preu_f32(render_alpha(&r->opt));
    r->win = cosim_update_window(r->dp, c->pipefast);
    int hp_bank_w = 0, ppc = 0;
    if (c->model_only) {        /* no RTL: the configuration the build would have */
        if (cosim_rtl_config(r->opt.preu, &hp_bank_w, &ppc)) {
            fprintf(stderr, "pree cosim: no pree_top configuration with %d PREUs\n", r->opt.preu);
            return 2;
        }
    } else {
        if (!(r->rtl = open_rtl(&r->opt, c, r->dp, r->alpha, r->win))) return 1;
        hp_bank_w = cosim_rtl_hp_bank_w(r->rtl);
        ppc = cosim_rtl_ppc(r->rtl);
    }
    cosim_drv_opts_t dopt = {.preu = r->opt.preu, .datapath = r->dp, .hp_bank_w = hp_bank_w, .reorder = c->reorder,
                              .schedule = c->schedule, .window = c->window, .gap = c->gap, .seed = 1,
                              .model_only = c->model_only, .ppc = ppc, .win = r->win,
                              .reg_flow = cosim_reg_flow(c->pipefast)};
    if (!(r->ctx.drv = cosim_drv_new(r->rtl, &dopt))) { fprintf(stderr, "pree cosim: out of memory\n"); return 1; }
    r->opt.record_ops = 1;
    r->opt.one_rank = 1;   /* under mpirun too: each rank runs the whole engine (cosim_part_t) */
    r->rep = (cosim_report_t){.scene = c->scene, .width = r->opt.width, .height = r->opt.height, .datapath = r->dp,
                              .preu = r->opt.preu, .ppc = ppc, .model_only = c->model_only, .axi = c->axi,
                              .reorder = c->reorder, .window = c->window, .pipe_fast = c->pipefast,
                              .update_window = r->win, .pixel_layout = c->pixel_layout,
                              .alpha = (double)fp32_from_bits(r->alpha), .gap = c->gap};
    return -1;
}

/* The engine's session phase by phase (render.h: open, eye pass, photon blocks, radiance, close)
 * and the RTL, driven from this loop: each block's operations (the candidates that pass the
 * host's tests) go to the RTL after the model applied them; at the engine's re-filter points the
 * host reads the radii back (cosim_refilter.h); then the RTL drains. 0, or 1 on a failure (its
 * message printed). */
static int run_update(cosim_run_t *r)
{
    char err[1024];
    const double t_start = now();
    render_session_t *rs = render_open(&r->scene, &r->opt, &r->res, err, sizeof err);
    int rc = !rs ? -1 : render_eye_pass(rs, err, sizeof err), streamed = 0;
    if (rc == 0 && cosim_part_open(&r->part, r->res.hp.n, render_hp_address(rs))) {
        snprintf(err, sizeof err, "out of memory");
        rc = -1;
    }
    if (rc == 0 && !r->c.model_only)
        rc = load_hit_points(&r->ctx, &r->res.hp, r->part.addr, r->part.n_local, err, sizeof err);
    while (rc == 0 && render_step(rs, err, sizeof err) > 0) {
        if (stream_block(&r->ctx, render_block_ops(rs), r->part.addr, &r->abuf, &r->acap)) { streamed = -1; break; }
        if (r->c.refilter && cosim_refilter(r->ctx.drv, rs, &r->res.hp, &r->part, r->dp, r->c.model_only,
                                            &r->rep.refilter, err, sizeof err))
            rc = -1;
    }
    if (rs) {
        render_radiance(rs, err, sizeof err);
        int rc2 = render_close(rs);
        if (rc == 0) rc = rc2;
    }
    r->rep.sec_engine = now() - t_start;
    if (rc != 0 || streamed) {
        fprintf(stderr, "pree cosim: %s: %s\n", r->c.scene, streamed ? cosim_drv_error(r->ctx.drv) : err);
        return 1;
    }
    const double t0 = now(), c0 = cpu_now();
    if (cosim_drv_drain(r->ctx.drv)) { fprintf(stderr, "pree cosim: %s\n", cosim_drv_error(r->ctx.drv)); return 1; }
    r->rep.sec_update_rtl = r->ctx.sec_rtl + (now() - t0);
    r->rep.cpu_update_rtl = r->ctx.cpu_rtl + (cpu_now() - c0);
    return 0;
}

/* Under mpirun: every rank's PREE gathered, rank 0 compares the whole against the model (and
 * against one PREE's radiance order). 0 on rank 0 to go on; else 1, with the exit status in
 * *status and *agreed set when every rank got past the gather. */
static int check_board(cosim_run_t *r, int fail, int *status, int *agreed)
{
    const size_t npix = r->npix;
    cosim_report_t *rep = &r->rep;
    cosim_rank_t mine = {0};
    r->figs = calloc((size_t)r->part.nranks, sizeof *r->figs);
    r->got = calloc(r->res.hp.n ? r->res.hp.n : 1, sizeof *r->got);
    r->Lr = calloc(npix * 3, sizeof *r->Lr);
    r->Lm = calloc(npix * 3, sizeof *r->Lm);
    r->L1 = calloc(npix * 3, sizeof *r->L1);
    r->rgb = malloc(npix * 3 * sizeof *r->rgb);
    if (!r->figs || !r->got || !r->Lr || !r->Lm || !r->L1 || !r->rgb) {
        fprintf(stderr, "pree cosim: out of memory\n");
        fail = 1;
    }
    if (!fail) {
        cosim_drv_counters(r->ctx.drv, rep->cnt_upd);
        mine.hit_points = r->part.n_local;
        mine.photons_sent = r->ctx.photons_sent;
        mine.photons_other = r->ctx.photons_other;
        mine.ops_sent = cosim_drv_ops_sent(r->ctx.drv);
        for (int l = 0; l < r->opt.preu; l++) mine.ops += rep->cnt_upd[CNT_OPS0 + l];
        mine.cycles = rep->cnt_upd[CNT_CYC_UPD];
        mine.utilization = mine.cycles ? (double)mine.ops / ((double)r->opt.preu * (double)mine.cycles) : 0;
    }
    const double t0 = now();
    *status = 1;
    if (cosim_dist_gather(r->ctx.drv, &r->part, &r->res, r->opt.preu, r->c.pipefast, npix, fail, r->got, r->Lr, r->Lm,
                          &mine, r->figs))
        return 1;
    *agreed = 1;
    rep->sec_rad_rtl = now() - t0;
    cosim_drv_counters(r->ctx.drv, rep->cnt_all);
    if (r->part.rank > 0) { *status = 0; return 1; }
    rep->hp_diff = cosim_compare_hit_points(r->got, &r->part, &r->res.hp, r->dp, &rep->hp_diff_points, &r->first_hp);
    rep->img_diff = cosim_image_words_differ(r->Lr, r->Lm, npix, 1);
    if (cosim_model_radiance(&r->res, r->part.model, r->res.hp.n, r->opt.preu, r->c.pipefast, npix, r->L1)) {
        fprintf(stderr, "pree cosim: out of memory\n");
        return 1;
    }
    rep->img_diff_one_pree = cosim_image_words_differ(r->Lr, r->L1, npix, 0);
    for (size_t j = 0; j < npix * 3; j++) {   /* the ulps of binary32 sums in two orders */
        const long long d = (long long)(int32_t)r->Lr[j] - (long long)(int32_t)r->L1[j];
        const unsigned long long u = (unsigned long long)(d < 0 ? -d : d);
        if (u > rep->img_max_ulp_one_pree) rep->img_max_ulp_one_pree = u;
    }
    rep->mpi_ranks = r->part.nranks;
    rep->ranks = r->figs;
    return cosim_image_out(&r->c, &r->scene, &r->opt, r->Lr, r->res.emitted, r->rgb, rep) ? 1 : 0;
}

/* One PREE: its hit-point memory against the fp32 model's final state, then the radiance pass
 * and the image; with --model-only, the cycle model's counters stand for the RTL's. 0, or -1
 * with a message printed. */
static int check_one(cosim_run_t *r)
{
    const size_t npix = r->npix;
    cosim_report_t *rep = &r->rep;
    if (r->c.model_only) {
        cosim_sched_stats_t ss;
        cosim_drv_sched_stats(r->ctx.drv, &ss);
        memcpy(rep->cnt_upd, ss.cnt, sizeof rep->cnt_upd);
        memcpy(rep->cnt_all, ss.cnt, sizeof rep->cnt_all);
        return 0;
    }
    cosim_drv_counters(r->ctx.drv, rep->cnt_upd);
    const size_t n = r->res.hp.n;
    r->got = malloc((n ? n : 1) * sizeof *r->got);
    r->Lr = calloc(npix * 3, sizeof *r->Lr);
    r->Lm = calloc(npix * 3, sizeof *r->Lm);
    r->rgb = malloc(npix * 3 * sizeof *r->rgb);
    if (!r->got || !r->Lr || !r->Lm || !r->rgb) { fprintf(stderr, "pree cosim: out of memory\n"); return -1; }
    for (size_t i = 0; i < n; i++) cosim_drv_read_hp(r->ctx.drv, (uint32_t)i, &r->got[i].w, &r->got[i].px);
    const cosim_part_t *part = r->part.spatial ? &r->part : NULL;
    rep->hp_diff = cosim_compare_hit_points(r->got, part, &r->res.hp, r->dp, &rep->hp_diff_points, &r->first_hp);
    const double t0 = now();
    long long img = cosim_compare_image(r->ctx.drv, &r->res, part ? part->model : NULL, r->opt.preu, r->c.pipefast,
                                        npix, r->Lr, r->Lm);
    if (img < 0) return -1;
    rep->img_diff = (unsigned long long)img;
    rep->sec_rad_rtl = now() - t0;
    cosim_drv_counters(r->ctx.drv, rep->cnt_all);
    return cosim_image_out(&r->c, &r->scene, &r->opt, r->Lr, r->res.emitted, r->rgb, rep);
}

static void run_free(cosim_run_t *r)
{
    free(r->Lr);
    free(r->Lm);
    free(r->L1);
    free(r->got);
    free(r->figs);
    cosim_part_free(&r->part);
    free(r->rgb);
    render_result_free(&r->res);
    free(r->abuf);
    cosim_drv_free(r->ctx.drv);
    cosim_rtl_free(r->rtl);
    if (r->have_scene) scene_free(&r->scene);
}

int pree_cmd_cosim(int argc, char **argv)
{
    cosim_run_t r = {0};
    int status = run_open(&r, argc, argv);
    if (status >= 0) { run_free(&r); return status; }
    status = 1;
    int agreed = 0;     /* under mpirun: every rank got past the gather, and agrees on the status */
    const int fail = run_update(&r);
    if (r.dist) {       /* every rank its PREE; rank 0 compares the whole */
        if (check_board(&r, fail, &status, &agreed)) goto out;
    } else if (fail || check_one(&r)) {
        goto out;
    }
    cosim_report_t *rep = &r.rep;
    rep->photons_emitted = r.res.stats.photons_emitted;
    rep->hit_points = r.res.hp.n;
    rep->photons_sent = r.ctx.photons_sent;
    rep->photons_empty = r.ctx.photons_empty;
    rep->ops_sent = cosim_drv_ops_sent(r.ctx.drv);
    rep->cpu_process = cpu_now();
    rep->have_sched = cosim_drv_sched_stats(r.ctx.drv, &rep->sched) == 0;
    status = cosim_finish_report(rep, &r.c, r.opt.progress);
    if (status && !rep->pass && !r.c.trace && !r.dist && fail_trace_wanted())
        leave_fail_trace(argc, argv, r.ctx.drv, r.first_hp, r.win);
out:
    if (agreed) status = render_dist_max(status);   /* every rank exits as rank 0 */
    run_free(&r);
    return status;
}

/* Under an MPI launcher each rank simulates one PREE (cosim_part_t). */
int main(int argc, char **argv)
{
    if (pree_mpi_begin_cosim(&argc, &argv) < 0) return 2;
    const int rc = pree_cmd_cosim(argc, argv);
    pree_mpi_end();
    return rc;
}
