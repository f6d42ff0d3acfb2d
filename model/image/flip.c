// SPDX-License-Identifier: Apache-2.0
/* flip.c: LDR-FLIP (see flip.h). Two pipelines per pixel:
 *   colour: sRGB -> linear RGB -> XYZ -> YCxCz; each opponent channel filtered by its contrast
 *           sensitivity function (a sum of Gaussians in visual degrees, separable); back to
 *           linear RGB clamped to [0, 1]; CIELAB with the Hunt adjustment (a, b scaled by L/100);
 *           HyAB distance |dL| + |(da, db)|, raised to qc = 0.7 and redistributed so that
 *           pc = 0.4 of the largest (green against blue) maps to pt = 0.95;
 *   feature: the unfiltered achromatic channel's edge (first derivative of a Gaussian) and point
 *           (second derivative) responses; the larger difference of their magnitudes, over
 *           sqrt(2), raised to qf = 0.5.
 * FLIP = colour ^ (1 - feature). Every filter is separable and clamps at the image edge. */
#include "flip.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define QC 0.7
#define PC 0.4
#define PT 0.95
#define QF 0.5
#define FEATURE_W 0.082   /* degrees: peak-to-trough width of the edge detector */

static const double ILLUM[3] = {0.950428545, 1.0, 1.088900371};   /* D65 white in XYZ */

static double srgb_to_lin(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static void lin_to_xyz(const double *c, double *x)
{
    x[0] = (10135552.0 * c[0] + 8788810.0 * c[1] + 4435075.0 * c[2]) / 24577794.0;
    x[1] = (2613072.0 * c[0] + 8788810.0 * c[1] + 887015.0 * c[2]) / 12288897.0;
    x[2] = (1425312.0 * c[0] + 8788810.0 * c[1] + 70074185.0 * c[2]) / 73733382.0;
}

static void xyz_to_lin(const double *x, double *c)
{
    c[0] = 3.241003275 * x[0] - 1.537398934 * x[1] - 0.498615861 * x[2];
    c[1] = -0.969224334 * x[0] + 1.875930071 * x[1] + 0.041554224 * x[2];
    c[2] = 0.055639423 * x[0] - 0.204011202 * x[1] + 1.057148933 * x[2];
}

/* Linear RGB to Hunt-adjusted CIELAB. */
static void lin_to_hunt_lab(const double *c, double *lab)
{
    double x[3], f[3];
    lin_to_xyz(c, x);
    const double d = 6.0 / 29.0;
    for (int k = 0; k < 3; k++) {
        double v = x[k] / ILLUM[k];
        f[k] = v > d * d * d ? cbrt(v) : v / (3.0 * d * d) + 4.0 / 29.0;
    }
    lab[0] = 116.0 * f[1] - 16.0;
    lab[1] = 0.01 * lab[0] * 500.0 * (f[0] - f[1]);
    lab[2] = 0.01 * lab[0] * 200.0 * (f[1] - f[2]);
}

static double hyab(const double *p, const double *q)
{
    return fabs(p[0] - q[0]) + hypot(p[1] - q[1], p[2] - q[2]);
}

void pree_flip_input(const pree_image_t *img, float *out)
{
    const size_t n = (size_t)img->width * img->height * 3;
    for (size_t i = 0; i < n; i++) {
        double v = img->rgb[i];
        if (img->samples == PREE_SAMPLES_U8) v /= 255.0;
        else if (img->samples == PREE_SAMPLES_U16) v /= 65535.0;
        else v = v > 0.0 ? pow(1.0 - exp(-v), 1.0 / 2.2) : 0.0;
        out[i] = (float)(v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v);
    }
}

/* One pass of a separable convolution of plane in (w x h) into out with kernel k of radius r,
 * along x (vertical = 0) or y (1), clamping coordinates at the edges. */
static void conv1(const double *in, double *out, int w, int h, const double *k, int r, int vertical)
{
    const int len = vertical ? h : w;
    const size_t step = vertical ? (size_t)w : 1;
    #pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const int at = vertical ? y : x;
            const double *base = in + (size_t)y * w + x - (size_t)at * step;   /* this line's start */
            double s = 0.0;
            for (int j = -r; j <= r; j++) {
                int q = at + j < 0 ? 0 : at + j >= len ? len - 1 : at + j;
                s += k[j + r] * base[(size_t)q * step];
            }
            out[(size_t)y * w + x] = s;
        }
}

