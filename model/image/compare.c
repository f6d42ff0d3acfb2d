// SPDX-License-Identifier: Apache-2.0
/* compare.c: SSIM (Wang et al. 2004, Gaussian 11x11, valid windows), SNR, PSNR, RMSE and the
 * maximum absolute difference between two RGB images, plus a false-colour difference map.
 * SSIM is separable: each input row is filtered horizontally into five moment rows (a, b, a^2,
 * b^2, ab) kept in a ring of 11, then each output row filters the ring vertically. The output
 * is cut into fixed tiles (channel x band of rows x strip of columns, small enough for the ring
 * to stay in cache) whose sums are added in a fixed order, so the result is the same for any
 * number of threads. The loops are SIMD without reassociation, so every lane rounds exactly as
 * the scalar code would. */
#include "compare.h"
#include "diffmap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIN     PREE_SSIM_WINDOW   /* window side */
#define RAD     (WIN / 2)          /* window radius: 5 */
#define SIGMA   1.5
#define K1      0.01
#define K2      0.03
#define NMOM    5                  /* moments filtered: a, b, a*a, b*b, a*b */
#define BAND    256                /* output rows per tile */
#define STRIP   256                /* output columns per tile */

/* An AVX2 copy of the hot loop where the CPU has it (same IEEE results: no FMA contraction). */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PREE_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PREE_SIMD_CLONES
#endif

/* The 1-D Gaussian weights g[0..10], exp(-(k-5)^2 / (2 sigma^2)) normalised to sum 1; the 2-D
 * window weight is g[i] * g[j], which also sums to 1. */
static void gauss_weights(double g[WIN])
{
    double sum = 0.0;
    for (int k = 0; k < WIN; k++) {
        double d = k - RAD;
        g[k] = exp(-d * d / (2.0 * SIGMA * SIGMA));
        sum += g[k];
    }
    for (int k = 0; k < WIN; k++) g[k] /= sum;
}

/* out[x] = sum_k g[k] in[x+k] for x < n, folding the symmetric taps. */
static inline void hfilter(const double *restrict in, double *restrict out, int n, const double *g)
{
    const double g0 = g[0], g1 = g[1], g2 = g[2], g3 = g[3], g4 = g[4], g5 = g[5];
    #pragma omp simd
    for (int x = 0; x < n; x++)
        out[x] = g5 * in[x + 5] + g0 * (in[x] + in[x + 10]) + g1 * (in[x + 1] + in[x + 9])
               + g2 * (in[x + 2] + in[x + 8]) + g3 * (in[x + 3] + in[x + 7]) + g4 * (in[x + 4] + in[x + 6]);
}

/* out[x] = sum_k g[k] rows[k][x] for x < n, the same fold and order as hfilter. */
static inline void vfilter(const double *const rows[WIN], double *restrict out, int n, const double *g)
{
    const double g0 = g[0], g1 = g[1], g2 = g[2], g3 = g[3], g4 = g[4], g5 = g[5];
    const double *restrict r0 = rows[0], *restrict r1 = rows[1], *restrict r2 = rows[2];
    const double *restrict r3 = rows[3], *restrict r4 = rows[4], *restrict r5 = rows[5];
    const double *restrict r6 = rows[6], *restrict r7 = rows[7], *restrict r8 = rows[8];
    const double *restrict r9 = rows[9], *restrict r10 = rows[10];
    #pragma omp simd
    for (int x = 0; x < n; x++)
        out[x] = g5 * r5[x] + g0 * (r0[x] + r10[x]) + g1 * (r1[x] + r9[x]) + g2 * (r2[x] + r8[x])
               + g3 * (r3[x] + r7[x]) + g4 * (r4[x] + r6[x]);
}

/* One tile: channel c, output rows [y0, y1), output columns [x0, x0 + n) of an image w wide
 * (output (x, y) is the window whose top-left input pixel is (x, y)). Puts the sum of the SSIM
 * map over the tile in *sum_out, and, when map_out is not NULL, the map itself at map_out[y * wv + x];
 * returns 0, or -1 when out of memory. */
