// SPDX-License-Identifier: Apache-2.0
/* cli_render.c: `pree render SCENE [options]`: parse and check the options, render, write
 * the images and the statistics. SIGINT or SIGTERM stops the render in any phase (the photon
 * block in progress is abandoned) and writes the image of the photon blocks done so far, or
 * nothing when no block was done; the exit status is then 130 (a second signal ends the process
 * at once). SIGPIPE is ignored: a closed stderr stops the progress, never the render. */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli.h"
#include "render_dist.h"
#include "checkpoint.h"
#include "cli_options.h"
#include "cli_outputs.h"
#include "cli_pm.h"
#include "cli_resume.h"
#include "cli_series.h"
#include "cpu_features.h"
#include "image.h"
#include "render.h"
#include "stats_json.h"

#define MAX_OUTPUTS 8

static volatile sig_atomic_t interrupted;
static void on_sigint(int sig) { (void)sig; interrupted = 1; }

/* Write the image to path; an EXR file carries the run's description in its header (pree:scene,
 * pree:size, pree:photons, ...: docs/compare.md, "Image files written by the engine"). */
static int write_image(const char *path, const char *scene, const render_options_t *opt,
                       const render_result_t *res, char *err, size_t errlen)
{
    char size[32], photons[32], offset[32], alpha[32], hash[32];
    snprintf(size, sizeof size, "%dx%d", res->width, res->height);
    snprintf(photons, sizeof photons, "%llu", (unsigned long long)res->stats.photons_emitted);
    snprintf(offset, sizeof offset, "%llu", (unsigned long long)opt->photon_offset);
    snprintf(alpha, sizeof alpha, "%.17g", render_alpha(opt));
    snprintf(hash, sizeof hash, "%016llx", (unsigned long long)res->stats.image_hash);
    const char *meta[] = {
        "pree:scene", scene, "pree:size", size, "pree:photons", photons, "pree:photon_offset", offset,
        "pree:precision", opt->precision == PRECISION_FP32 ? "fp32" : "double",
        "pree:datapath", stats_datapath_name(opt), "pree:grid", stats_grid_name(opt->grid),
        "pree:alpha", alpha, "pree:version", pree_version(), "pree:image_hash", hash, NULL};
    return pree_image_write_scaled(path, res->width, res->height, res->rgb, meta, exp2(opt->exposure), err, errlen);
}

