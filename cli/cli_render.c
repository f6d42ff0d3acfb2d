/* cli_render.c: `pree render SCENE [options]`: parse and check the options, render, write
 * the images and the statistics. SIGINT or SIGTERM stops the render in any phase (the photon
 * block in progress is abandoned) and writes the image of the photon blocks done so far, or
 * nothing when no block was done; the exit status is then 130. SIGPIPE is ignored: a closed
 * stderr stops the progress, never the render. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli.h"
#include "checkpoint.h"
#include "cli_options.h"
#include "image.h"
#include "render.h"
#include "stats_json.h"

#define MAX_OUTPUTS 8

static volatile sig_atomic_t interrupted;
static void on_sigint(int sig) { (void)sig; interrupted = 1; }

static void render_usage(FILE *f)
{
    fprintf(f,
        "usage: pree render SCENE [options]\n"
        "  --width W              image width in pixels (default 320)\n"
        "  --height H             image height in pixels (default 240)\n"
        "  --photons N            photons to emit, rounded down to whole 1000s (default 768000)\n"
        "  --photon-offset K      trace photon k with Halton index K + k (default 0): a reference render\n"
        "                         whose photon paths are disjoint from those of the renders it judges\n"
        "  --precision P          double (the reference) or fp32 (the PREE datapath's arithmetic)\n"
        "  --datapath D           fp32: paper (default: the paper's PREU, bit for bit) or stable (exact\n"
        "                         count, wide 1/r2 and tau/r2: accurate for any photon count)\n"
        "  --alpha A              the radius reduction alpha, in (0, 1] (default 0.7)\n"
        "  --grid G               cells (default: exact cells, skips), smallppm (the reference program's\n"
        "                         hash grid, exact counts) or brute (every hit point, for tests)\n"
        "  --scan S               bucket (default: a block's candidates bucket by bucket, then applied in\n"
        "                         photon order) or photon (photon by photon; the oracle); same bits\n"
        "  --no-skip              disable the skips (zero-weight hit points, empty cells, far candidates)\n"
        "  --preu P               fp32: the PREE's PREU count (4, 8 or 16, default 4), which sets the\n"
        "                         radiance pass's per-pixel order (docs/pree_top.md)\n"
        "  --threads T            OpenMP threads (default: all cores); the image does not depend on T\n"
        "  --out IMAGE            .png, .ppm or .exr; may be given several times (default SCENE-NAME.png)\n"
        "  --stats FILE.json      write the statistics\n"
        "  --checkpoint FILE      write the render's state to FILE every --checkpoint-every photons and\n"
        "                         when the photon pass ends or is interrupted (atomically)\n"
        "  --checkpoint-every N   photons between checkpoints (default 1024000)\n"
        "  --resume FILE          continue from a checkpoint of the same scene, options and build: the\n"
        "                         same bits as an uninterrupted render, for any --threads\n"
        "  --time-limit S         stop after the photon block in progress once S seconds have passed;\n"
        "                         the image holds the photons done (stats: photons_emitted), exit 0\n"
        "  --quiet                no progress on stderr\n");
}

int pree_cmd_render(int argc, char **argv)
{
    render_options_t opt = {.width = 320, .height = 240, .photons = 768000, .precision = PRECISION_DOUBLE,
                            .grid = GRID_CELLS, .preu = 4, .progress = 1, .interrupt = &interrupted};
    const char *scene_path = NULL, *stats_path = NULL;
    const char *outs[MAX_OUTPUTS];
    int nout = 0;
    char err[1024];
    cli_args_t a = {argc, argv, 1, "render"};
    while (a.i < argc) {
        const char *arg = argv[a.i++];
        long long v;
        int r = cli_render_option(&a, arg, &opt, 1);
        if (r != 1) { if (r) return r; continue; }
        if (!strcmp(arg, "--help") || !strcmp(arg, "-h")) { render_usage(stdout); return 0; }
        else if (!strcmp(arg, "--photon-offset")) {
            if (cli_int(&a, arg, 0, 10000000000LL, &v)) return 2;
            opt.photon_offset = (uint64_t)v;
        } else if (!strcmp(arg, "--threads")) { if (cli_int(&a, arg, 1, 1024, &v)) return 2; opt.threads = (int)v; }
        else if (!strcmp(arg, "--precision")) {
            const char *s = cli_value(&a, arg);
            if (!s) return 2;
            if (!strcmp(s, "double")) opt.precision = PRECISION_DOUBLE;
            else if (!strcmp(s, "fp32")) opt.precision = PRECISION_FP32;
            else return cli_error(&a, "--precision: '%s' is not double or fp32", s);
        } else if (!strcmp(arg, "--scan")) {
            const char *s = cli_value(&a, arg);
            if (!s) return 2;
            if (!strcmp(s, "bucket")) opt.scan = SCAN_BUCKET;
            else if (!strcmp(s, "photon")) opt.scan = SCAN_PHOTON;
            else return cli_error(&a, "--scan: '%s' is not bucket or photon", s);
        } else if (!strcmp(arg, "--out")) {
            const char *s = cli_value(&a, arg);
            if (!s) return 2;
            if (nout == MAX_OUTPUTS) return cli_error(&a, "--out: at most %d outputs", MAX_OUTPUTS);
            if (cli_image_ext(&a, s)) return 2;
            outs[nout++] = s;
        } else if (!strcmp(arg, "--stats")) { if (!(stats_path = cli_value(&a, arg))) return 2; }
        else if (!strcmp(arg, "--checkpoint")) { if (!(opt.checkpoint = cli_value(&a, arg))) return 2; }
        else if (!strcmp(arg, "--resume")) { if (!(opt.resume = cli_value(&a, arg))) return 2; }
        else if (!strcmp(arg, "--checkpoint-every")) {
            if (cli_int(&a, arg, 1000, 1000000000000LL, &v)) return 2;
            opt.checkpoint_every = (uint64_t)v;
        } else if (!strcmp(arg, "--time-limit")) {
            if (cli_real(&a, arg, 0, 1, 1e9, &opt.time_limit)) return 2;
        }
        else if (arg[0] == '-' && arg[1]) return cli_error(&a, "unknown option '%s' (see 'pree render --help')", arg);
        else if (scene_path) return cli_error(&a, "more than one scene given ('%s' and '%s')", scene_path, arg);
        else scene_path = arg;
    }
    if (!scene_path) return cli_error(&a, "no scene given (usage: pree render SCENE [options])");
    if (opt.datapath == DATAPATH_STABLE && opt.precision != PRECISION_FP32)
        return cli_error(&a, "--datapath stable needs --precision fp32 (the double mode has no datapath)");
    if ((uint64_t)opt.width * (uint64_t)opt.height > 64ull * 1024 * 1024)
        return cli_error(&a, "%dx%d is more than 64 Mpixels", opt.width, opt.height);
    char default_out[600];
    if (nout == 0) {
        const char *base = strrchr(scene_path, '/');
        base = base ? base + 1 : scene_path;
        snprintf(default_out, sizeof default_out, "%s.png", base);
        outs[nout++] = default_out;
    }

    scene_t scene;
    if (scene_load(scene_path, &scene, err, sizeof err)) {
        fprintf(stderr, "pree render: %s\n", err);
        return 1;
    }
    if (opt.checkpoint && checkpoint_probe(opt.checkpoint, err, sizeof err)) {
        fprintf(stderr, "pree render: %s\n", err);
        scene_free(&scene);
        return 1;
    }
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);
    render_result_t res;
    int rc = render_run(&scene, &opt, &res, err, sizeof err);
    if (rc < 0) {
        fprintf(stderr, "pree render: %s: %s%s\n", scene_path, err, interrupted ? "; nothing written" : "");
        render_result_free(&res);
        scene_free(&scene);
        return interrupted ? 130 : 1;
    }
    int status = rc == 1 ? 130 : 0;
    /* A black image is a correct answer here, but rarely the one intended. */
    if (res.stats.hit_points == 0)
        fprintf(stderr, "pree render: warning: %s: no eye ray reaches a diffuse surface; the image is black\n", scene_path);
    else if (res.stats.photon_hits == 0)
        fprintf(stderr, "pree render: warning: %s: no photon reaches a diffuse surface; the image is black\n", scene_path);
    if (res.stats.hit_points_saturated)
        fprintf(stderr, "pree render: warning: %s: %llu hit points reached the stable datapath's wide-format limit "
                "(1/r2 or tau/r2 beyond binary32's range: the radius stopped shrinking there; docs/numerics.md)\n",
                scene_path, res.stats.hit_points_saturated);
    if (rc == 1)
        fprintf(stderr, "pree render: interrupted after %llu photons; writing what was made\n",
                (unsigned long long)res.stats.photons_emitted);
    if (res.stats.time_limited)
        fprintf(stderr, "pree render: time limit of %g s reached after %llu photons; writing what was made\n",
                opt.time_limit, (unsigned long long)res.stats.photons_emitted);
    for (int k = 0; k < nout; k++) {
        if (pree_image_write(outs[k], res.width, res.height, res.rgb, err, sizeof err)) {
            fprintf(stderr, "pree render: %s\n", err);
            status = 1;
        }
    }
    if (stats_path && stats_json_write(stats_path, scene_path, &opt, &res.stats, rc == 1, err, sizeof err)) {
        fprintf(stderr, "pree render: %s\n", err);
        status = 1;
    }
    if (opt.progress)
        fprintf(stderr, "pree render: %llu hit points, %llu photons, %llu candidates, %llu accepted, %.3f s\n",
                res.stats.hit_points, res.stats.photons_emitted, res.stats.upd.candidates,
                res.stats.upd.accepted, res.stats.sec_total);
    render_result_free(&res);
    scene_free(&scene);
    return status;
}
