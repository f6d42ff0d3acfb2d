// SPDX-License-Identifier: Apache-2.0
/* test_compare.c: known answers for SSIM, SNR, PSNR, RMSE and max difference, an independent
 * direct-window SSIM, thread-count independence, the heat map, and refused comparisons. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "compare.h"

/* cmocka 1.1.5 (Debian bookworm) has no assert_double_equal. */
#define assert_near(got, want, tol)                                                           \
    do {                                                                                      \
        double got_ = (got), want_ = (want);                                                  \
        if (!(fabs(got_ - want_) <= (tol)))                                                   \
            fail_msg("%s = %.17g, want %.17g within %g", #got, got_, want_, (double)(tol)); \
    } while (0)

/* An image filled by a callback f(x, y, c), with the given sample type. */
static pree_image_t make(int w, int h, int samples, double (*f)(int, int, int))
{
    pree_image_t img;
    char err[128];
    assert_int_equal(pree_image_alloc(&img, w, h, err, sizeof err), 0);
    img.samples = samples;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 3; c++) img.rgb[3 * (y * w + x) + c] = (float)f(x, y, c);
    return img;
}

/* Deterministic pseudo-random numbers in [0, 1) (64-bit LCG, top 53 bits). */
static uint64_t lcg_state;
static double rnd(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg_state >> 11) / 9007199254740992.0;
}

static double const100(int x, int y, int c) { (void)x; (void)y; (void)c; return 100.0; }
static double const110(int x, int y, int c) { (void)x; (void)y; (void)c; return 110.0; }
static double const10(int x, int y, int c) { (void)x; (void)y; (void)c; return 10.0; }
static double sixteenths(int x, int y, int c) { return ((x * 7 + y * 13 + c * 5) % 128) / 16.0; }
static double sixteenths_shift(int x, int y, int c) { return sixteenths(x, y, c) + 0.25; }
static double bytes(int x, int y, int c) { return (x * 37 + y * 91 + c * 53 + (x * y) % 17) % 256; }

/* Identical images: SSIM exactly 1, SNR and PSNR infinite, no difference. */
static void test_identical(void **state)
{
    (void)state;
    pree_image_t a = make(40, 30, PREE_SAMPLES_U8, bytes), b = make(40, 30, PREE_SAMPLES_U8, bytes);
    pree_metrics_t m;
    char err[256];
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), 0);
    assert_true(m.ssim == 1.0);
    assert_true(isinf(m.snr_db) && m.snr_db > 0);
    assert_true(isinf(m.psnr_db) && m.psnr_db > 0);
    assert_true(m.rmse == 0.0 && m.max_abs == 0.0 && m.mse == 0.0);
    assert_true(m.peak == 255.0);
    pree_image_free(&a);
    pree_image_free(&b);
}

/* A constant offset of 0.25 on a float image: RMSE and max difference exactly 0.25. */
static void test_constant_offset(void **state)
{
    (void)state;
    pree_image_t a = make(23, 19, PREE_SAMPLES_FLOAT, sixteenths);
    pree_image_t b = make(23, 19, PREE_SAMPLES_FLOAT, sixteenths_shift);
    pree_metrics_t m;
    char err[256];
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), 0);
    assert_true(m.rmse == 0.25);
    assert_true(m.max_abs == 0.25);
    assert_true(m.mse == 0.0625);
    assert_true(m.peak == 127.0 / 16.0);   /* float: the reference's max - min */
    /* PSNR = 10 log10(L^2 / 0.0625) with L = 7.9375: 10 log10(1008.0625) = 30.0348745926 */
    assert_near(m.psnr_db, 30.0348745926, 1e-9);
    pree_image_free(&a);
    pree_image_free(&b);
}

/* Hand-worked SNR and PSNR: an 11x11 8-bit image of 10s, one sample off by 3.
 * sum ref^2 = 363 * 100 = 36300, sum d^2 = 9, MSE = 9/363:
 * SNR = 10 log10(36300/9) = 36.0566411560, PSNR = 10 log10(255^2 * 363/9) = 64.1874447646,
 * RMSE = sqrt(9/363) = 0.157459164324. */