static void render_usage(FILE *f)
{
    fprintf(f,
        "usage: pree render SCENE [options]\n"
        "       pree render --resume CHECKPOINT [options]\n"
        "  --width W              image width in pixels (default 320)\n"
        "  --height H             image height in pixels (default 240)\n"
        "  --photons N            photons to emit, rounded down to whole 1000s (default 768000)\n"
        "  --photon-offset K      trace photon k with Halton index K + k (default 0): a reference render\n"
        "                         whose photon paths are disjoint from those of the renders it judges\n"
        "  --precision P          double (the reference) or fp32 (the PREE datapath's arithmetic)\n"
        "  --datapath D           fp32: paper (default: the paper's PREU, bit for bit) or stable (exact\n"
        "                         count, wide 1/r2 and tau/r2: accurate for any photon count; implies\n"
        "                         --precision fp32)\n"
        "  --alpha A              the radius reduction alpha, in (0, 1] (default 0.7)\n"
        "  --grid G               cells (default: exact cells, skips), smallppm (the reference program's\n"
        "                         hash grid, exact counts) or brute (every hit point, for tests)\n"
        "  --scan S               bucket (default: a block's candidates bucket by bucket, then applied in\n"
        "                         photon order) or photon (photon by photon; the oracle); same bits\n"
        "  --no-skip              disable the skips (zero-weight hit points, empty cells, far candidates)\n"
        "  --simd L               the vector instructions of the update's screening and the sphere\n"
        "                         tests: auto (default: the widest the processor has), avx512, avx2\n"
        "                         or scalar (an absent one is an error); the same bits at every level\n"
        "  --preu P               fp32: the PREE whose radiance pass the image reproduces bit for bit\n"
        "  --pipe-fast            (the order of each pixel's additions, docs/pree_top.md): its PREU count\n"
        "  --layout L             (1, 2, 4, 8, 16; default 4), its deep PREU pipelines (PipeFast = 1), its\n"
        "                         hit-point layout (spatial, the default, or pixel); 'pree cosim' with\n"
        "                         the same scene and options writes the same image\n"
        "  --prees N              fp32: the image of a board of N such PREEs, each holding its run of\n"
        "                         the spatial order, as 'mpirun -np N pree cosim' forms it (default 1)\n"
        "  --threads T            OpenMP threads (default: all cores); the image does not depend on T\n"
        "  --out IMAGE            .png, .ppm or .exr; may be given several times (default NAME.png in the\n"
        "                         current folder, NAME the scene's file name less .scene or .pbrt)\n"
        "  --stats FILE.json      write the statistics\n"
        "  --checkpoint FILE      write the render's state to FILE every --checkpoint-every photons and\n"
        "                         when the photon pass ends or is interrupted (atomically)\n"
        "  --checkpoint-every N   photons between checkpoints (default 1024000)\n"
        "  --resume FILE          continue the checkpoint's render: alone, as it was started (scene,\n"
        "                         options, outputs are in FILE); with --photons N, extended to N; other\n"
        "                         outputs may be given, options that change the bits may not. The\n"
        "                         same bits as an uninterrupted render, for any --threads\n"
        "  --eye-rays N           eye rays a pixel, 1..256 (default 1, through its centre): N > 1 rays\n"
        "                         at jittered points of the pixel, each of weight 1/N (anti-aliasing;\n"
        "                         N times the hit points)\n"
        "  --radius R             every hit point's initial radius, in scene units (default: from the\n"
        "                         hit points' bounds, as smallppm; a pbrt file's sppm \"radius\")\n"
        "  --exposure EV          scale the PNG and PPM outputs by 2^EV before the tone curve, EV in\n"
        "                         [-30, 30] (default 0); EXR outputs hold the linear radiance as it is\n"
        "  --hide-lights          the image without the area lights' own emitted radiance (the photon\n"
        "                         radiance alone; by default the camera sees the lights)\n"
        "  --light-sampling S     uniform (default: photon i from light i mod L) or power (each light\n"
        "                         with probability its share of the total flux)\n"
        "  --max-bounces W        photon paths stop at their hit after W bounces (1 to 1000; default:\n"
        "                         the scene's max_depth alone): shorter, more even tracing tasks, a\n"
        "                         darker image (docs/photon_map.md, \"Capping photon paths\")\n"
        "  --write-every N        a convergence series: also write every output at N, 2N, ... photons\n"
        "  --write-at N,N,...     and/or at these counts (100k, 1.5M: whole thousands), each NAME.EXT as\n"
        "                         NAME-COUNT.EXT with the bits of a render of COUNT photons\n"
        "  --time-limit S         stop after the photon block in progress once S seconds have passed;\n"
        "                         the image holds the photons done (stats: photons_emitted), exit 0\n"
        "  --quiet                no progress and no summary on stderr (warnings and errors only); without\n"
        "                         it the last line names every file written\n"
        "  --max-memory SIZE      the memory the render may hold, e.g. 512M or 8G (default: the\n"
        "                         address-space limit and the available memory); checked against an\n"
        "                         estimate before allocating\n");
    cli_pm_usage(f);
}

enum { OPT_PHOTON_OFFSET = CLI_OWN, OPT_PRECISION, OPT_SCAN, OPT_OUT, OPT_STATS, OPT_CHECKPOINT,
       OPT_CHECKPOINT_EVERY, OPT_RESUME, OPT_TIME_LIMIT, OPT_MAX_MEMORY, OPT_PREES, OPT_WRITE_EVERY, OPT_WRITE_AT,
       OPT_LIGHT_SAMPLING, OPT_SIMD, OPT_MAX_BOUNCES };

