// SPDX-License-Identifier: Apache-2.0
/* diffmap.h: difference images people can read: per-pixel error fields (absolute, relative,
 * 1 - SSIM) drawn in false colour with a colour bar and its values below the picture.
 *
 * API
 *   pree_scale_t        the bar's range and mapping (linear or log) for one field
 *   pree_err_abs        per-pixel max over channels of |a - b|
 *   pree_err_rel        per-pixel max over channels of |a - b| / (|a| + eps)
 *   pree_scale_fit      the range that puts the field's largest value at the top of the bar
 *   pree_diffmap_size   the canvas a field of w x h gets (picture, bar, labels)
 *   pree_diffmap_draw   the 8-bit RGB canvas: picture top-left, colour bar and values below
 *
 * Colours: pree_false_colour, black through red and yellow to white (compare.h's heat map), so
 * the picture of an absolute-error field on the linear fitted scale is pree_diff_heatmap's,
 * byte for byte. NaN samples (where a field is undefined, e.g. SSIM's 5-pixel border) are
 * drawn in the background grey. docs/compare.md, "`--diff OUT` and `--log`: difference maps", gives the definitions. */
#ifndef PREE_DIFFMAP_H
#define PREE_DIFFMAP_H

#define PREE_DIFFMAP_BG 48   /* background grey of the canvas */
#define PREE_REL_EPS 0.01    /* relative error's guard: eps = PREE_REL_EPS * the reference's peak */

typedef struct {
    double lo, hi;      /* field values at the bar's left and right ends */
    int log;            /* 1: position log(v/lo)/log(hi/lo); 0: (v - lo)/(hi - lo) */
    int one_minus;      /* 1: labels show 1 - v (an SSIM map drawn as 1 - SSIM) */
    const char *title;  /* drawn at the left of the label row: lower-case letters, digits, space */
} pree_scale_t;

void pree_err_abs(const float *a, const float *b, int w, int h, double *e);
void pree_err_rel(const float *a, const float *b, int w, int h, double eps, double *e);

/* Fill s->lo, s->hi for field e[n] (NaN ignored): linear: 0 .. max; log: max / 10^decades ..
 * max (decades 4), or the smallest positive value's decade if that is higher. A zero field
 * gets hi = 1 (everything at the bottom colour). Returns the field's maximum. */
double pree_scale_fit(const double *e, long n, int log, pree_scale_t *s);

/* Position 0..1 of value v on the bar (0 for v <= lo, 1 for v >= hi; NaN for NaN). */
double pree_scale_pos(const pree_scale_t *s, double v);

/* rgb[3] of pree_diff_heatmap's colour map at t in [0, 1]. */
void pree_false_colour(double t, unsigned char rgb[3]);

void pree_diffmap_size(int w, int h, int *cw, int *ch);

/* Draw field e[w*h] into out[cw*ch*3] (cw, ch from pree_diffmap_size). */
void pree_diffmap_draw(const double *e, int w, int h, const pree_scale_t *s, unsigned char *out);

#endif
