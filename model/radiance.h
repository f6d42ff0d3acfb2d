/* radiance.h: radiance evaluation (Eq. 4 of paper 000): each hit point adds
 * tau / (pi R^2 N_emitted) to its pixel.
 *
 * Double mode: the reference program's order, hit points newest first, factor
 * 1/(((pi*r2)*batches)*1000). fp32 mode: the PREU's radiance datapath (Eq. 9), each pixel
 * accumulated from +0 over its hit points in ascending address order. Hit points of weight
 * zero add exactly zero and are skipped when skip_zero is set (counted in *skipped). */
#ifndef PREE_RADIANCE_H
#define PREE_RADIANCE_H

#include <stdint.h>
#include "hitpoints.h"
#include "update.h"

/* Returns 0, or -1 when out of memory. */
int radiance_evaluate(const hitpoints_t *h, precision_t prec, uint64_t emitted, int skip_zero,
                       double *rgb, size_t num_pixels, unsigned long long *skipped);

#endif