static const struct option render_longopts[] = {
    CLI_RENDER_LONGOPTS,
    CLI_PM_LONGOPTS,
    {"photon-offset", required_argument, NULL, OPT_PHOTON_OFFSET},
    {"precision", required_argument, NULL, OPT_PRECISION},
    {"scan", required_argument, NULL, OPT_SCAN},
    {"out", required_argument, NULL, OPT_OUT},
    {"stats", required_argument, NULL, OPT_STATS},
    {"checkpoint", required_argument, NULL, OPT_CHECKPOINT},
    {"checkpoint-every", required_argument, NULL, OPT_CHECKPOINT_EVERY},
    {"resume", required_argument, NULL, OPT_RESUME},
    {"time-limit", required_argument, NULL, OPT_TIME_LIMIT},
    {"max-memory", required_argument, NULL, OPT_MAX_MEMORY},
    {"prees", required_argument, NULL, OPT_PREES},
    {"simd", required_argument, NULL, OPT_SIMD},
    {"write-every", required_argument, NULL, OPT_WRITE_EVERY},
    {"write-at", required_argument, NULL, OPT_WRITE_AT},
    {"light-sampling", required_argument, NULL, OPT_LIGHT_SAMPLING},
    {"max-bounces", required_argument, NULL, OPT_MAX_BOUNCES},
    {NULL, 0, NULL, 0}
};

/* What the command line asks for besides the render options. */
typedef struct {
    const char *scene_path, *stats_path;
    const char *outs[MAX_OUTPUTS];
    int nout;
    char default_out[600];
    int precision_given;    /* --precision was on the command line */
    char given[48][64];     /* the options on the command line, by name ("--width") */
    const char *given_names[48];
    int ngiven;
    cli_series_t series;    /* --write-every, --write-at */
    int light_power;        /* --light-sampling power */
    int max_bounces;        /* --max-bounces W (0: none) */
} render_job_t;

