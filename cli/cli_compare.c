// SPDX-License-Identifier: Apache-2.0
/* cli_compare.c: `pree compare IMAGE_A IMAGE_B [--diff OUT] [--log] [--flip] [--json]`: print SSIM, SNR,
 * PSNR, RMSE and the maximum absolute difference of B against the reference A, and write the
 * difference maps (diffmap.h). */
#include "cli.h"
#include "cli_options.h"
#include "cli_outputs.h"
#include "compare.h"
#include "diffmap.h"
#include "flip.h"
#include "image.h"
#include "json_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static void usage(FILE *f)
{
    fprintf(f,
        "usage: pree compare IMAGE_A IMAGE_B [--diff OUT] [--log] [--flip] [--json]\n"
        "\n"
        "Compare IMAGE_B against the reference IMAGE_A (.png, .ppm or .exr, same size and sample\n"
        "type) and print one 'key value' line per figure: width, height, peak (the dynamic\n"
        "range L: 255 for 8-bit images, the reference's max - min for float images), ssim,\n"
        "snr_db, psnr_db (inf when identical), rmse, max_abs.\n"
        "\n"
        "  --diff OUT  also write difference maps. OUT.png or OUT.ppm: three false-colour pictures\n"
        "              (black = none, then red, yellow, white = the largest), each with a colour\n"
        "              bar and its values below: OUT the relative error, per pixel the largest\n"
        "              channel's |A - B| / (|A| + 0.01 peak); OUT-abs the absolute error |A - B|;\n"
        "              OUT-ssim the SSIM map (1 - SSIM drawn, SSIM on the labels). Each bar's top\n"
        "              is its map's maximum, printed as rel_max, max_abs and ssim_min.\n"
        "              OUT.exr: |A - B| per channel, linear\n"
        "  --log       the maps' colour on a log scale (four decades below the maximum)\n"
        "  --flip      also LDR-FLIP (Andersson et al. 2020, 67 pixels per degree): the mean as\n"
        "              'flip'; with --diff the map as OUT-flip, its largest pixel as flip_max.\n"
        "              Float images are compared through the engine's display transform\n"
        "  --json      print the figures as one JSON object instead (inf as the string \"inf\")\n"
        "\n"
        "Exit status: 0 success, 1 unreadable image, size or type mismatch, or write failure,\n"
        "2 usage error. See docs/compare.md for the exact definitions.\n");
}

/* A figure as text for people: "inf"/"-inf" for infinities, else 10 significant digits. */
static void fmt_num(char *buf, size_t len, double v)
{
    if (isinf(v)) snprintf(buf, len, "%s", v > 0 ? "inf" : "-inf");
    else snprintf(buf, len, "%.10g", v);
}

/* OUT with SUFFIX before its extension: "d.png" + "-abs" = "d-abs.png". */
static void suffixed(char *buf, size_t len, const char *path, const char *suffix)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    size_t stem = dot ? (size_t)(dot - path) : strlen(path);
    snprintf(buf, len, "%.*s%s%s", (int)stem, path, suffix, dot ? dot : "");
}

/* Draw field e (w x h) with scale s into an 8-bit picture with its colour bar at path. */
static int write_field(const char *path, const double *e, int w, int h, const pree_scale_t *s,
                       char *err, size_t errlen)
{
    int cw, ch;
    pree_diffmap_size(w, h, &cw, &ch);
    unsigned char *u = malloc((size_t)3 * cw * ch);
    if (!u) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    pree_diffmap_draw(e, w, h, s, u);
    int rc = pree_image_write_u8(path, cw, ch, u, err, errlen);
    free(u);
    return rc;
}

/* The --diff figures: each field's scale maximum (what the top of its bar stands for). */
typedef struct { int valid; double rel_max, abs_max, ssim_min, flip_max; } diff_figs_t;

/* --diff OUT.png|.ppm: OUT the relative error, OUT-abs the absolute error, OUT-ssim the SSIM
 * map, each in false colour with its bar; OUT.exr: linear |A - B| per channel. On failure no
 * file of the set is left. */
