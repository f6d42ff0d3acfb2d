/* radiance.h: radiance evaluation (Eq. 4 of paper 000): each hit point adds
 * tau / (pi R^2 N_emitted) to its pixel.
 *
 * Double mode: the reference program's order, hit points newest first, factor
 * 1/(((pi*r2)*batches)*1000). fp32 mode: the PREU's radiance datapath (Eq. 9), each pixel
 * accumulated from +0 over its hit points in the PREE's issue order for `preu` PREUs: the
 * ADISO-REC leaping sequence (model/pree/adiso_order.h, docs/pree_top.md "Radiance order"). Hit points of weight
 * zero add exactly zero and are skipped when skip_zero is set (counted in *skipped). */
#ifndef PREE_RADIANCE_H
#define PREE_RADIANCE_H

#include <stdint.h>
#include "hitpoints.h"
#include "update.h"

/* Radiance pipeline stages of a PREU (ADISO-REC's Npip_stage) in the paper's configuration (RTL
 * PipeFast = 0); a deeper PREU (PipeFast = 1: 64) issues in another order, and a co-simulation of
 * it passes its own depth to radiance_fp32_words. */
#define RADIANCE_PREU_STAGES 12

/* Returns 0, or -1 when out of memory or preu is not a power of two in 1..64. */
int radiance_evaluate_preu(const hitpoints_t *h, precision_t prec, uint64_t emitted, int skip_zero,
                           int preu, double *rgb, size_t num_pixels, unsigned long long *skipped);
/* fp32 only: add every hit point's contribution to the binary32 pixel sums L (3 words per pixel,
 * zeroed by the caller), in the issue order for `preu` PREUs whose radiance pipelines have
 * `stages` stages (ADISO-REC's depth). Returns 0 or -1 as above (also for stages < 1). */
int radiance_fp32_words(const hitpoints_t *h, uint64_t emitted, int skip_zero, int preu, int stages,
                        uint32_t *L, unsigned long long *skipped);

#endif
