/* cosim_main.c: `pree cosim SCENE [options]` (the program build/pree-cosim-<config>, which
 * `pree cosim` runs): the renderer in fp32 mode as the host of the Verilated PREE
 * (rtl/pree_top.v), the engine and the RTL driven from one loop. Every photon hit's operations
 * are streamed into the RTL in photon order; after the last photon the RTL's hit-point memory is compared word for word with
 * the fp32 model, the radiance pass runs in RTL, and its pixel memory (the image) is compared
 * with the model's radiance in the same order. A double-precision render of the same scene
 * gives SSIM and SNR. Under mpirun with N ranks, N PREEs (cosim_part_t): each rank runs the same
 * engine and drives a PREE that holds its partition of the hit points. Exit status: 0 when both
 * comparisons show 0 differing words, 1 otherwise or on a failure, 2 on a usage error. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "cli.h"
#include "cli_options.h"
#include "compare.h"
#include "cosim_drv.h"
#include "cosim_report.h"
#include "cosim_sched.h"
#include "cosim_shadow.h"
#include "fail_trace.h"
#include "fp32_ops.h"
#include "image.h"
#include "radiance.h"
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

/* A hit point's address in another rank's PREE (render_hp_address translated by cosim_part_t). */
#define OTHER_RANK UINT32_MAX

/* Where each hit point lies in the PREE's memory (docs/pree_top.md, "Hit-point layout").
 * Under mpirun with more than one rank (docs/scale_out.md, "Multi-PREE co-simulation"): every
 * rank runs the whole fp32 engine alone (opt.one_rank) and drives one PREE, which holds only
 * the hit points the rank owns, [lo[rank], lo[rank + 1]) of the photon pass's spatial order
 * (render_dist_lo: the distributed render's partition), at the local addresses i - lo[rank];
 * it is sent only the operations on them. Without mpirun (or with one rank): nranks 1, and
 * addr i (--layout spatial, the default: the same spatial order) or the eye pass's order
 * (--layout pixel: the model's own index after render_close). */
typedef struct {
    int nranks, rank;
    size_t *lo;                 /* nranks + 1 */
    uint32_t *addr;             /* photon-pass index -> this PREE's address, or OTHER_RANK */
    uint32_t *model;            /* photon-pass index -> the model's index after render_close */
    size_t n_local;
    int spatial;                /* addresses in the photon pass's spatial order (else model's) */
} cosim_part_t;

/* The RTL's words of one hit point and its pixel, as gathered from the ranks. */
typedef struct {
    preu_hpw_t w;
    uint32_t px;
} hp_read_t;

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

#define STR_(x) #x
#define STR(x) STR_(x)
#define WINDOW_16_STR STR(COSIM_SCHED_WINDOW_16)

static void cosim_usage(FILE *f)
{
    fprintf(f,
        "usage: pree cosim SCENE [options]\n"
        "  --width W --height H --photons N --grid G --no-skip --threads T   as for 'pree render'\n"
        "                         (--threads: the eye pass and the double reference render)\n"
        "  --preu P               PREUs in the RTL: 4, 8 or 16 (default 4)\n"
        "  --datapath D --alpha A  the PREU datapath (paper or stable) and alpha, as for 'pree render'\n"
        "  --pipe-fast            the RTL with PipeFast = 1 (the deep PREU pipeline, docs/fpga.md)\n"
        "  --trace FILE.fst       write an FST waveform of the whole run (slow)\n"
        "  --trace-window A:B     only cycles A..B of it (a failing run without --trace leaves\n"
        "                         the cycles around its first mismatch in build/pree-cosim-*-fail-c*.fst)\n"
        "  --out IMAGE            the RTL image (.png, .ppm or .exr)\n"
        "  --stats FILE.json      comparison, SSIM/SNR, cycles, utilization, stalls, speed\n"
        "  --no-reference         skip the double render (no SSIM/SNR)\n"
        "  --no-reorder           stream each photon's candidates in the engine's order\n"
        "  --no-schedule          stream photons in photon order (default: the host's scheduler\n"
        "                         reorders photons that share no hit point, against stalls)\n"
        "  --window W             photons the scheduler holds pending (default 128; " WINDOW_16_STR " with\n"
        "                         16 PREUs)\n"
        "  --layout L             hit-point addresses in the PREE: spatial (the engine's spatial\n"
        "                         order, the default: a photon's candidates lie in a few address\n"
        "                         runs, which the bank hash spreads) or pixel (the eye pass's order)\n"
        "  --model-only           the scheduler's cycle model alone (the RTL not clocked, no\n"
        "                         comparison): its predicted update pass in the --stats report\n"
        "  --gap P                idle cycles on the photon input with probability P (--axi: random\n"
        "                         back-pressure and gaps on every stream and AXI4-Lite channel)\n"
        "  --axi                  run through the AXI4 wrapper rtl/pree_axi.v (build/pree-cosim-axi-*)\n"
        "  --quiet                no progress on stderr\n"
        "under mpirun -np N: N PREEs, each rank's holding its partition of the hit points (the\n"
        "distributed render's) and sent only their operations; rank 0 compares the whole and\n"
        "writes the outputs, with each rank's figures and the load imbalance (docs/scale_out.md)\n");
}

