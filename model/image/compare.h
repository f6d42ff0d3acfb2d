// SPDX-License-Identifier: Apache-2.0
/* compare.h: image comparison metrics: SSIM, SNR, PSNR, RMSE, maximum absolute difference.
 *
 * API
 *   pree_metrics_t          the figures for one pair of images
 *   pree_compare_peak       the dynamic range L a reference image implies
 *   pree_compare            all metrics of a test image against a reference image
 *   pree_ssim               SSIM alone, over raw interleaved RGB floats
 *   pree_ssim_map           SSIM per pixel (the window centred there), and the mean
 *   pree_diff_heatmap       an 8-bit false-colour picture of where two images differ
 *
 * Definitions (docs/compare.md gives them in full): SSIM as Wang et al. 2004 with an 11x11
 * Gaussian window (sigma 1.5, weights normalised to sum 1), K1 = 0.01, K2 = 0.03, over 'valid'
 * window positions only ((W-10) x (H-10) of them), averaged per channel then over R, G, B.
 * SNR = 10 log10(sum ref^2 / sum (ref-test)^2), PSNR = 10 log10(L^2 / MSE), RMSE = sqrt(MSE),
 * with sums and the mean over all W*H*3 samples. All arithmetic is double. */
#ifndef PREE_COMPARE_H
#define PREE_COMPARE_H

#include <stddef.h>
#include "image.h"

/* Smallest image SSIM accepts: the window must fit once. */
#define PREE_SSIM_WINDOW 11

typedef struct {
    double peak;      /* dynamic range L used by SSIM and PSNR */
    double ssim;      /* mean SSIM over valid windows and the three channels */
    double snr_db;    /* +inf when the images are identical */
    double psnr_db;   /* +inf when the images are identical */
    double mse;       /* mean squared difference over all samples */
    double rmse;      /* sqrt(mse) */
    double max_abs;   /* largest |ref - test| over all samples */
} pree_metrics_t;

/* L for a reference image: 255 for 8-bit sources, 65535 for 16-bit ones, and for float
 * sources the reference's max - min over all samples (1 when that is 0). */
double pree_compare_peak(const pree_image_t *ref);

/* Compare `test` against `ref` (the reference: its range sets L). Fails (-1, one line in err
 * naming the problem) when the sizes differ, the sample types differ (8-bit vs 16-bit vs float),
 * the image is smaller than 11x11, or a sample is not finite. *m is written only on success. */
int pree_compare(const pree_image_t *ref, const pree_image_t *test, pree_metrics_t *m,
                 char *err, size_t errlen);

/* SSIM of two w x h interleaved RGB float images (w, h >= 11) with dynamic range L, as above.
 * The result does not depend on the number of OpenMP threads. */
double pree_ssim(const float *a, const float *b, int w, int h, double L);

/* SSIM as pree_ssim, and out[w*h] the per-pixel map: the three channels' mean SSIM of the
 * window centred on each pixel, NaN within 5 pixels of the border (no valid window). NaN
 * (and out untouched) when out of memory or w, h < 11. */
double pree_ssim_map(const float *a, const float *b, int w, int h, double L, double *out);

/* Fill out[w*h*3] with a heat map of e = max over channels |a - b| per pixel: t = e / max e over
 * the image, colour (r, g, b) = 255 * (clamp(3t), clamp(3t-1), clamp(3t-2)) rounded, i.e. black
 * through red and yellow to white. Identical images give an all-black map. Returns 0, or -1
 * when out of memory. */
int pree_diff_heatmap(const float *a, const float *b, int w, int h, unsigned char *out);

#endif