static void test_hand_snr_psnr(void **state)
{
    (void)state;
    pree_image_t a = make(11, 11, PREE_SAMPLES_U8, const10), b = make(11, 11, PREE_SAMPLES_U8, const10);
    b.rgb[3 * (4 * 11 + 6) + 1] = 13.0f;
    pree_metrics_t m;
    char err[256];
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), 0);
    assert_near(m.snr_db, 36.0566411560, 1e-9);
    assert_near(m.psnr_db, 64.1874447646, 1e-9);
    assert_near(m.rmse, 0.157459164324, 1e-11);
    assert_true(m.max_abs == 3.0);
    assert_true(m.ssim < 1.0 && m.ssim > 0.9);
    pree_image_free(&a);
    pree_image_free(&b);
}

/* Flat images 100 against 110 (8-bit): every window has zero variance, so SSIM is the
 * luminance term alone: (2*100*110 + C1) / (100^2 + 110^2 + C1), C1 = (0.01*255)^2 = 6.5025,
 * = 22006.5025 / 22106.5025 = 0.99547644409. */
static void test_flat_ssim(void **state)
{
    (void)state;
    pree_image_t a = make(20, 15, PREE_SAMPLES_U8, const100), b = make(20, 15, PREE_SAMPLES_U8, const110);
    pree_metrics_t m;
    char err[256];
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), 0);
    assert_near(m.ssim, 0.99547644409, 1e-10);
    assert_near(m.snr_db, 20.0, 1e-12);   /* 10 log10(100^2 / 10^2) */
    pree_image_free(&a);
    pree_image_free(&b);
}

/* SSIM written the plain way: for every valid window position, the 2-D Gaussian weights
 * exp(-(i^2 + j^2) / 4.5) normalised over the 121 taps, the weighted means, variances and
 * covariance summed directly, then the SSIM formula; mean per channel, then over channels. */
static double direct_ssim(const pree_image_t *a, const pree_image_t *b, double L)
{
    double wt[11][11], wsum = 0.0;
    for (int i = 0; i < 11; i++)
        for (int j = 0; j < 11; j++) {
            wt[i][j] = exp(-((i - 5) * (i - 5) + (j - 5) * (j - 5)) / (2.0 * 1.5 * 1.5));
            wsum += wt[i][j];
        }
    const double C1 = pow(0.01 * L, 2), C2 = pow(0.03 * L, 2);
    double total = 0.0;
    for (int c = 0; c < 3; c++) {
        double chan = 0.0;
        int count = 0;
        for (int y = 0; y + 11 <= a->height; y++)
            for (int x = 0; x + 11 <= a->width; x++) {
                double ma = 0, mb = 0;
                for (int i = 0; i < 11; i++)
                    for (int j = 0; j < 11; j++) {
                        size_t k = 3 * ((size_t)(y + i) * a->width + x + j) + c;
                        ma += wt[i][j] / wsum * a->rgb[k];
                        mb += wt[i][j] / wsum * b->rgb[k];
                    }
                double va = 0, vb = 0, cab = 0;   /* central moments, not E[x^2] - mu^2 */
                for (int i = 0; i < 11; i++)
                    for (int j = 0; j < 11; j++) {
                        size_t k = 3 * ((size_t)(y + i) * a->width + x + j) + c;
                        double da = a->rgb[k] - ma, db = b->rgb[k] - mb;
                        va += wt[i][j] / wsum * da * da;
                        vb += wt[i][j] / wsum * db * db;
                        cab += wt[i][j] / wsum * da * db;
                    }
                double l = (2 * ma * mb + C1) / (ma * ma + mb * mb + C1);
                double cs = (2 * cab + C2) / (va + vb + C2);
                chan += l * cs;
                count++;
            }
        total += chan / count;
    }
    return total / 3;
}

