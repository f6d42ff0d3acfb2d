// SPDX-License-Identifier: Apache-2.0
/* diffmap.c: error fields and their false-colour pictures with a labelled colour bar (see
 * diffmap.h). The labels are drawn with a 5x7 pixel font of the few characters they need. */
#include "diffmap.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MIN_W     240   /* narrowest canvas: room for three labels under the bar */
#define MARGIN    6     /* bar's distance from the canvas edges */
#define BAR_GAP   6     /* picture to bar */
#define BAR_H     12
#define TICK_H    2
#define TEXT_GAP  2
#define GLYPH_W   5
#define GLYPH_H   7
#define ADVANCE   6     /* glyph plus one column of space */
#define LOG_DECADES 4

/* 5x7 glyphs, one byte a row, bit 4 leftmost. */
static const struct { char c; unsigned char rows[GLYPH_H]; } glyphs[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}}, {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}}, {'e', {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E}},
    {'a', {0x00, 0x00, 0x0E, 0x01, 0x0F, 0x11, 0x0F}}, {'b', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1E}},
    {'f', {0x06, 0x09, 0x08, 0x1C, 0x08, 0x08, 0x08}}, {'g', {0x00, 0x0F, 0x11, 0x11, 0x0F, 0x01, 0x0E}},
    {'i', {0x04, 0x00, 0x0C, 0x04, 0x04, 0x04, 0x0E}}, {'l', {0x0C, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'m', {0x00, 0x00, 0x1A, 0x15, 0x15, 0x11, 0x11}}, {'o', {0x00, 0x00, 0x0E, 0x11, 0x11, 0x11, 0x0E}},
    {'p', {0x00, 0x00, 0x1E, 0x11, 0x1E, 0x10, 0x10}}, {'r', {0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10}},
    {'s', {0x00, 0x00, 0x0E, 0x10, 0x0E, 0x01, 0x1E}}, {'n', {0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}}, {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}},
};

void pree_err_abs(const float *a, const float *b, int w, int h, double *e)
{
    for (long p = 0; p < (long)w * h; p++) {
        double m = 0.0;
        for (int c = 0; c < 3; c++) {
            double d = fabs((double)a[3 * p + c] - (double)b[3 * p + c]);
            if (d > m) m = d;
        }
        e[p] = m;
    }
}

void pree_err_rel(const float *a, const float *b, int w, int h, double eps, double *e)
{
    for (long p = 0; p < (long)w * h; p++) {
        double m = 0.0;
        for (int c = 0; c < 3; c++) {
            double d = fabs((double)a[3 * p + c] - (double)b[3 * p + c]) / (fabs((double)a[3 * p + c]) + eps);
            if (d > m) m = d;
        }
        e[p] = m;
    }
}

double pree_scale_fit(const double *e, long n, int log, pree_scale_t *s)
{
    double mx = 0.0, minpos = INFINITY;
    for (long i = 0; i < n; i++) {
        if (isnan(e[i])) continue;
        if (e[i] > mx) mx = e[i];
        if (e[i] > 0.0 && e[i] < minpos) minpos = e[i];
    }
    s->log = log;
    s->hi = mx > 0.0 ? mx : 1.0;
    s->lo = 0.0;
    if (log) {
        s->lo = s->hi / pow(10.0, LOG_DECADES);
        if (mx > 0.0) {
            double dec = pow(10.0, floor(log10(minpos)));
            if (dec > s->lo && dec < s->hi) s->lo = dec;
        }
    }
    return mx;
}

double pree_scale_pos(const pree_scale_t *s, double v)
{
    if (isnan(v)) return NAN;
    double t = s->log ? (v > 0.0 ? log(v / s->lo) / log(s->hi / s->lo) : 0.0)
                      : (v - s->lo) / (s->hi - s->lo);
    return t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
}

void pree_false_colour(double t, unsigned char rgb[3])
{
    for (int c = 0; c < 3; c++) {
        double v = 3.0 * t - c;
        v = v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
        rgb[c] = (unsigned char)(v * 255.0 + 0.5);
    }
}

