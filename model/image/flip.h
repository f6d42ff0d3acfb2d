// SPDX-License-Identifier: Apache-2.0
/* flip.h: LDR-FLIP, the perceptual difference of two LDR images (Andersson, Nilsson,
 * Akenine-Moller, Oskarsson, Astrom, Fairchild, "FLIP: A Difference Evaluator for Alternating
 * Images", HPG 2020), written from the paper's description; docs/compare.md, "FLIP", gives the
 * steps and the check against NVIDIA's own implementation.
 *
 * API
 *   PREE_FLIP_PPD     the paper's default observer: 0.7 m from a 0.7 m wide 3840-pixel display
 *   pree_flip_input   an image's display values in [0, 1] (sRGB-encoded) from a pree_image_t
 *   pree_flip         the per-pixel FLIP map (0 = no perceived difference, 1 = the largest) and
 *                     its mean
 *
 * All arithmetic is double; the result does not depend on the number of OpenMP threads. */
#ifndef PREE_FLIP_H
#define PREE_FLIP_H

#include "image.h"

#define PREE_FLIP_PPD (0.7 * (3840.0 / 0.7) * (3.14159265358979323846 / 180.0))

/* Display values: 8-bit samples / 255, 16-bit / 65535, float (linear radiance) through the
 * engine's display transform (1 - exp(-L))^(1/2.2) without its 8-bit rounding. out[w*h*3]. */
void pree_flip_input(const pree_image_t *img, float *out);

/* FLIP map of test against ref (display values, w x h x 3, in [0, 1]) at ppd pixels per degree
 * into map[w*h] (may be NULL); returns the mean, or NAN when out of memory. */
double pree_flip(const float *ref, const float *test, int w, int h, double ppd, double *map);

#endif