PREE_SIMD_CLONES
static int ssim_tile(const float *a, const float *b, int w, int c, int y0, int y1, int x0, int n,
                     double c1, double c2, const double *g, double *sum_out, double *map_out, int wv)
{
    const int nin = n + WIN - 1;   /* input columns the tile reads */
    double *mem = malloc(sizeof(double) * ((size_t)NMOM * nin + (size_t)(WIN + 1) * NMOM * n + n));
    if (!mem) return -1;
    double *in = mem;                              /* NMOM rows of nin: one input row's moments */
    double *ring = in + (size_t)NMOM * nin;        /* WIN slots of NMOM rows of n */
    double *mom = ring + (size_t)WIN * NMOM * n;   /* NMOM rows of n: windowed moments */
    double *map = mom + (size_t)NMOM * n;          /* one row of the SSIM map */
    double sum = 0.0;

    for (int r = y0; r < y1 + WIN - 1; r++) {
        /* Load input row r of channel c and its products. */
        const float *pa = a + 3 * ((size_t)r * w + x0) + c, *pb = b + 3 * ((size_t)r * w + x0) + c;
        #pragma omp simd
        for (int x = 0; x < nin; x++) {
            double va = pa[3 * x], vb = pb[3 * x];
            in[x] = va;
            in[nin + x] = vb;
            in[2 * nin + x] = va * va;
            in[3 * nin + x] = vb * vb;
            in[4 * nin + x] = va * vb;
        }
        /* Filter it horizontally into the ring slot of row r. */
        double *slot = ring + (size_t)((r - y0) % WIN) * NMOM * n;
        for (int q = 0; q < NMOM; q++) hfilter(in + (size_t)q * nin, slot + (size_t)q * n, n, g);
        if (r < y0 + WIN - 1) continue;

        /* Filter the 11 rows of output row y vertically, moment by moment. */
        const int y = r - (WIN - 1);
        for (int q = 0; q < NMOM; q++) {
            const double *rows[WIN];
            for (int k = 0; k < WIN; k++)
                rows[k] = ring + (size_t)((y + k - y0) % WIN) * NMOM * n + (size_t)q * n;
            vfilter(rows, mom + (size_t)q * n, n, g);
        }
        /* SSIM per window: luminance-contrast-structure in Wang's combined form. */
        const double *mu_a = mom, *mu_b = mom + n, *e_aa = mom + 2 * n, *e_bb = mom + 3 * n,
                     *e_ab = mom + 4 * n;
        #pragma omp simd
        for (int x = 0; x < n; x++) {
            double ma = mu_a[x], mb = mu_b[x];
            double var_a = e_aa[x] - ma * ma, var_b = e_bb[x] - mb * mb, cov = e_ab[x] - ma * mb;
            map[x] = ((2.0 * ma * mb + c1) * (2.0 * cov + c2))
                   / ((ma * ma + mb * mb + c1) * (var_a + var_b + c2));
        }
        double row = 0.0;
        for (int x = 0; x < n; x++) row += map[x];
        if (map_out) memcpy(map_out + (size_t)y * wv + x0, map, sizeof(double) * n);
        sum += row;
    }
    free(mem);
    *sum_out = sum;
    return 0;
}

/* The mean SSIM; with map (3 * (w-10) * (h-10) doubles) not NULL also the map per channel. */
static double ssim_run(const float *a, const float *b, int w, int h, double L, double *map)
{
    if (w < WIN || h < WIN) return NAN;
    double g[WIN];
    gauss_weights(g);
    const double c1 = (K1 * L) * (K1 * L), c2 = (K2 * L) * (K2 * L);
    const int hv = h - (WIN - 1), wv = w - (WIN - 1);
    const int nbands = (hv + BAND - 1) / BAND, nstrips = (wv + STRIP - 1) / STRIP;
    const int per_channel = nbands * nstrips, ntiles = 3 * per_channel;
    double *sums = malloc(sizeof(double) * ntiles);
    if (!sums) return NAN;
    int failed = 0;

    #pragma omp parallel for schedule(dynamic) reduction(|:failed)
    for (int t = 0; t < ntiles; t++) {
        int c = t / per_channel, band = (t % per_channel) / nstrips, strip = t % nstrips;
        int y0 = band * BAND, y1 = y0 + BAND < hv ? y0 + BAND : hv;
        int x0 = strip * STRIP, n = x0 + STRIP < wv ? STRIP : wv - x0;
        double *mc = map ? map + (size_t)c * wv * hv : NULL;
        failed |= ssim_tile(a, b, w, c, y0, y1, x0, n, c1, c2, g, &sums[t], mc, wv) != 0;
    }
    /* Add the tiles in a fixed order: the mean per channel, then over channels. */
    double total = 0.0;
    for (int c = 0; c < 3; c++) {
        double ch = 0.0;
        for (int k = 0; k < per_channel; k++) ch += sums[c * per_channel + k];
        total += ch / ((double)wv * hv);
    }
    free(sums);
    return failed ? NAN : total / 3.0;
}

double pree_ssim(const float *a, const float *b, int w, int h, double L)
{
    return ssim_run(a, b, w, h, L, NULL);
}