static int canvas_w(int w) { return w > MIN_W ? w : MIN_W; }
static int bar_top(int h) { return h + BAR_GAP; }
static int text_top(int h) { return bar_top(h) + BAR_H + TICK_H + TEXT_GAP; }

void pree_diffmap_size(int w, int h, int *cw, int *ch)
{
    *cw = canvas_w(w);
    *ch = text_top(h) + 2 * (GLYPH_H + TEXT_GAP) + 2;
}

static void put(unsigned char *out, int cw, int x, int y, const unsigned char rgb[3])
{
    memcpy(out + 3 * ((long)y * cw + x), rgb, 3);
}

/* Draw string str with its left edge at x (clipped to the canvas), top at y. */
static void text(unsigned char *out, int cw, int ch, int x, int y, const char *str)
{
    static const unsigned char ink[3] = {255, 255, 255};
    for (; *str; str++, x += ADVANCE) {
        const unsigned char *rows = NULL;
        for (size_t g = 0; g < sizeof glyphs / sizeof glyphs[0]; g++)
            if (glyphs[g].c == *str) rows = glyphs[g].rows;
        if (!rows) continue;   /* space and anything unknown: blank */
        for (int r = 0; r < GLYPH_H; r++)
            for (int k = 0; k < GLYPH_W; k++)
                if (rows[r] >> (GLYPH_W - 1 - k) & 1 && x + k >= 0 && x + k < cw && y + r < ch)
                    put(out, cw, x + k, y + r, ink);
    }
}

/* A bar value: 3 significant digits; as 1 - v with enough decimals to tell the ends apart
 * (an SSIM map's labels: 1.00000, 0.99930, 0.99859). */
static void label(char *buf, size_t len, const pree_scale_t *s, double v)
{
    if (!s->one_minus) { snprintf(buf, len, "%.3g", v); return; }
    int digits = 3 - (int)floor(log10(s->hi - s->lo));
    snprintf(buf, len, "%.*f", digits < 3 ? 3 : digits > 9 ? 9 : digits, 1.0 - v);
}

void pree_diffmap_draw(const double *e, int w, int h, const pree_scale_t *s, unsigned char *out)
{
    int cw, ch;
    pree_diffmap_size(w, h, &cw, &ch);
    memset(out, PREE_DIFFMAP_BG, (size_t)3 * cw * ch);
    unsigned char rgb[3];
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double t = pree_scale_pos(s, e[(long)y * w + x]);
            if (isnan(t)) continue;
            pree_false_colour(t, rgb);
            put(out, cw, x, y, rgb);
        }
    /* The bar: column x0 is the bottom colour, column x1 the top one. */
    const int x0 = MARGIN, x1 = cw - 1 - MARGIN, by = bar_top(h), ty = text_top(h);
    for (int x = x0; x <= x1; x++) {
        pree_false_colour((double)(x - x0) / (x1 - x0), rgb);
        for (int y = by; y < by + BAR_H; y++) put(out, cw, x, y, rgb);
    }
    /* Ticks and values at both ends and the middle (arithmetic or geometric). */
    const double mid = s->log ? sqrt(s->lo * s->hi) : 0.5 * (s->lo + s->hi);
    const double vals[3] = {s->lo, mid, s->hi};
    const int xs[3] = {x0, (x0 + x1) / 2, x1};
    static const unsigned char ink[3] = {255, 255, 255};
    char buf[32];
    for (int k = 0; k < 3; k++) {
        for (int y = by + BAR_H; y < by + BAR_H + TICK_H; y++) put(out, cw, xs[k], y, ink);
        label(buf, sizeof buf, s, vals[k]);
        int width = (int)strlen(buf) * ADVANCE - 1;
        int left = k == 0 ? x0 : k == 1 ? xs[k] - width / 2 : x1 + 1 - width;
        text(out, cw, ch, left, ty, buf);
    }
    if (s->title) text(out, cw, ch, x0, ty + GLYPH_H + TEXT_GAP + 1, s->title);
}
