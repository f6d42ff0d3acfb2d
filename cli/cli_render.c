/* cli_render.c: `pree render SCENE [options]`: parse and check the options, render, write
 * the images and the statistics. Ctrl-C stops after the current photon block and writes
 * the image of the photons done so far; the exit status is then 130. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli.h"
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
        "  --quiet                no progress on stderr\n");
}

enum { OPT_PHOTON_OFFSET = CLI_OWN, OPT_PRECISION, OPT_SCAN, OPT_OUT, OPT_STATS };

static const struct option render_longopts[] = {
    CLI_RENDER_LONGOPTS,
    {"photon-offset", required_argument, NULL, OPT_PHOTON_OFFSET},
    {"precision", required_argument, NULL, OPT_PRECISION},
    {"scan", required_argument, NULL, OPT_SCAN},
    {"out", required_argument, NULL, OPT_OUT},
    {"stats", required_argument, NULL, OPT_STATS},
    {NULL, 0, NULL, 0}
};

int pree_cmd_render(int argc, char **argv)
{
    render_options_t opt = {.width = 320, .height = 240, .photons = 768000, .precision = PRECISION_DOUBLE,
                            .grid = GRID_CELLS, .preu = 4, .progress = 1, .interrupt = &interrupted};
    const char *scene_path, *stats_path = NULL;
    const char *outs[MAX_OUTPUTS];
    int nout = 0;
    char err[1024];
    cli_args_t a;
    cli_begin(&a, argc, argv, "render", render_longopts, &opt, 1);
    for (int id; (id = cli_next(&a)) != 0;) {
        long long v;
        int k;
        if (id < 0) return 2;
        switch (id) {
        case CLI_HELP: render_usage(stdout); return 0;
        case OPT_PHOTON_OFFSET:
            if (cli_int(&a, 0, 10000000000LL, &v)) return 2;
            opt.photon_offset = (uint64_t)v;
            break;
        case OPT_PRECISION: {
            static const char *const names[] = {"double", "fp32"};
            if ((k = cli_keyword(&a, names, 2)) < 0) return 2;
            opt.precision = k ? PRECISION_FP32 : PRECISION_DOUBLE;
            break;
        }
        case OPT_SCAN: {
            static const char *const names[] = {"bucket", "photon"};
            if ((k = cli_keyword(&a, names, 2)) < 0) return 2;
            opt.scan = k ? SCAN_PHOTON : SCAN_BUCKET;
            break;
        }
        case OPT_OUT:
            if (nout == MAX_OUTPUTS) return cli_error(&a, "--out: at most %d outputs", MAX_OUTPUTS);
            if (cli_image_ext(&a, a.val)) return 2;
            outs[nout++] = a.val;
            break;
        case OPT_STATS: stats_path = a.val; break;
        }
    }
    if (!(scene_path = cli_scene(&a))) return 2;
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
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    render_result_t res;
    int rc = render_run(&scene, &opt, &res, err, sizeof err);
    if (rc < 0) {
        fprintf(stderr, "pree render: %s: %s\n", scene_path, err);
        render_result_free(&res);
        scene_free(&scene);
        return 1;
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