static int write_diff(const char *path, const pree_image_t *a, const pree_image_t *b, double peak,
                      int log, const double *flip, diff_figs_t *f, char *err, size_t errlen)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    const int w = a->width, h = a->height;
    size_t n = (size_t)w * h * 3;
    int rc = -1;
    if (dot && !strcasecmp(dot, ".exr")) {
        double *d = malloc(n * sizeof *d);
        if (!d) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
        for (size_t i = 0; i < n; i++) d[i] = fabs((double)a->rgb[i] - (double)b->rgb[i]);
        rc = pree_image_write(path, w, h, d, err, errlen);
        free(d);
        return rc;
    }
    char names[4][4096];
    snprintf(names[0], sizeof names[0], "%s", path);
    suffixed(names[1], sizeof names[1], path, "-abs");
    suffixed(names[2], sizeof names[2], path, "-ssim");
    suffixed(names[3], sizeof names[3], path, "-flip");
    double *e = malloc(sizeof(double) * w * h);
    if (!e) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    int done = 0;
    pree_scale_t s = {0};
    pree_err_rel(a->rgb, b->rgb, w, h, PREE_REL_EPS * peak, e);
    f->rel_max = pree_scale_fit(e, (long)w * h, log, &s);
    s.title = log ? "rel err (log)" : "rel err";
    if (write_field(names[0], e, w, h, &s, err, errlen)) goto out;
    done = 1;
    pree_err_abs(a->rgb, b->rgb, w, h, e);
    f->abs_max = pree_scale_fit(e, (long)w * h, log, &s);
    s.title = log ? "abs err (log)" : "abs err";
    if (write_field(names[1], e, w, h, &s, err, errlen)) goto out;
    done = 2;
    if (isnan(pree_ssim_map(a->rgb, b->rgb, w, h, peak, e))) {
        snprintf(err, errlen, "%.900s: out of memory", names[2]);
        goto out;
    }
    for (long p = 0; p < (long)w * h; p++) e[p] = 1.0 - e[p];   /* drawn as 1 - SSIM */
    f->ssim_min = 1.0 - pree_scale_fit(e, (long)w * h, log, &s);
    s.one_minus = 1;
    s.title = log ? "ssim (log 1-ssim)" : "ssim";
    if (write_field(names[2], e, w, h, &s, err, errlen)) goto out;
    done = 3;
    if (flip) {
        f->flip_max = pree_scale_fit(flip, (long)w * h, log, &s);
        s.one_minus = 0;
        s.title = log ? "flip (log)" : "flip";
        if (write_field(names[3], flip, w, h, &s, err, errlen)) goto out;
    }
    rc = 0;
    f->valid = 1;
out:
    for (int k = 0; rc && k < done; k++) remove(names[k]);
    free(e);
    return rc;
}

/* The FLIP map of b against a (display values, flip.h) and its mean in *mean; NULL when out
 * of memory. */
static double *compute_flip(const pree_image_t *a, const pree_image_t *b, double *mean)
{
    const size_t n = (size_t)a->width * a->height;
    float *da = malloc(sizeof(float) * 3 * n), *db = malloc(sizeof(float) * 3 * n);
    double *map = malloc(sizeof(double) * n);
    if (da && db && map) {
        pree_flip_input(a, da);
        pree_flip_input(b, db);
        *mean = pree_flip(da, db, a->width, a->height, PREE_FLIP_PPD, map);
    }
    free(da);
    free(db);
    if (map && isnan(*mean)) { free(map); map = NULL; }
    return map;
}

enum { OPT_DIFF = CLI_OWN, OPT_JSON, OPT_LOG, OPT_FLIP };

static const struct option compare_longopts[] = {
    {"help", no_argument, NULL, CLI_HELP},
    {"diff", required_argument, NULL, OPT_DIFF},
    {"json", no_argument, NULL, OPT_JSON},
    {"log", no_argument, NULL, OPT_LOG},
    {"flip", no_argument, NULL, OPT_FLIP},
    {NULL, 0, NULL, 0}
};

/* The figures on stdout, as lines "key value" or (json) one JSON object: the metrics m, FLIP's
 * mean (flip_mean, with --flip), the maps' scale tops (figs, with --diff). 0, or -1 when they
 * cannot be written. */