/* Parse the command line into opt and j: -1 to go on, else the exit status (0 after --help). */
static int parse_args(int argc, char **argv, render_options_t *opt, render_job_t *j)
{
    cli_args_t a;
    cli_begin(&a, argc, argv, "render", render_longopts, NULL, 1);
    for (int id; (id = cli_next(&a)) != 0;) {
        long long v;
        int k;
        if (id < 0) return 2;
        if (id != CLI_HELP && j->ngiven < 48) {
            snprintf(j->given[j->ngiven], sizeof j->given[0], "%s", a.name);
            j->given_names[j->ngiven] = j->given[j->ngiven];
            j->ngiven++;
        }
        switch (id) {
        case CLI_HELP: render_usage(stdout); return 0;
        case OPT_PHOTON_OFFSET:
            if (cli_int(&a, 0, 10000000000LL, &v)) return 2;
            opt->photon_offset = (uint64_t)v;
            break;
        case OPT_PRECISION: {
            static const char *const names[] = {"double", "fp32"};
            if ((k = cli_keyword(&a, names, 2)) < 0) return 2;
            opt->precision = k ? PRECISION_FP32 : PRECISION_DOUBLE;
            j->precision_given = 1;
            break;
        }
        case OPT_SCAN: {
            static const char *const names[] = {"bucket", "photon"};
            if ((k = cli_keyword(&a, names, 2)) < 0) return 2;
            opt->scan = k ? SCAN_PHOTON : SCAN_BUCKET;
            break;
        }
        case OPT_OUT:
            if (j->nout == MAX_OUTPUTS) return cli_error(&a, "--out: at most %d outputs", MAX_OUTPUTS);
            if (cli_image_ext(&a, a.val)) return 2;
            j->outs[j->nout++] = a.val;
            break;
        case OPT_STATS: j->stats_path = a.val; break;
        case OPT_MAX_MEMORY: if (cli_size(&a, &opt->max_memory)) return 2; break;
        case OPT_CHECKPOINT: opt->checkpoint = a.val; break;
        case OPT_RESUME: opt->resume = a.val; break;
        case OPT_CHECKPOINT_EVERY:
            if (cli_int(&a, 1000, 1000000000000LL, &v)) return 2;
            opt->checkpoint_every = (uint64_t)v;
            break;
        case OPT_TIME_LIMIT: if (cli_real(&a, 0, 1, 1e9, &opt->time_limit)) return 2; break;
        case OPT_PREES: if (cli_int(&a, 1, 1024, &v)) return 2; opt->prees = (int)v; break;
        case OPT_LIGHT_SAMPLING: {
            static const char *const names[] = {"uniform", "power"};
            if ((k = cli_keyword(&a, names, 2)) < 0) return 2;
            j->light_power = k;
            break;
        }
        case OPT_MAX_BOUNCES:
            if (cli_int(&a, 1, 1000, &v)) return 2;
            j->max_bounces = (int)v;
            break;
        case OPT_SIMD:
            if (cpu_simd_parse(a.val, &k))
                return cli_error(&a, "--simd %s: expected auto, avx512, avx2 or scalar", a.val);
            if (cpu_simd_force(k))
                return cli_error(&a, "--simd %s: this processor lacks %s", a.val, a.val);
            break;
        case OPT_WRITE_EVERY:
        case OPT_WRITE_AT: if (cli_series_option(&a, id == OPT_WRITE_EVERY, &j->series)) return 2; break;
        default:
            if ((k = cli_render_option(&a, id, opt, 1)) == 2) return 2;
            if (k == 1 && cli_pm_option(&a, id, opt)) return 2;
        }
    }
    int nops;
    cli_operands(&a, &nops);
    if (opt->resume && nops == 0) return -1;   /* the scene and the rest from the checkpoint (resume_args) */
    if (!(j->scene_path = cli_scene(&a)) || cli_pm_check(&a, opt)) return 2;
    if (opt->prees > 1 && opt->layout == HP_LAYOUT_PIXEL)
        return cli_error(&a, "--prees %d: a board of PREEs holds the spatial layout (drop --layout pixel)", opt->prees);
    if (opt->datapath == DATAPATH_STABLE && !j->precision_given) opt->precision = PRECISION_FP32;
    if (opt->datapath == DATAPATH_STABLE && opt->precision != PRECISION_FP32)
        return cli_error(&a, "--datapath stable is fp32's (the double mode has no datapath): drop --precision double");
    if ((uint64_t)opt->width * (uint64_t)opt->height > 64ull * 1024 * 1024)
        return cli_error(&a, "%dx%d is more than 64 Mpixels", opt->width, opt->height);
    if (j->nout == 0) {   /* NAME.png in the current folder, NAME the scene's file name less .scene or .pbrt */
        const char *base = strrchr(j->scene_path, '/'), *dot;
        base = base ? base + 1 : j->scene_path;
        int len = (int)strlen(base);
        if ((dot = strrchr(base, '.')) && dot > base && (!strcmp(dot, ".scene") || !strcmp(dot, ".pbrt")))
            len = (int)(dot - base);
        snprintf(j->default_out, sizeof j->default_out, "%.*s.png", len, base);
        j->outs[j->nout++] = j->default_out;
    }
    return -1;
}

/* The note a checkpoint of this render carries (cli_resume.h): 0, or 2 printed. */
static int job_note(const render_options_t *opt, const render_job_t *j, char *note, size_t len)
{
    static char series[16 * CLI_SERIES_MAX + 64];
    int n = snprintf(series, sizeof series, "--light-sampling %s\n", j->light_power ? "power" : "uniform");
    if (j->max_bounces) n += snprintf(series + n, sizeof series - (size_t)n, "--max-bounces %d\n", j->max_bounces);
    cli_series_note(&j->series, series + n, sizeof series - (size_t)n);
    const cli_resume_job_t rj = {.scene = j->scene_path, .stats = j->stats_path, .outs = j->outs, .nout = j->nout,
                                 .series = series};
    return cli_resume_note(opt, &rj, note, len);
}

/* A resume: parse again with the options the checkpoint carries that the command line does not
 * give (into *opt and *j; *rargc, *rargv hold the strings, freed by the caller). -1 to go on,
 * else the exit status. */
static int resume_args(int argc, char **argv, render_options_t *opt, render_job_t *j, int *rargc, char ***rargv)
{
    static char rec[CHECKPOINT_NOTE_MAX], cmd[CHECKPOINT_NOTE_MAX];
    char err[1024];
    uint64_t done;
    if (checkpoint_read_note(opt->resume, rec, sizeof rec, &done, err, sizeof err)) {
        fprintf(stderr, "pree render: %s\n", err);
        return 1;
    }
    if (job_note(opt, j, cmd, sizeof cmd)) return 2;
    const int has_scene = j->scene_path != NULL;
    const int rc = cli_resume_args(opt->resume, rec, cmd, j->given_names, j->ngiven, has_scene, argc, argv, rargc, rargv);
    return rc ? rc : -1;
}