/* kx along x, then ky along y; tmp and out are w*h. */
static void conv2(const double *in, double *tmp, double *out, int w, int h, const double *kx,
                  const double *ky, int r)
{
    conv1(in, tmp, w, h, kx, r, 0);
    conv1(tmp, out, w, h, ky, r, 1);
}

/* The contrast sensitivity filters of the three opponent channels: channel c's 2-D kernel is
 * sum_t amp[c][t] * G_t(x) G_t(y), G_t(x) = exp(-pi^2 (x/ppd)^2 / b[c][t]), normalised to sum 1. */
static const double CSF_A[3][2] = {{1.0, 0.0}, {1.0, 0.0}, {34.1, 13.5}};
static const double CSF_B[3][2] = {{0.0047, 1e-5}, {0.0053, 1e-5}, {0.04, 0.025}};

static int csf_radius(double ppd)
{
    return (int)ceil(3.0 * sqrt(0.04 / (2.0 * M_PI * M_PI)) * ppd);
}

/* The CSF-filtered planes (ycc: 3 planes of w*h, replaced by their filtered values). */
static int csf_filter(double *ycc, int w, int h, double ppd)
{
    const int r = csf_radius(ppd);
    const size_t n = (size_t)w * h;
    double *g = malloc(sizeof(double) * (2 * r + 1));
    double *buf = malloc(sizeof(double) * 3 * n);
    if (!g || !buf) { free(g); free(buf); return -1; }
    double *tmp = buf, *part = buf + n, *acc = buf + 2 * n;
    for (int c = 0; c < 3; c++) {
        double total = 0.0;
        memset(acc, 0, sizeof(double) * n);
        for (int t = 0; t < 2; t++) {
            if (CSF_A[c][t] == 0.0) continue;
            double sum = 0.0;
            for (int k = -r; k <= r; k++) {
                double x = k / ppd;
                g[k + r] = exp(-M_PI * M_PI * x * x / CSF_B[c][t]);
                sum += g[k + r];
            }
            const double amp = CSF_A[c][t] * sqrt(M_PI / CSF_B[c][t]);
            total += amp * sum * sum;
            conv2(ycc + c * n, tmp, part, w, h, g, g, r);
            for (size_t i = 0; i < n; i++) acc[i] += amp * part[i];
        }
        for (size_t i = 0; i < n; i++) ycc[c * n + i] = acc[i] / total;
    }
    free(g);
    free(buf);
    return 0;
}

/* Image (display values) to 3 planes of YCxCz and one of normalised luminance y. */
static void to_ycxcz(const float *img, int w, int h, double *ycc, double *lum)
{
    const size_t n = (size_t)w * h;
    for (size_t p = 0; p < n; p++) {
        double c[3], x[3];
        for (int k = 0; k < 3; k++) c[k] = srgb_to_lin(img[3 * p + k]);
        lin_to_xyz(c, x);
        for (int k = 0; k < 3; k++) x[k] /= ILLUM[k];
        ycc[p] = 116.0 * x[1] - 16.0;
        ycc[n + p] = 500.0 * (x[0] - x[1]);
        ycc[2 * n + p] = 200.0 * (x[1] - x[2]);
        lum[p] = (ycc[p] + 16.0) / 116.0;
    }
}

/* Filtered YCxCz back to Hunt-adjusted CIELAB through linear RGB clamped to [0, 1]. */
static void ycxcz_to_lab(const double *ycc, size_t n, size_t p, double *lab)
{
    double x[3], c[3];
    x[1] = (ycc[p] + 16.0) / 116.0;
    x[0] = ycc[n + p] / 500.0 + x[1];
    x[2] = x[1] - ycc[2 * n + p] / 200.0;
    for (int k = 0; k < 3; k++) x[k] *= ILLUM[k];
    xyz_to_lin(x, c);
    for (int k = 0; k < 3; k++) c[k] = c[k] < 0.0 ? 0.0 : c[k] > 1.0 ? 1.0 : c[k];
    lin_to_hunt_lab(c, lab);
}

