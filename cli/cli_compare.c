/* cli_compare.c: `pree compare IMAGE_A IMAGE_B [--diff OUT] [--json]`: print SSIM, SNR, PSNR,
 * RMSE and the maximum absolute difference of B against the reference A. */
#include "cli.h"
#include "cli_options.h"
#include "compare.h"
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
        "usage: pree compare IMAGE_A IMAGE_B [--diff OUT] [--json]\n"
        "\n"
        "Compare IMAGE_B against the reference IMAGE_A (.png, .ppm or .exr, same size and sample\n"
        "type) and print one 'key value' line per figure: width, height, peak (the dynamic\n"
        "range L: 255 for 8-bit images, the reference's max - min for float images), ssim,\n"
        "snr_db, psnr_db (inf when identical), rmse, max_abs.\n"
        "\n"
        "  --diff OUT  also write a difference image: OUT.png or OUT.ppm gets a heat map of the\n"
        "              per-pixel largest channel difference scaled by its maximum (black = none,\n"
        "              then red, yellow, white = max_abs); OUT.exr gets |A - B| per channel, linear\n"
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

/* Write the --diff image: a heat map for .png/.ppm, linear |a - b| for .exr. */
static int write_diff(const char *path, const pree_image_t *a, const pree_image_t *b,
                      char *err, size_t errlen)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    size_t n = (size_t)a->width * a->height * 3;
    int rc;
    if (dot && !strcasecmp(dot, ".exr")) {
        double *d = malloc(n * sizeof *d);
        if (!d) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
        for (size_t i = 0; i < n; i++) d[i] = fabs((double)a->rgb[i] - (double)b->rgb[i]);
        rc = pree_image_write(path, a->width, a->height, d, err, errlen);
        free(d);
    } else {
        unsigned char *u = malloc(n);
        if (!u) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
        pree_diff_heatmap(a->rgb, b->rgb, a->width, a->height, u);
        rc = pree_image_write_u8(path, a->width, a->height, u, err, errlen);
        free(u);
    }
    return rc;
}

enum { OPT_DIFF = CLI_OWN, OPT_JSON };

static const struct option compare_longopts[] = {
    {"help", no_argument, NULL, CLI_HELP},
    {"diff", required_argument, NULL, OPT_DIFF},
    {"json", no_argument, NULL, OPT_JSON},
    {NULL, 0, NULL, 0}
};

int pree_cmd_compare(int argc, char **argv)
{
    const char *diff = NULL;
    int json = 0;
    cli_args_t o;
    cli_begin(&o, argc, argv, "compare", compare_longopts, NULL, 0);
    for (int id; (id = cli_next(&o)) != 0;) {
        if (id < 0) return 2;
        if (id == CLI_HELP) { usage(stdout); return 0; }
        if (id == OPT_JSON) json = 1;
        if (id == OPT_DIFF) {
            diff = o.val;
            if (!*diff) return cli_error(&o, "--diff: empty output file name");
        }
    }
    int nfiles;
    char **files = cli_operands(&o, &nfiles);
    if (nfiles > 2) return cli_error(&o, "too many images: '%s' (give exactly two)", files[2]);
    if (nfiles != 2)
        return cli_error(&o, "needs two images (usage: pree compare IMAGE_A IMAGE_B [--diff OUT] [--json])");

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
    if (diff && write_diff(diff, &a, &b, err, sizeof err)) {
        fprintf(stderr, "pree compare: --diff: %s\n", err);
        goto done;
    }

    const char *keys[] = {"peak", "ssim", "snr_db", "psnr_db", "rmse", "max_abs"};
    const double vals[] = {m.peak, m.ssim, m.snr_db, m.psnr_db, m.rmse, m.max_abs};
    char num[64];
    if (json) {
        json_t *fig = json_object();
        json_set_str(fig, "image_a", files[0]);
        json_set_str(fig, "image_b", files[1]);
        json_set_u64(fig, "width", (uint64_t)a.width);
        json_set_u64(fig, "height", (uint64_t)a.height);
        for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)   /* JSON has no infinity */
            json_object_set_new(fig, keys[k], isinf(vals[k]) ? json_string(vals[k] > 0 ? "inf" : "-inf")
                                                           : json_real(vals[k]));
        if (json_file_print(stdout, fig)) { fprintf(stderr, "pree compare: cannot write the figures\n"); goto done; }
    } else {
        printf("width %d\nheight %d\n", a.width, a.height);
        for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
            fmt_num(num, sizeof num, vals[k]);
            printf("%s %s\n", keys[k], num);
        }
    }
    if (fflush(stdout) != 0) { fprintf(stderr, "pree compare: cannot write the figures\n"); goto done; }
    rc = 0;
done:
    pree_image_free(&a);
    pree_image_free(&b);
    return rc;
}