/* Every output checked before any work starts (see cli_outputs.h): 0, or 1 with the error printed. */
static int check_outputs(const render_job_t *j)
{
    cli_file_t in = {"the scene", j->scene_path}, out[MAX_OUTPUTS + 1];
    for (int k = 0; k < j->nout; k++) out[k] = (cli_file_t){"--out", j->outs[k]};
    if (j->stats_path) out[j->nout] = (cli_file_t){"--stats", j->stats_path};
    return cli_outputs_check("render", &in, 1, out, j->nout + (j->stats_path != NULL)) ? 1 : 0;
}

static void catch_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sa.sa_flags = SA_RESETHAND;   /* a second signal ends the process at once */
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);
}

/* What the user should know about a finished render (rc as render_run's). */
static void warn_result(const render_job_t *j, const render_options_t *opt, const render_stats_t *st, int rc)
{
    /* A black image is a correct answer here, but rarely the one intended. */
    if (st->hit_points == 0)
        fprintf(stderr, "pree render: warning: %s: no eye ray reaches a diffuse surface; the image is black\n", j->scene_path);
    else if (st->photon_hits == 0)
        fprintf(stderr, "pree render: warning: %s: no photon reaches a diffuse surface; the image is black\n", j->scene_path);
    /* binary32 positions: one ulp at the hit points' largest coordinate against the initial radius. */
    const double ulp = st->hp_coord_max > 0 ? ldexp(1.0, ilogb(st->hp_coord_max) - 23) : 0;
    if (opt->precision == PRECISION_FP32 && st->r0 > 0 && ulp > 0.01 * st->r0)
        fprintf(stderr, "pree render: warning: %s: hit points lie up to %g from the origin, where one binary32 step "
                "(%g) is %.1f%% of the initial radius %g: fp32 loses accuracy; move the scene towards the origin "
                "(docs/numerics_renders.md, \"Translation\")\n", j->scene_path, st->hp_coord_max, ulp, 100 * ulp / st->r0, st->r0);
    if (st->hit_points_saturated)
        fprintf(stderr, "pree render: warning: %s: %llu hit points reached the stable datapath's wide-format limit "
                "(1/r2 or tau/r2 beyond binary32's range: the radius stopped shrinking there; docs/numerics.md)\n",
                j->scene_path, st->hit_points_saturated);
    if (rc == 1)
        fprintf(stderr, "pree render: interrupted after %llu photons; writing what was made\n",
                (unsigned long long)st->photons_emitted);
    if (st->time_limited)
        fprintf(stderr, "pree render: time limit of %g s reached after %llu photons; writing what was made\n",
                opt->time_limit, (unsigned long long)st->photons_emitted);
}

/* Append path to the list of files written (", "-separated; "..." once it is full). */
static void wrote_add(char *list, size_t len, const char *path)
{
    size_t used = strlen(list);
    if (used + strlen(path) + 8 >= len) {
        if (used + 5 < len && strcmp(list + (used >= 3 ? used - 3 : 0), "...")) strcat(list, ", ...");
        return;
    }
    snprintf(list + used, len - used, "%s%s", used ? ", " : "", path);
}

/* The images and the statistics, each named in wrote when written: 0, or 1 when one of them
 * could not be written (printed). */
static int write_outputs(const render_job_t *j, const render_options_t *opt, const render_result_t *res, int rc,
                         char *wrote, size_t wrote_len)
{
    char err[1024];
    int status = 0;
    for (int k = 0; k < j->nout; k++) {
        if (write_image(j->outs[k], j->scene_path, opt, res, err, sizeof err)) {
            fprintf(stderr, "pree render: %s\n", err);
            status = 1;
        } else {
            wrote_add(wrote, wrote_len, j->outs[k]);
        }
    }
    if (j->stats_path && stats_json_write(j->stats_path, j->scene_path, opt, &res->stats, rc == 1, err, sizeof err)) {
        fprintf(stderr, "pree render: %s\n", err);
        status = 1;
    } else if (j->stats_path) {
        wrote_add(wrote, wrote_len, j->stats_path);
    }
    return status;
}