/* Edge and point detector kernels (1-D factors): d the derivative factor, s the smoothing one;
 * the 2-D kernel d(x) s(y) has positive weights summing to 1 and negative ones to -1. */
static void detector(double ppd, int second, double *d, double *s, int r)
{
    const double sd = 0.5 * FEATURE_W * ppd;
    double pos = 0.0, neg = 0.0, gs = 0.0;
    for (int k = -r; k <= r; k++) {
        double g = exp(-(double)k * k / (2.0 * sd * sd));
        s[k + r] = g;
        gs += g;
        d[k + r] = second ? ((double)k * k / (sd * sd) - 1.0) * g : -k * g;
        if (d[k + r] > 0.0) pos += d[k + r];
        else neg -= d[k + r];
    }
    for (int k = 0; k <= 2 * r; k++) {
        s[k] /= gs;
        d[k] /= d[k] > 0.0 ? pos : neg;
    }
}

/* feat[n]: per pixel the magnitude of (x, y) responses of the detector (second: points). */
static void feature(const double *lum, int w, int h, double ppd, int second, double *tmp,
                    double *fx, double *feat)
{
    const int r = (int)ceil(3.0 * 0.5 * FEATURE_W * ppd);
    double d[2 * r + 1], s[2 * r + 1];
    detector(ppd, second, d, s, r);
    conv2(lum, tmp, fx, w, h, d, s, r);
    conv2(lum, tmp, feat, w, h, s, d, r);
    for (size_t i = 0; i < (size_t)w * h; i++) feat[i] = hypot(fx[i], feat[i]);
}

double pree_flip(const float *ref, const float *test, int w, int h, double ppd, double *map)
{
    const size_t n = (size_t)w * h;
    double *buf = malloc(sizeof(double) * 14 * n);
    if (!buf) return NAN;
    double *yr = buf, *yt = buf + 3 * n, *lr = buf + 6 * n, *lt = buf + 7 * n;
    double *er = buf + 8 * n, *et = buf + 9 * n, *pr = buf + 10 * n, *pt = buf + 11 * n;
    double *tmp = buf + 12 * n, *fx = buf + 13 * n;
    to_ycxcz(ref, w, h, yr, lr);
    to_ycxcz(test, w, h, yt, lt);
    if (csf_filter(yr, w, h, ppd) || csf_filter(yt, w, h, ppd)) { free(buf); return NAN; }
    feature(lr, w, h, ppd, 0, tmp, fx, er);
    feature(lt, w, h, ppd, 0, tmp, fx, et);
    feature(lr, w, h, ppd, 1, tmp, fx, pr);
    feature(lt, w, h, ppd, 1, tmp, fx, pt);

    const double green[3] = {0.0, 1.0, 0.0}, blue[3] = {0.0, 0.0, 1.0};
    double lg[3], lb[3];
    lin_to_hunt_lab(green, lg);
    lin_to_hunt_lab(blue, lb);
    const double cmax = pow(hyab(lg, lb), QC), pccmax = PC * cmax;
    double total = 0.0;
    for (int y = 0; y < h; y++) {
        double row = 0.0;
        for (int x = 0; x < w; x++) {
            const size_t p = (size_t)y * w + x;
            double a[3], b[3];
            ycxcz_to_lab(yr, n, p, a);
            ycxcz_to_lab(yt, n, p, b);
            const double e = pow(hyab(a, b), QC);
            const double ec = e < pccmax ? PT / pccmax * e : PT + (e - pccmax) / (cmax - pccmax) * (1.0 - PT);
            const double df = fmax(fabs(er[p] - et[p]), fabs(pt[p] - pr[p]));
            const double ef = pow(df / sqrt(2.0), QF);
            const double f = pow(ec, 1.0 - ef);
            if (map) map[p] = f;
            row += f;
        }
        total += row;
    }
    free(buf);
    return total / (double)n;
}