static int print_figures(char **files, const pree_image_t *a, const pree_metrics_t *m, const double *flip_mean,
                         const diff_figs_t *figs, int json)
{
    const char *keys[11] = {"peak", "ssim", "snr_db", "psnr_db", "rmse", "max_abs"};
    double vals[11] = {m->peak, m->ssim, m->snr_db, m->psnr_db, m->rmse, m->max_abs};
    size_t nkeys = 6;
    if (flip_mean) { keys[nkeys] = "flip"; vals[nkeys++] = *flip_mean; }
    if (figs->valid) {
        keys[nkeys] = "rel_max"; vals[nkeys++] = figs->rel_max;
        keys[nkeys] = "ssim_min"; vals[nkeys++] = figs->ssim_min;
        if (flip_mean) { keys[nkeys] = "flip_max"; vals[nkeys++] = figs->flip_max; }
    }
    if (json) {
        json_t *fig = json_object();
        json_set_str(fig, "image_a", files[0]);
        json_set_str(fig, "image_b", files[1]);
        json_set_u64(fig, "width", (uint64_t)a->width);
        json_set_u64(fig, "height", (uint64_t)a->height);
        for (size_t k = 0; k < nkeys; k++)   /* JSON has no infinity */
            json_object_set_new(fig, keys[k], isinf(vals[k]) ? json_string(vals[k] > 0 ? "inf" : "-inf")
                                                           : json_real(vals[k]));
        return json_file_print(stdout, fig) ? -1 : 0;
    }
    char num[64];
    printf("width %d\nheight %d\n", a->width, a->height);
    for (size_t k = 0; k < nkeys; k++) {
        fmt_num(num, sizeof num, vals[k]);
        printf("%s %s\n", keys[k], num);
    }
    return 0;
}

int pree_cmd_compare(int argc, char **argv)
{
    const char *diff = NULL;
    int json = 0, log = 0, want_flip = 0;
    diff_figs_t figs = {0};
    cli_args_t o;
    cli_begin(&o, argc, argv, "compare", compare_longopts, NULL, 0);
    for (int id; (id = cli_next(&o)) != 0;) {
        if (id < 0) return 2;
        if (id == CLI_HELP) { usage(stdout); return 0; }
        if (id == OPT_JSON) json = 1;
        if (id == OPT_LOG) log = 1;
        if (id == OPT_FLIP) want_flip = 1;
        if (id == OPT_DIFF) {
            diff = o.val;
            if (!*diff) return cli_error(&o, "--diff: empty output file name");
        }
    }
    int nfiles;
    char **files = cli_operands(&o, &nfiles);
    if (nfiles > 2) return cli_error(&o, "too many images: '%s' (give exactly two)", files[2]);
    if (nfiles != 2)
        return cli_error(&o, "needs two images (usage: pree compare IMAGE_A IMAGE_B [--diff OUT] [--log] [--flip] [--json])");
    if (diff) {   /* before any work: never over an input, a device or a missing directory */
        cli_file_t in[2] = {{"IMAGE_A", files[0]}, {"IMAGE_B", files[1]}}, out = {"--diff", diff};
        if (cli_outputs_check("compare", in, 2, &out, 1)) return 1;
    }

    char err[1024], errs[2][1024];
    pree_image_t img[2] = {{0}, {0}};
    int bad[2];
    pree_metrics_t m;
    int rc = 1;
    /* Read both images at once (decoding a 4k PNG takes a good part of a second). */
    #pragma omp parallel for num_threads(2)
    for (int k = 0; k < 2; k++) bad[k] = pree_image_read(files[k], &img[k], errs[k], sizeof errs[k]);
    pree_image_t a = img[0], b = img[1];
    for (int k = 0; k < 2; k++)
        if (bad[k]) {
            fprintf(stderr, "pree compare: %s\n", errs[k]);
            goto done;
        }
    if (pree_compare(&a, &b, &m, err, sizeof err)) {
        fprintf(stderr, "pree compare: %s vs %s: %s\n", files[0], files[1], err);
        goto done;
    }
    double flip_mean = NAN, *flip = want_flip ? compute_flip(&a, &b, &flip_mean) : NULL;
    if (want_flip && !flip) { fprintf(stderr, "pree compare: FLIP: out of memory\n"); goto done; }
    int bad_diff = diff && write_diff(diff, &a, &b, m.peak, log, flip, &figs, err, sizeof err);
    free(flip);
    if (bad_diff) {
        fprintf(stderr, "pree compare: --diff: %s\n", err);
        goto done;
    }

    if (print_figures(files, &a, &m, want_flip ? &flip_mean : NULL, &figs, json)) {
        fprintf(stderr, "pree compare: cannot write the figures\n");
        goto done;
    }
    if (fflush(stdout) != 0) { fprintf(stderr, "pree compare: cannot write the figures\n"); goto done; }
    rc = 0;
done:
    pree_image_free(&a);
    pree_image_free(&b);
    return rc;
}