double pree_ssim_map(const float *a, const float *b, int w, int h, double L, double *out)
{
    if (w < WIN || h < WIN) return NAN;
    const int wv = w - (WIN - 1), hv = h - (WIN - 1);
    double *map = malloc(sizeof(double) * 3 * wv * hv);
    if (!map) return NAN;
    double mean = ssim_run(a, b, w, h, L, map);
    for (long p = 0; p < (long)w * h; p++) out[p] = NAN;
    const size_t plane = (size_t)wv * hv;
    for (int y = 0; y < hv; y++)
        for (int x = 0; x < wv; x++) {
            size_t k = (size_t)y * wv + x;
            out[(size_t)(y + RAD) * w + x + RAD] = (map[k] + map[plane + k] + map[2 * plane + k]) / 3.0;
        }
    free(map);
    return mean;
}

double pree_compare_peak(const pree_image_t *ref)
{
    if (ref->samples == PREE_SAMPLES_U8) return 255.0;
    if (ref->samples == PREE_SAMPLES_U16) return 65535.0;
    size_t n = (size_t)ref->width * ref->height * 3;
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        double v = ref->rgb[i];
        if (v < lo) lo = v;
        if (v > hi) hi = v;
    }
    double range = hi - lo;
    return range > 0.0 && isfinite(range) ? range : 1.0;
}

static const char *samples_name(int s)
{
    return s == PREE_SAMPLES_U8 ? "8-bit" : s == PREE_SAMPLES_U16 ? "16-bit" : "float";
}

int pree_compare(const pree_image_t *ref, const pree_image_t *test, pree_metrics_t *m,
                 char *err, size_t errlen)
{
    const int w = ref->width, h = ref->height;
    if (w != test->width || h != test->height) {
        if (err) snprintf(err, errlen, "image sizes differ: %dx%d and %dx%d", w, h, test->width, test->height);
        return -1;
    }
    if (ref->samples != test->samples) {
        if (err) snprintf(err, errlen, "sample types differ: %s and %s (compare like with like)",
                          samples_name(ref->samples), samples_name(test->samples));
        return -1;
    }
    if (w < WIN || h < WIN) {
        if (err) snprintf(err, errlen, "images are %dx%d; SSIM needs at least %dx%d", w, h, WIN, WIN);
        return -1;
    }

    /* Sums over all samples, a row at a time; stop at the first non-finite sample. */
    double sum_ref2 = 0.0, sum_d2 = 0.0, max_abs = 0.0;
    for (int y = 0; y < h; y++) {
        const float *pa = ref->rgb + (size_t)3 * y * w, *pb = test->rgb + (size_t)3 * y * w;
        double row_ref2 = 0.0, row_d2 = 0.0;
        for (int i = 0; i < 3 * w; i++) {
            double va = pa[i], vb = pb[i], d = va - vb;
            if (!isfinite(va) || !isfinite(vb)) {
                if (err) snprintf(err, errlen, "%s image has a non-finite value at pixel (%d, %d)",
                                  isfinite(va) ? "second" : "first", i / 3, y);
                return -1;
            }
            row_ref2 += va * va;
            row_d2 += d * d;
            if (fabs(d) > max_abs) max_abs = fabs(d);
        }
        sum_ref2 += row_ref2;
        sum_d2 += row_d2;
    }
    const double n = (double)w * h * 3;
    pree_metrics_t r;
    r.peak = pree_compare_peak(ref);
    r.mse = sum_d2 / n;
    r.rmse = sqrt(r.mse);
    r.max_abs = max_abs;
    r.snr_db = sum_d2 == 0.0 ? INFINITY : 10.0 * log10(sum_ref2 / sum_d2);
    r.psnr_db = sum_d2 == 0.0 ? INFINITY : 10.0 * log10(r.peak * r.peak / r.mse);
    r.ssim = pree_ssim(ref->rgb, test->rgb, w, h, r.peak);
    if (isnan(r.ssim)) {
        if (err) snprintf(err, errlen, "out of memory computing SSIM");
        return -1;
    }
    *m = r;
    return 0;
}

int pree_diff_heatmap(const float *a, const float *b, int w, int h, unsigned char *out)
{
    size_t n = (size_t)w * h;
    double *e = malloc(sizeof(double) * n);
    if (!e) return -1;
    pree_err_abs(a, b, w, h, e);
    double emax = 0.0;
    for (size_t p = 0; p < n; p++)
        if (e[p] > emax) emax = e[p];
    for (size_t p = 0; p < n; p++) pree_false_colour(emax > 0.0 ? e[p] / emax : 0.0, out + 3 * p);
    free(e);
    return 0;
}