/* A noisy float image against a scaled, shifted, noisier copy, and an 8-bit pair. */
static void test_ssim_against_direct(void **state)
{
    (void)state;
    enum { W = 37, H = 29 };
    pree_image_t a, b;
    char err[256];
    assert_int_equal(pree_image_alloc(&a, W, H, err, sizeof err), 0);
    assert_int_equal(pree_image_alloc(&b, W, H, err, sizeof err), 0);
    lcg_state = 12345;
    for (int i = 0; i < W * H * 3; i++) {
        int x = (i / 3) % W, y = (i / 3) / W;
        a.rgb[i] = (float)(2.0 + sin(0.3 * x) * cos(0.2 * y) + 0.5 * rnd());
        b.rgb[i] = (float)(0.8 * a.rgb[i] + 0.3 + 0.2 * (rnd() - 0.5));
    }
    pree_metrics_t m;
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), 0);
    double want = direct_ssim(&a, &b, m.peak);
    assert_near(m.ssim, want, 1e-12);
    assert_true(m.ssim > 0.2 && m.ssim < 0.99);   /* a real, non-trivial value */

    /* 8-bit: quantised versions of the same pair, L = 255. */
    for (int i = 0; i < W * H * 3; i++) {
        a.rgb[i] = floorf(a.rgb[i] * 60.0f);
        b.rgb[i] = floorf(b.rgb[i] * 60.0f);
    }
    a.samples = b.samples = PREE_SAMPLES_U8;
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), 0);
    assert_true(m.peak == 255.0);
    assert_near(m.ssim, direct_ssim(&a, &b, 255.0), 1e-12);
    pree_image_free(&a);
    pree_image_free(&b);
}

/* The same bits with 1, 2 and 3 threads on an image tall enough for several bands. */
static void test_ssim_thread_independent(void **state)
{
    (void)state;
    enum { W = 61, H = 407 };
    pree_image_t a, b;
    char err[256];
    assert_int_equal(pree_image_alloc(&a, W, H, err, sizeof err), 0);
    assert_int_equal(pree_image_alloc(&b, W, H, err, sizeof err), 0);
    lcg_state = 777;
    for (int i = 0; i < W * H * 3; i++) {
        a.rgb[i] = (float)(255.0 * rnd());
        b.rgb[i] = (float)(0.5 * a.rgb[i] + 100.0 * rnd());
    }
    double s[3];
    for (int t = 1; t <= 3; t++) {
        omp_set_num_threads(t);
        s[t - 1] = pree_ssim(a.rgb, b.rgb, W, H, 255.0);
    }
    assert_memory_equal(&s[0], &s[1], sizeof(double));
    assert_memory_equal(&s[0], &s[2], sizeof(double));
    assert_near(s[0], direct_ssim(&a, &b, 255.0), 1e-12);
    pree_image_free(&a);
    pree_image_free(&b);
}

static void test_peak(void **state)
{
    (void)state;
    pree_image_t f = make(12, 12, PREE_SAMPLES_FLOAT, sixteenths);
    assert_true(pree_compare_peak(&f) == 127.0 / 16.0);
    f.samples = PREE_SAMPLES_U16;
    assert_true(pree_compare_peak(&f) == 65535.0);
    pree_image_free(&f);
    pree_image_t flat = make(12, 12, PREE_SAMPLES_FLOAT, const10);
    assert_true(pree_compare_peak(&flat) == 1.0);   /* zero range falls back to 1 */
    pree_image_free(&flat);
}