/* What the convergence series' writer needs (series_write). */
typedef struct {
    const render_job_t *j;
    const render_options_t *opt;
    int written;            /* points written */
} series_ctx_t;

/* A point of the series: every output as NAME-COUNT.EXT. 0, or -1 with err. */
static int series_write(void *ctx, const render_result_t *res, char *err, size_t errlen)
{
    series_ctx_t *c = ctx;
    const render_job_t *j = c->j;
    const uint64_t n = res->stats.photons_emitted;
    char names[MAX_OUTPUTS + 1][4200], list[4096] = "";
    for (int k = 0; k <= j->nout; k++) {
        const char *path = k < j->nout ? j->outs[k] : j->stats_path;
        if (!path) continue;
        if (cli_series_name(path, n, names[k], sizeof names[k])) {
            snprintf(err, errlen, "%s: the name with -%llu is too long", path, (unsigned long long)n);
            return -1;
        }
        const int bad = k < j->nout ? write_image(names[k], j->scene_path, c->opt, res, err, errlen)
                                    : stats_json_write(names[k], j->scene_path, c->opt, &res->stats, 0, err, errlen);
        if (bad) return -1;
        wrote_add(list, sizeof list, names[k]);
    }
    c->written++;
    if (c->opt->progress) fprintf(stderr, "\npree render: %llu photons: wrote %s\n", (unsigned long long)n, list);
    return 0;
}

static int given(const render_job_t *j, const char *name)
{
    for (int k = 0; k < j->ngiven; k++)
        if (!strcmp(j->given[k], name)) return 1;
    return 0;
}

/* What depends on the scene: a pbrt file's Film resolution and photon count where the command
 * line gives none, then the checkpoint's note, the series' points and the rounding note. -1 to
 * go on, else the exit status. */
static int prepare_job(render_options_t *opt, render_job_t *j, scene_t *scene)
{
    static char note[CHECKPOINT_NOTE_MAX];
    char err[1024];
    if (j->light_power && scene_light_power(scene, err, sizeof err)) {
        fprintf(stderr, "pree render: %s\n", err);
        return 1;
    }
    scene->max_bounces = j->max_bounces;
    if (scene->film_width && !given(j, "--width")) opt->width = scene->film_width;
    if (scene->film_height && !given(j, "--height")) opt->height = scene->film_height;
    if (scene->film_photons && !given(j, "--photons")) opt->photons = scene->film_photons;
    if (scene->film_radius > 0 && !given(j, "--radius")) opt->initial_radius = scene->film_radius;
    if ((uint64_t)opt->width * (uint64_t)opt->height > 64ull * 1024 * 1024) {
        fprintf(stderr, "pree render: %dx%d is more than 64 Mpixels\n", opt->width, opt->height);
        return 2;
    }
    if (opt->photons > 10000000000ULL) {
        fprintf(stderr, "pree render: %llu photons is more than 1e10 (give --photons)\n", (unsigned long long)opt->photons);
        return 2;
    }
    if (opt->checkpoint) {
        if (job_note(opt, j, note, sizeof note)) return 2;
        opt->checkpoint_note = note;
    }
    if (cli_series_points(&j->series, render_emitted(opt->photons))) return 2;
    if (opt->progress && render_emitted(opt->photons) != opt->photons)
        fprintf(stderr, "pree render: --photons %llu renders %llu photons (whole batches of 1000)\n",
                (unsigned long long)opt->photons, (unsigned long long)render_emitted(opt->photons));
    return -1;
}