/* Hit point i of the model in the PREE memory's words. */
static void model_words(const hitpoints_t *hp, size_t i, preu_hpw_t *w)
{
    if (hp->stable) preu_hpw_from_stable(w, &hp->stable[i]);
    else preu_hpw_from_paper(w, &hp->fp32[i]);
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
        model_words(hp, j, &w[addr[j]]);
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

static int hp_words_differ(const preu_hpw_t *a, uint32_t pa, const preu_hpw_t *b, uint32_t pb, int datapath)
{
    int d = pa != pb;
    for (int k = 0; k < 3; k++) d += (a->pos[k] != b->pos[k]) + (a->f[k] != b->f[k]);
    for (int k = 0; k < preu_state_words(datapath); k++) d += a->st[k] != b->st[k];
    return d;
}

/* The RTL's hit-point memory got[0..hp->n) against the model's hit points (got[i] holds the
 * model's hit point part->model[i], in rank r's PREE where part->lo[r] <= i < part->lo[r + 1];
 * or, where part is NULL, i): differing words; the hit points that
 * differ and the first (its index in got) in *points and *first (SIZE_MAX: none). The first
 * five are printed. PREE_TEST_CORRUPT_HP=N flips a bit of the model's hit point N first: the
 * failure path's check (tests/checks/fail_trace.sh, mpi_cosim.sh). */
static unsigned long long compare_hit_points(const hp_read_t *got, const cosim_part_t *part, const hitpoints_t *hp,
                                             int dp, unsigned long long *points, size_t *first)
{
    const uint32_t *model = part ? part->model : NULL;
    const char *env = getenv("PREE_TEST_CORRUPT_HP");
    const size_t corrupt = env ? (size_t)strtoull(env, NULL, 10) : SIZE_MAX;
    unsigned long long words = 0;
    *points = 0;
    *first = SIZE_MAX;
    for (size_t i = 0; i < hp->n; i++) {
        const size_t j = model ? model[i] : i;
        preu_hpw_t m;
        model_words(hp, j, &m);
        if (j == corrupt) m.st[0] ^= 1;
        int dw = hp_words_differ(&got[i].w, got[i].px, &m, (uint32_t)hp->pixel[j], dp);
        if (!dw) continue;
        if (*points < 5) {
            fprintf(stderr, "pree cosim: hit point %zu differs", j);
            for (int r = 0; part && part->nranks > 1 && r < part->nranks; r++)
                if (i >= part->lo[r] && i < part->lo[r + 1])
                    fprintf(stderr, " (rank %d's PREE, address %zu)", r, i - part->lo[r]);
            fprintf(stderr, ": state words RTL/model");
            for (int k = 0; k < preu_state_words(dp); k++) fprintf(stderr, " %08x/%08x", got[i].w.st[k], m.st[k]);
            fputc('\n', stderr);
        }
        if (*first == SIZE_MAX) *first = i;
        words += (unsigned long long)dw;
        ++*points;
    }
    return words;
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

static void to_float(const double *rgb, size_t n, float *out)
{
    for (size_t i = 0; i < n; i++) out[i] = (float)rgb[i];
}

enum { OPT_GAP = CLI_OWN, OPT_NO_REFERENCE, OPT_NO_REORDER, OPT_NO_SCHEDULE, OPT_WINDOW,
       OPT_TRACE, OPT_TRACE_WINDOW, OPT_OUT, OPT_STATS, OPT_MODEL_ONLY, OPT_AXI, OPT_PIPE_FAST, OPT_LAYOUT };

static const struct option cosim_longopts[] = {
    CLI_RENDER_LONGOPTS,
    {"gap", required_argument, NULL, OPT_GAP},
    {"no-reference", no_argument, NULL, OPT_NO_REFERENCE},
    {"no-reorder", no_argument, NULL, OPT_NO_REORDER},
    {"no-schedule", no_argument, NULL, OPT_NO_SCHEDULE},
    {"window", required_argument, NULL, OPT_WINDOW},
    {"trace", required_argument, NULL, OPT_TRACE},
    {"trace-window", required_argument, NULL, OPT_TRACE_WINDOW},
    {"out", required_argument, NULL, OPT_OUT},
    {"stats", required_argument, NULL, OPT_STATS},
    {"model-only", no_argument, NULL, OPT_MODEL_ONLY},
    {"axi", no_argument, NULL, OPT_AXI},
    {"pipe-fast", no_argument, NULL, OPT_PIPE_FAST},
    {"layout", required_argument, NULL, OPT_LAYOUT},
    {NULL, 0, NULL, 0}
};

/* The command line of pree cosim beyond the render options. */
typedef struct {
    const char *scene, *stats, *out, *trace;
    int reference, reorder, schedule, window, model_only, axi, pipefast;
    int pixel_layout;                  /* --layout pixel */
    uint64_t win_from, win_to;         /* --trace-window */
    double gap;
} cosim_args_t;

/* Scans the command line into opt and c: -1 to go on, else the exit status (0 after --help, 2 on
 * a usage error, with its message printed). */
static int parse_args(int argc, char **argv, render_options_t *opt, cosim_args_t *c)
{
    *c = (cosim_args_t){.reference = 1, .reorder = 1, .schedule = 1, .win_to = UINT64_MAX};
    cli_args_t a;
    cli_begin(&a, argc, argv, "cosim", cosim_longopts, opt, 11);
    for (int id; (id = cli_next(&a)) != 0;) {
        long long v;
        if (id < 0) return 2;
        switch (id) {
        case CLI_HELP: cosim_usage(stdout); return 0;
        case OPT_GAP:
            if (cli_real(&a, 0, 0, 1, &c->gap)) return 2;
            if (c->gap == 1) return cli_error(&a, "--gap: '%s' is not in [0, 1)", a.val);
            break;
        case OPT_NO_REFERENCE: c->reference = 0; break;
        case OPT_NO_REORDER: c->reorder = 0; break;
        case OPT_NO_SCHEDULE: c->schedule = 0; break;
        case OPT_WINDOW: if (cli_int(&a, 1, 4096, &v)) return 2; c->window = (int)v; break;
        case OPT_TRACE: c->trace = a.val; break;
        case OPT_TRACE_WINDOW: {
            unsigned long long w0, w1;
            char end;
            if (sscanf(a.val, "%llu:%llu%c", &w0, &w1, &end) != 2 || w1 < w0)
                return cli_error(&a, "--trace-window: '%s' is not FIRST:LAST (cycles)", a.val);
            c->win_from = w0;
            c->win_to = w1;
            break;
        }
        case OPT_OUT: if (cli_image_ext(&a, a.val)) return 2; c->out = a.val; break;
        case OPT_STATS: c->stats = a.val; break;
        case OPT_MODEL_ONLY: c->model_only = 1; break;
        case OPT_AXI: c->axi = 1; break;
        case OPT_PIPE_FAST: c->pipefast = 1; break;
        case OPT_LAYOUT:
            if (strcmp(a.val, "spatial") && strcmp(a.val, "pixel"))
                return cli_error(&a, "--layout: '%s' is not spatial or pixel", a.val);
            c->pixel_layout = !strcmp(a.val, "pixel");
            break;
        }
    }
    if (!(c->scene = cli_scene(&a))) return 2;
    if (!c->window) c->window = cosim_sched_default_window(opt->preu);
    if (c->model_only && !c->schedule) return cli_error(&a, "--model-only needs the scheduler (drop --no-schedule)");
    if (c->win_to != UINT64_MAX && !c->trace) return cli_error(&a, "--trace-window needs --trace");
    if (c->axi != COSIM_DRV_AXI)
        return cli_error(&a, c->axi ? "--axi: this program drives pree_top (run 'pree cosim --axi', build/pree-cosim-axi-*)"
                                    : "this program drives pree_axi: give --axi");
    if ((size_t)opt->width * (size_t)opt->height > (1u << COSIM_PXAW))
        return cli_error(&a, "%dx%d has more pixels than the RTL's pixel memory (%u)", opt->width, opt->height,
                         1u << COSIM_PXAW);
    return -1;
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
    if (cosim_rtl_b_skid(rtl) != cosim_b_skid(c->pipefast)) {
        fprintf(stderr, "pree cosim: the RTL's B skid is %d, the host's table says %d\n", cosim_rtl_b_skid(rtl),
                cosim_b_skid(c->pipefast));
        cosim_rtl_free(rtl);
        return NULL;
    }
    return rtl;
}

/* The pixel words of Lr that differ from Lm's; with print, the first five are printed. */
static unsigned long long image_words_differ(const uint32_t *Lr, const uint32_t *Lm, size_t npix, int print)
{
    unsigned long long diff = 0;
    for (size_t j = 0; j < npix * 3; j++) {
        if (Lr[j] != Lm[j] && diff < 5 && print)
            fprintf(stderr, "pree cosim: pixel %zu channel %zu differs: RTL %08x model %08x\n", j / 3, j % 3, Lr[j], Lm[j]);
        diff += Lr[j] != Lm[j];
    }
    return diff;
}

/* The fp32 model's radiance pass over n hit points in a PREE's address order (order[a]: the
 * model's index of the hit point at address a; NULL: the model's own order, all of them), the
 * order in which that PREE's ADISO-REC adds them: into L (zeroed here). 0 or -1 (memory). */
static int model_radiance(const render_result_t *res, const uint32_t *order, size_t n, int preu, int pipefast,
                          size_t npix, uint32_t *L)
{
    const hitpoints_t *h = &res->hp;
    unsigned long long skipped;
    memset(L, 0, npix * 3 * sizeof *L);
    if (!order) return radiance_fp32_words(h, res->stats.photons_emitted, 0, preu, cosim_radiance_depth(pipefast), L,
                                           &skipped);
    hitpoints_t sub = {.n = n};
    sub.pixel = malloc((n ? n : 1) * sizeof *sub.pixel);
    if (h->stable) sub.stable = malloc((n ? n : 1) * sizeof *sub.stable);
    else sub.fp32 = malloc((n ? n : 1) * sizeof *sub.fp32);
    int rc = -1;
    if (sub.pixel && (sub.stable || sub.fp32)) {
        for (size_t a = 0; a < n; a++) {
            const size_t j = order[a];
            sub.pixel[a] = h->pixel[j];
            if (h->stable) sub.stable[a] = h->stable[j];
            else sub.fp32[a] = h->fp32[j];
        }
        rc = radiance_fp32_words(&sub, res->stats.photons_emitted, 0, preu, cosim_radiance_depth(pipefast), L, &skipped);
    }
    free(sub.pixel);
    free(sub.stable);
    free(sub.fp32);
    return rc;
}

/* The radiance pass in RTL (pixel words into Lr) and in the model (into Lm), in the same order
 * (order: as for model_radiance): the differing words (the first five printed), or -1 with a
 * message printed. */
static long long compare_image(cosim_drv_t *drv, const render_result_t *res, const uint32_t *order, int preu,
                               int pipefast, size_t npix, uint32_t *Lr, uint32_t *Lm)
{
    const uint32_t ne = preu_n_emitted(res->stats.photons_emitted);
    if (cosim_drv_radiance(drv, (uint32_t)res->hp.n, ne, npix, Lr)) {
        fprintf(stderr, "pree cosim: radiance pass: %s\n", cosim_drv_error(drv));
        return -1;
    }
    if (model_radiance(res, order, res->hp.n, preu, pipefast, npix, Lm)) {
        fprintf(stderr, "pree cosim: out of memory\n");
        return -1;
    }
    return (long long)image_words_differ(Lr, Lm, npix, 1);
}

/* SSIM, SNR and the rest of the RTL image rgb against a double-precision render of the same
 * scene, photons and grid: 0, or -1 with a message printed (-2: the comparison alone failed). */
static int reference_metrics(const scene_t *scene, const render_options_t *opt, const double *rgb, pree_metrics_t *m)
{
    char err[1024];
    const size_t npix = (size_t)opt->width * (size_t)opt->height;
    render_options_t ropt = {.width = opt->width, .height = opt->height, .photons = opt->photons,
                             .precision = PRECISION_DOUBLE, .grid = opt->grid, .threads = opt->threads,
                             .no_skip = opt->no_skip, .preu = opt->preu, .one_rank = 1};
    render_result_t ref = {0};
    if (render_run(scene, &ropt, &ref, err, sizeof err)) {
        fprintf(stderr, "pree cosim: reference: %s\n", err);
        render_result_free(&ref);
        return -1;
    }
    pree_image_t ia = {0}, ib = {0};
    int rc = 0;
    if (pree_image_alloc(&ia, opt->width, opt->height, err, sizeof err) ||
        pree_image_alloc(&ib, opt->width, opt->height, err, sizeof err)) {
        fprintf(stderr, "pree cosim: %s\n", err);
        rc = -1;
    } else {
        to_float(ref.rgb, npix * 3, ia.rgb);
        to_float(rgb, npix * 3, ib.rgb);
        if (pree_compare(&ia, &ib, m, err, sizeof err)) { fprintf(stderr, "pree cosim: compare: %s\n", err); rc = -2; }
    }
    pree_image_free(&ia);
    pree_image_free(&ib);
    render_result_free(&ref);
    return rc;
}

/* The RTL's image (binary32 words Lr, widened into rgb) to --out, and with a reference its
 * metrics in rep: 0, or -1 with a message printed. */
static int rtl_image_out(const cosim_args_t *c, const scene_t *scene, const render_options_t *opt, const uint32_t *Lr,
                         double *rgb, cosim_report_t *rep)
{
    char err[1024];
    const size_t npix = (size_t)opt->width * (size_t)opt->height;
    for (size_t j = 0; j < npix * 3; j++) rgb[j] = (double)fp32_from_bits(Lr[j]);
    if (c->out && pree_image_write(c->out, opt->width, opt->height, rgb, err, sizeof err)) {
        fprintf(stderr, "pree cosim: %s\n", err);
        return -1;
    }
    if (c->reference) {
        const int m = reference_metrics(scene, opt, rgb, &rep->m);
        if (m == -1) return -1;
        rep->have_metrics = m == 0;
    }
    return 0;
}

/* The report's figures, its JSON (--stats) and the closing line: the exit status (0 when both
 * comparisons show 0 differing words, or with --model-only), or 1 when the JSON is not written. */
static int finish_report(cosim_report_t *rep, const cosim_args_t *c, int progress)
{
    char err[1024];
    cosim_report_figures(rep);
    if (rep->ops_upd != rep->ops_sent)
        fprintf(stderr, "pree cosim: %llu update operations sent, %llu counted in the RTL\n",
                (unsigned long long)rep->ops_sent, (unsigned long long)rep->ops_upd);
    if (c->stats && cosim_report_write(c->stats, rep, err, sizeof err)) {
        fprintf(stderr, "pree cosim: %s\n", err);
        return 1;
    }
    if (progress && c->model_only)
        fprintf(stderr, "pree cosim: cycle model, %d PREUs: %llu ops in %llu cycles (utilization %.4f%%)\n",
                rep->preu, (unsigned long long)rep->ops_upd, (unsigned long long)rep->cyc_upd, 100 * rep->util_upd);
    else if (progress && rep->mpi_ranks > 1) {
        for (int k = 0; k < rep->mpi_ranks; k++) {
            const cosim_rank_t *q = &rep->ranks[k];
            fprintf(stderr, "pree cosim: rank %d of %d: %d PREUs, %llu hit points: %llu ops in %llu cycles "
                    "(utilization %.4f%%); radiance %llu cycles; image words differing %llu\n", k, rep->mpi_ranks,
                    rep->preu, (unsigned long long)q->hit_points, (unsigned long long)q->ops,
                    (unsigned long long)q->cycles, 100 * q->utilization, (unsigned long long)q->radiance_cycles,
                    (unsigned long long)q->image_words_differing);
        }
        fprintf(stderr, "pree cosim: %d PREEs of %d PREUs: load imbalance %.4f (max / mean update cycles), "
                "utilization %.4f%% over the longest; differing words: hit points %llu, image %llu%s "
                "(against one PREE's radiance order, which adds a pixel's hit points in another order: %llu, at most %llu "
                "ulps)\n", rep->mpi_ranks, rep->preu, rep->imbalance, 100 * rep->util_all, rep->hp_diff, rep->img_diff,
                rep->pass ? "" : " FAIL", rep->img_diff_one_pree, rep->img_max_ulp_one_pree);
    } else if (progress)
        fprintf(stderr, "pree cosim: %d PREUs: %llu ops in %llu cycles (utilization %.4f%%), %.0f ops/CPU-s; "
                "differing words: hit points %llu, image %llu%s\n",
                rep->preu, (unsigned long long)rep->ops_upd, (unsigned long long)rep->cyc_upd, 100 * rep->util_upd,
                rep->sim_ops_per_cpu_s, rep->hp_diff, rep->img_diff, rep->pass ? "" : " FAIL");
    return rep->pass || c->model_only ? 0 : 1;
}

/* This rank's partition of n hit points (p->nranks and p->rank set); perm: render_hp_address.
 * 0, or -1 (memory). */
static int part_open(cosim_part_t *p, size_t n, const uint32_t *perm)
{
    p->lo = malloc((size_t)(p->nranks + 1) * sizeof *p->lo);
    p->addr = malloc((n ? n : 1) * sizeof *p->addr);
    p->model = malloc((n ? n : 1) * sizeof *p->model);
    if (!p->lo || !p->addr || !p->model) return -1;
    for (int r = 0; r <= p->nranks; r++) p->lo[r] = render_dist_lo(n, r, p->nranks);
    const size_t lo = p->lo[p->rank], hi = p->lo[p->rank + 1];
    for (size_t i = 0; i < n; i++) {
        p->model[i] = perm[i];
        p->addr[i] = !p->spatial ? perm[i] : i >= lo && i < hi ? (uint32_t)(i - lo) : OTHER_RANK;
    }
    p->n_local = hi - lo;
    return 0;
}

static void part_free(cosim_part_t *p)
{
    free(p->lo);
    free(p->addr);
    free(p->model);
}

/* Under mpirun, after the update pass (every rank alike; fail: this rank's state so far): the
 * ranks' PREE memories gathered into rank 0's got (photon-pass order); each PREE's radiance pass
 * over its own hit points, and the model's over the same hit points in the same order, compared
 * (mine->image_words_differing); rank 0 adds the ranks' pixel words in rank order in binary32,
 * as the host of a board of PREEs would, into Lr (the RTL's) and Lm (the model's); every rank's
 * figures into figs on rank 0. 0, or 1 when any rank failed (its message printed by it). */
static int dist_gather(cosim_ctx_t *ctx, const cosim_part_t *p, const render_result_t *res, int preu, int pipefast,
                       size_t npix, int fail, hp_read_t *got, uint32_t *Lr, uint32_t *Lm, cosim_rank_t *mine,
                       cosim_rank_t *figs)
{
    const size_t lo = p->lo[p->rank], words = npix * 3;
    if (!fail)
        for (size_t a = 0; a < p->n_local; a++) cosim_drv_read_hp(ctx->drv, (uint32_t)a, &got[lo + a].w, &got[lo + a].px);
    if (render_dist_max(fail)) return 1;
    render_dist_gather_ranges(got, sizeof *got, p->lo);
    uint32_t *part = malloc(2 * words * sizeof *part);   /* the RTL's pixel words, then the model's */
    if (!part) { fprintf(stderr, "pree cosim: out of memory\n"); fail = 1; }
    else if (cosim_drv_radiance(ctx->drv, (uint32_t)p->n_local, preu_n_emitted(res->stats.photons_emitted), npix, part)) {
        fprintf(stderr, "pree cosim: rank %d: radiance pass: %s\n", p->rank, cosim_drv_error(ctx->drv));
        fail = 1;
    } else if (model_radiance(res, p->model + lo, p->n_local, preu, pipefast, npix, part + words)) {
        fprintf(stderr, "pree cosim: out of memory\n");
        fail = 1;
    }
    if (!fail) {
        uint64_t cnt[COSIM_NCNT];
        cosim_drv_counters(ctx->drv, cnt);
        mine->radiance_cycles = cnt[CNT_CYC_RAD];
        mine->radiance_ops = 0;
        for (int l = 0; l < preu; l++) mine->radiance_ops += cnt[CNT_OPS0 + l];
        mine->radiance_ops -= mine->ops;
        mine->image_words_differing = 0;
        for (size_t j = 0; j < words; j++) mine->image_words_differing += part[j] != part[words + j];
    }
    void *recv = NULL, *rf = NULL;
    size_t cap = 0, fcap = 0, *counts = malloc((size_t)p->nranks * sizeof *counts);
    if (!counts) fail = 1;
    if (render_dist_max(fail) || render_dist_allgather(part, 2 * words * sizeof *part, &recv, &cap, counts) ||
        render_dist_allgather(mine, sizeof *mine, &rf, &fcap, counts)) {
        free(part);
        free(recv);
        free(rf);
        free(counts);
        return 1;
    }
    memcpy(figs, rf, (size_t)p->nranks * sizeof *figs);
    free(rf);
    const uint32_t *all = recv;
    for (int r = 0; r < p->nranks; r++)
        for (size_t j = 0; j < words; j++) {
            const uint32_t *q = all + (size_t)r * 2 * words;
            Lr[j] = r ? fp32_add(Lr[j], q[j]) : q[j];
            Lm[j] = r ? fp32_add(Lm[j], q[words + j]) : q[words + j];
        }
    free(part);
    free(recv);
    free(counts);
    return 0;
}

int pree_cmd_cosim(int argc, char **argv)
{
    render_options_t opt = {.width = 320, .height = 240, .photons = 768000, .precision = PRECISION_FP32,
                            .grid = GRID_CELLS, .preu = 4, .progress = 1};
    cosim_args_t c;
    int st = parse_args(argc, argv, &opt, &c);
    if (st >= 0) return st;
    const size_t npix = (size_t)opt.width * (size_t)opt.height;
    char err[1024];
    scene_t scene;
    cosim_part_t part = {.nranks = render_dist_size(), .rank = render_dist_rank()};
    const int dist = part.nranks > 1;
    if (dist && (c.model_only || c.trace || c.axi || c.pixel_layout)) {
        if (part.rank == 0)
            fprintf(stderr, "pree cosim: under mpirun with %d ranks: --model-only, --trace, --axi and --layout pixel "
                    "are not supported\n", part.nranks);
        return 2;
    }
    part.spatial = !c.pixel_layout;
    if (dist && part.rank > 0) opt.progress = 0;   /* rank 0 prints the engine's progress and the report */
    if (scene_load(c.scene, &scene, err, sizeof err)) { fprintf(stderr, "pree cosim: %s\n", err); return 1; }

    const int dp = opt.datapath == DATAPATH_STABLE;
    /* The update rule's run-time constants, as the render derives them (model/ppm/render.c). */
    const uint32_t alpha = preu_f32(render_alpha(&opt));
    int hp_bank_w = 0, ppc = 0, win = cosim_update_window(dp, c.pipefast);
    cosim_rtl_t *rtl = NULL;
    if (c.model_only) {        /* no RTL: the configuration the build would have */
        if (cosim_rtl_config(opt.preu, &hp_bank_w, &ppc)) {
            fprintf(stderr, "pree cosim: no pree_top configuration with %d PREUs\n", opt.preu);
            scene_free(&scene);
            return 2;
        }
    } else {
        if (!(rtl = open_rtl(&opt, &c, dp, alpha, win))) { scene_free(&scene); return 1; }
        hp_bank_w = cosim_rtl_hp_bank_w(rtl);
        ppc = cosim_rtl_ppc(rtl);
    }
    cosim_drv_opts_t dopt = {.preu = opt.preu, .datapath = dp, .hp_bank_w = hp_bank_w, .reorder = c.reorder,
                              .schedule = c.schedule, .window = c.window, .gap = c.gap, .seed = 1,
                              .model_only = c.model_only, .ppc = ppc, .win = win,
                              .skid = cosim_b_skid(c.pipefast)};
    cosim_ctx_t ctx = {0};
    ctx.drv = cosim_drv_new(rtl, &dopt);
    opt.record_ops = 1;
    opt.one_rank = 1;   /* under mpirun too: each rank runs the whole engine (cosim_part_t) */

    int status = 1;
    render_result_t res = {0};
    uint32_t *Lr = NULL, *Lm = NULL, *L1 = NULL, *abuf = NULL;
    hp_read_t *got = NULL;
    cosim_rank_t *figs = NULL;
    int agreed = 0;     /* under mpirun: every rank got past the gather, and agrees on the status */
    size_t acap = 0;
    double *rgb = NULL;
    double t_start = now();
    /* The engine's photon blocks and the RTL, driven from this loop: each block's operations
     * (the candidates that pass the host's tests) go to the RTL after the model applied them. */
    render_session_t *rs = ctx.drv ? render_open(&scene, &opt, &res, err, sizeof err) : NULL;
    if (!ctx.drv) snprintf(err, sizeof err, "out of memory");
    int rc = !rs ? -1 : 0;
    if (rc == 0 && part_open(&part, res.hp.n, render_hp_address(rs))) { snprintf(err, sizeof err, "out of memory"); rc = -1; }
    if (rc == 0 && !c.model_only) rc = load_hit_points(&ctx, &res.hp, part.addr, part.n_local, err, sizeof err);
    int streamed = 0;
    while (rc == 0 && render_step(rs, err, sizeof err) > 0) {
        if (stream_block(&ctx, render_block_ops(rs), part.addr, &abuf, &acap)) { streamed = -1; break; }
    }
    if (rs) {
        int rc2 = render_close(rs, err, sizeof err);
        if (rc == 0) rc = rc2;
    }
    cosim_report_t rep = {.scene = c.scene, .width = opt.width, .height = opt.height, .datapath = dp,
                          .preu = opt.preu, .ppc = ppc, .model_only = c.model_only, .axi = c.axi,
                          .reorder = c.reorder, .window = c.window, .pipe_fast = c.pipefast, .update_window = win,
                          .pixel_layout = c.pixel_layout,
                          .alpha = (double)fp32_from_bits(alpha), .gap = c.gap};
    rep.sec_engine = now() - t_start;
    int fail = 0;
    if (rc != 0 || streamed) {
        fprintf(stderr, "pree cosim: %s: %s\n", c.scene, streamed ? cosim_drv_error(ctx.drv) : err);
        fail = 1;
    }
    double t0 = now(), c0 = cpu_now();
    if (!fail && cosim_drv_drain(ctx.drv)) { fprintf(stderr, "pree cosim: %s\n", cosim_drv_error(ctx.drv)); fail = 1; }
    if (fail && !dist) goto out;
    rep.sec_update_rtl = ctx.sec_rtl + (now() - t0);
    rep.cpu_update_rtl = ctx.cpu_rtl + (cpu_now() - c0);
    size_t first_hp = SIZE_MAX;
    if (dist) {                /* every rank its PREE; rank 0 compares the whole */
        cosim_rank_t mine = {0};
        figs = calloc((size_t)part.nranks, sizeof *figs);
        got = calloc(res.hp.n ? res.hp.n : 1, sizeof *got);
        Lr = calloc(npix * 3, sizeof *Lr);
        Lm = calloc(npix * 3, sizeof *Lm);
        L1 = calloc(npix * 3, sizeof *L1);
        rgb = malloc(npix * 3 * sizeof *rgb);
        if (!figs || !got || !Lr || !Lm || !L1 || !rgb) { fprintf(stderr, "pree cosim: out of memory\n"); fail = 1; }
        if (!fail) {
            cosim_drv_counters(ctx.drv, rep.cnt_upd);
            mine.hit_points = part.n_local;
            mine.photons_sent = ctx.photons_sent;
            mine.photons_other = ctx.photons_other;
            mine.ops_sent = cosim_drv_ops_sent(ctx.drv);
            for (int l = 0; l < opt.preu; l++) mine.ops += rep.cnt_upd[CNT_OPS0 + l];
            mine.cycles = rep.cnt_upd[CNT_CYC_UPD];
            mine.utilization = mine.cycles ? (double)mine.ops / ((double)opt.preu * (double)mine.cycles) : 0;
        }
        t0 = now();
        if (dist_gather(&ctx, &part, &res, opt.preu, c.pipefast, npix, fail, got, Lr, Lm, &mine, figs)) goto out;
        agreed = 1;
        rep.sec_rad_rtl = now() - t0;
        cosim_drv_counters(ctx.drv, rep.cnt_all);
        if (part.rank > 0) { status = 0; goto out; }
        rep.hp_diff = compare_hit_points(got, &part, &res.hp, dp, &rep.hp_diff_points, &first_hp);
        rep.img_diff = image_words_differ(Lr, Lm, npix, 1);
        if (model_radiance(&res, part.model, res.hp.n, opt.preu, c.pipefast, npix, L1)) {
            fprintf(stderr, "pree cosim: out of memory\n");
            goto out;
        }
        rep.img_diff_one_pree = image_words_differ(Lr, L1, npix, 0);
        for (size_t j = 0; j < npix * 3; j++) {   /* the ulps of binary32 sums in two orders */
            const long long d = (long long)(int32_t)Lr[j] - (long long)(int32_t)L1[j];
            const unsigned long long u = (unsigned long long)(d < 0 ? -d : d);
            if (u > rep.img_max_ulp_one_pree) rep.img_max_ulp_one_pree = u;
        }
        rep.mpi_ranks = part.nranks;
        rep.ranks = figs;
        if (rtl_image_out(&c, &scene, &opt, Lr, rgb, &rep)) goto out;
    } else if (c.model_only) {        /* the cycle model's counters stand for the RTL's */
        cosim_sched_stats_t ss;
        cosim_drv_sched_stats(ctx.drv, &ss);
        memcpy(rep.cnt_upd, ss.cnt, sizeof rep.cnt_upd);
        memcpy(rep.cnt_all, ss.cnt, sizeof rep.cnt_all);
    } else {
        cosim_drv_counters(ctx.drv, rep.cnt_upd);
        /* Hit-point memory against the fp32 model's final state, then the image. */
        got = malloc((res.hp.n ? res.hp.n : 1) * sizeof *got);
        if (!got) { fprintf(stderr, "pree cosim: out of memory\n"); goto out; }
        for (size_t i = 0; i < res.hp.n; i++) cosim_drv_read_hp(ctx.drv, (uint32_t)i, &got[i].w, &got[i].px);
        rep.hp_diff = compare_hit_points(got, part.spatial ? &part : NULL, &res.hp, dp, &rep.hp_diff_points, &first_hp);
        Lr = calloc(npix * 3, sizeof *Lr);
        Lm = calloc(npix * 3, sizeof *Lm);
        rgb = malloc(npix * 3 * sizeof *rgb);
        if (!Lr || !Lm || !rgb) { fprintf(stderr, "pree cosim: out of memory\n"); goto out; }
        t0 = now();
        long long img = compare_image(ctx.drv, &res, part.spatial ? part.model : NULL, opt.preu, c.pipefast, npix, Lr, Lm);
        if (img < 0) goto out;
        rep.img_diff = (unsigned long long)img;
        rep.sec_rad_rtl = now() - t0;
        cosim_drv_counters(ctx.drv, rep.cnt_all);
        if (rtl_image_out(&c, &scene, &opt, Lr, rgb, &rep)) goto out;
    }
    rep.photons_emitted = res.stats.photons_emitted;
    rep.hit_points = res.hp.n;
    rep.photons_sent = ctx.photons_sent;
    rep.photons_empty = ctx.photons_empty;
    rep.ops_sent = cosim_drv_ops_sent(ctx.drv);
    rep.cpu_process = cpu_now();
    rep.have_sched = cosim_drv_sched_stats(ctx.drv, &rep.sched) == 0;
    status = finish_report(&rep, &c, opt.progress);
    if (status && !rep.pass && !c.trace && !dist && fail_trace_wanted())
        leave_fail_trace(argc, argv, ctx.drv, first_hp, win);
out:
    if (agreed) status = render_dist_max(status);   /* every rank exits as rank 0 */
    free(Lr);
    free(Lm);
    free(L1);
    free(got);
    free(figs);
    part_free(&part);
    free(rgb);
    render_result_free(&res);
    free(abuf);
    cosim_drv_free(ctx.drv);
    cosim_rtl_free(rtl);
    scene_free(&scene);
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