/* Comparisons that must be refused with a one-line reason. */
static void test_refused(void **state)
{
    (void)state;
    pree_metrics_t m;
    char err[256];
    pree_image_t a = make(20, 15, PREE_SAMPLES_U8, bytes), b = make(15, 20, PREE_SAMPLES_U8, bytes);
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "sizes differ"));
    pree_image_free(&b);

    b = make(20, 15, PREE_SAMPLES_FLOAT, bytes);
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "sample types differ"));
    b.samples = PREE_SAMPLES_U8;
    b.rgb[3 * 17 + 2] = NAN;
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "non-finite value at pixel (17, 0)"));
    pree_image_free(&a);
    pree_image_free(&b);

    a = make(10, 40, PREE_SAMPLES_U8, bytes);
    b = make(10, 40, PREE_SAMPLES_U8, bytes);
    assert_int_equal(pree_compare(&a, &b, &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "at least 11x11"));
    assert_null(strchr(err, '\n'));
    assert_true(isnan(pree_ssim(a.rgb, b.rgb, 10, 40, 255.0)));
    pree_image_free(&a);
    pree_image_free(&b);
}

/* Heat map: black where equal, white at the largest difference, (255, 128, 0) at half of it. */
static void test_heatmap(void **state)
{
    (void)state;
    pree_image_t a = make(3, 2, PREE_SAMPLES_FLOAT, const10), b = make(3, 2, PREE_SAMPLES_FLOAT, const10);
    unsigned char out[18];
    pree_diff_heatmap(a.rgb, b.rgb, 3, 2, out);
    for (int i = 0; i < 18; i++) assert_int_equal(out[i], 0);
    b.rgb[3 * 4 + 2] = 14.0f;   /* pixel 4: difference 4 in blue: the maximum */
    b.rgb[3 * 1 + 0] = 8.0f;    /* pixel 1: difference 2 in red and 1 in green: max 2, half */
    b.rgb[3 * 1 + 1] = 11.0f;
    pree_diff_heatmap(a.rgb, b.rgb, 3, 2, out);
    const unsigned char want[18] = {0, 0, 0, 255, 128, 0, 0, 0, 0, 0, 0, 0, 255, 255, 255, 0, 0, 0};
    assert_memory_equal(out, want, 18);
    pree_image_free(&a);
    pree_image_free(&b);
}

/* The SSIM map: its valid windows' mean is pree_ssim's figure (up to the order of the sums),
 * NaN within 5 pixels of the border, and it is the same whatever the thread count. */
static void test_ssim_map(void **state)
{
    (void)state;
    const int w = 37, h = 29;
    pree_image_t a = make(w, h, PREE_SAMPLES_U8, bytes), b = make(w, h, PREE_SAMPLES_U8, bytes);
    for (int i = 0; i < 3 * w * h; i += 7) b.rgb[i] = (float)fmod(b.rgb[i] + 40.0, 256.0);
    double *m1 = malloc(sizeof(double) * w * h), *m2 = malloc(sizeof(double) * w * h);
    assert_non_null(m1);
    assert_non_null(m2);
    omp_set_num_threads(1);
    double mean = pree_ssim_map(a.rgb, b.rgb, w, h, 255.0, m1);
    omp_set_num_threads(3);
    pree_ssim_map(a.rgb, b.rgb, w, h, 255.0, m2);
    assert_memory_equal(m1, m2, sizeof(double) * w * h);
    assert_true(mean == pree_ssim(a.rgb, b.rgb, w, h, 255.0));
    double sum = 0.0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int inside = x >= 5 && x < w - 5 && y >= 5 && y < h - 5;
            assert_int_equal(isnan(m1[y * w + x]), !inside);
            if (inside) sum += m1[y * w + x];
        }
    assert_true(fabs(sum / ((w - 10) * (h - 10)) - mean) < 1e-12);
    assert_true(mean < 0.99);
    free(m1);
    free(m2);
    pree_image_free(&a);
    pree_image_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_identical),
        cmocka_unit_test(test_constant_offset),
        cmocka_unit_test(test_hand_snr_psnr),
        cmocka_unit_test(test_flat_ssim),
        cmocka_unit_test(test_ssim_against_direct),
        cmocka_unit_test(test_ssim_thread_independent),
        cmocka_unit_test(test_peak),
        cmocka_unit_test(test_refused),
        cmocka_unit_test(test_heatmap),
        cmocka_unit_test(test_ssim_map),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