/* Render the job: the exit status. */
static int render_job(render_options_t *opt_in, render_job_t *jp)
{
    render_options_t opt = *opt_in;
    char err[1024];
    int status;
    if (check_outputs(jp)) return 1;
    scene_t scene;
    if (scene_load(jp->scene_path, &scene, err, sizeof err)) {
        fprintf(stderr, "pree render: %s\n", err);
        return 1;
    }
    if ((status = prepare_job(&opt, jp, &scene)) >= 0) {
        scene_free(&scene);
        return status;
    }
    const render_job_t j = *jp;
    if (opt.checkpoint && checkpoint_probe(opt.checkpoint, err, sizeof err)) {
        fprintf(stderr, "pree render: %s\n", err);
        scene_free(&scene);
        return 1;
    }
    catch_signals();
    series_ctx_t sc = {.j = &j, .opt = &opt};
    if (j.series.npoints) {
        opt.write_at = j.series.points;
        opt.write_at_n = j.series.npoints;
        opt.snapshot = series_write;
        opt.snapshot_ctx = &sc;
    }
    render_result_t res;
    char wrote[4096] = "";
    int rc = cli_estimator_render(&scene, &opt, &res, err, sizeof err);
    size_t nonfinite = 0;
    for (size_t i = 0; rc >= 0 && i < (size_t)res.width * res.height * 3; i++) nonfinite += !isfinite(res.rgb[i]);
    if (rc < 0) {
        fprintf(stderr, "pree render: %s: %s%s\n", j.scene_path, err, interrupted ? "; nothing written" : "");
        status = interrupted ? 130 : 1;
    } else if (nonfinite) {   /* never an image of inf or NaN with status 0 */
        fprintf(stderr, "pree render: %s: %zu pixel values are not finite (a light's power beyond the %s range?); "
                "nothing written\n", j.scene_path, nonfinite, opt.precision == PRECISION_FP32 ? "binary32" : "double");
        status = 1;
    } else {
        warn_result(&j, &opt, &res.stats, rc);
        /* Under MPI rank 0 holds the image and writes it (docs/scale_out.md). */
        status = render_dist_rank() == 0 && write_outputs(&j, &opt, &res, rc, wrote, sizeof wrote) ? 1 : rc == 1 ? 130 : 0;
        if (opt.checkpoint) wrote_add(wrote, sizeof wrote, opt.checkpoint);
        const render_stats_t *st = &res.stats;
        if (st->mpi_ranks > 1 && opt.progress)
            fprintf(stderr, "pree render: %d MPI ranks: %.1f bytes sent per photon; %.1f%% of the kept candidates "
                    "cross ranks (their hit point's owner is not the rank that traced the photon)\n", st->mpi_ranks,
                    st->photons_emitted ? (double)st->mpi_bytes_sent / (double)st->photons_emitted : 0.0,
                    st->mpi_kept ? 100.0 * (double)st->mpi_kept_foreign / (double)st->mpi_kept : 0.0);
        if (opt.progress)
            fprintf(stderr, "pree render: %llu hit points, %llu photons, %llu candidates, %llu accepted, %.3f s\n",
                    res.stats.hit_points, res.stats.photons_emitted, res.stats.upd.candidates,
                    res.stats.upd.accepted, res.stats.sec_total);
        /* The last line: every file this render wrote. */
        if (opt.progress && render_dist_rank() == 0)
            fprintf(stderr, "pree render: wrote %s%s\n", *wrote ? wrote : "nothing",
                    sc.written ? "; the series above" : "");
    }
    render_result_free(&res);
    scene_free(&scene);
    return status;
}

int pree_cmd_render(int argc, char **argv)
{
    const render_options_t defaults = {.width = 320, .height = 240, .photons = 768000, .precision = PRECISION_DOUBLE,
                                       .grid = GRID_CELLS, .preu = 4, .progress = 1, .interrupt = &interrupted};
    static render_job_t j;
    render_options_t opt = defaults;
    int status = parse_args(argc, argv, &opt, &j), rargc = 0;
    char **rargv = NULL;
    if (status < 0 && opt.resume) {   /* again, with the options the checkpoint carries */
        if ((status = resume_args(argc, argv, &opt, &j, &rargc, &rargv)) < 0) {
            opt = defaults;
            memset(&j, 0, sizeof j);
            status = parse_args(rargc, rargv, &opt, &j);
        }
    }
    if (status < 0) status = render_job(&opt, &j);
    if (rargv) cli_resume_free(rargc, rargv);
    return status;
}
