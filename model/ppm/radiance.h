// SPDX-License-Identifier: Apache-2.0
/* radiance.h: radiance evaluation (Eq. 4 of paper 000): each hit point adds
 * tau / (pi R^2 N_emitted) to its pixel.
 *
 * Double mode: the reference program's order, hit points newest first, factor
 * 1/(((pi*r2)*batches)*1000). fp32 mode: the PREE's radiance pass (Eq. 9), each pixel
 * accumulated from +0 over its hit points in the order in which that PREE issues them: ADISO-REC's
 * leaping sequence over its hit-point addresses (model/pree/adiso_order.h, docs/pree_top.md
 * "Radiance order") for its PREU count and radiance pipeline depth, each address standing for the
 * hit point its layout puts there. So the fp32 image is the RTL's, bit for bit. Hit points of
 * weight zero add exactly zero and are skipped when skip_zero is set (counted in *skipped). */
#ifndef PREE_RADIANCE_H
#define PREE_RADIANCE_H

#include <stddef.h>
#include <stdint.h>
#include "hitpoints.h"
#include "pree_config.h"
#include "update.h"

/* The PREE whose radiance pass the fp32 mode reproduces, or a board of them (prees > 1: the
 * co-simulation under mpirun -np prees, docs/scale_out.md): PREE r holds the addresses
 * [lo(r), lo(r + 1)) (render_dist_lo of n) at its own addresses 0, 1, ... and evaluates them
 * alone, and the board's image is the PREEs' pixel words added in binary32 in PREE order
 * (radiance_board_add). */
typedef struct {
    int preu;             /* PREUs: a power of two in 1..64 */
    int stages;           /* their radiance pipeline's depth, ADISO-REC's Npip_stage (radiance_depth) */
    const uint32_t *at;   /* at[a]: the hit point at address a of its memory; NULL: hit point a */
    size_t n;             /* the addresses 0..n-1 it holds (n <= h->n; with at NULL, n = h->n) */
    int prees;            /* radiance_evaluate_preu: PREEs of the board (0 or 1: one PREE) */
} radiance_pree_t;

/* The radiance pipeline's depth of a PREU: 12 in the paper's configuration (RTL PipeFast = 0),
 * 64 in the deep one (PipeFast = 1), from the configuration table (pree_config.h); rtl/pree_top.v's
 * RAD_LAT, which the co-simulation checks against this before every run. */
static inline int radiance_depth(int pipe_fast)
{
    return PREE_RADIANCE_DEPTH(pipe_fast);
}

/* The image into rgb (3 doubles a pixel, num_pixels of them); pree: the fp32 mode's PREE or
 * board (not read in double mode). Returns 0, or -1 when out of memory, or the PREE is not one
 * adiso_order takes (preu a power of two in 1..64, stages >= 1), or a board has no `at`. */
int radiance_evaluate_preu(const hitpoints_t *h, precision_t prec, const radiance_pree_t *pree, uint64_t emitted,
                           int skip_zero, double *rgb, size_t num_pixels, unsigned long long *skipped);
/* fp32 only: add the contributions of the hit points one PREE holds (pree->prees not read) to the
 * binary32 pixel sums L (3 words per pixel, zeroed by the caller), in its issue order. Returns 0
 * or -1 as above. */
int radiance_fp32_words(const hitpoints_t *h, const radiance_pree_t *pree, uint64_t emitted, int skip_zero,
                        uint32_t *L, unsigned long long *skipped);
/* The emitted radiance the eye paths met (render_result_t.emitted; NULL: none) added to the
 * image rgb, after the radiance pass, on the host: in double, or in fp32 mode as binary32 (rgb
 * holds binary32 values; emitted rounded once to binary32, then one binary32 addition), so the
 * fp32 image stays binary32 and an image from the RTL's pixel words gets the same bits. Pixels
 * that meet no light are untouched. */
void radiance_add_emitted(double *rgb, const double *emitted, size_t num_pixels, precision_t prec);
/* A board's image: PREE r's pixel words `part` added to the sums L in binary32 (first: PREE 0,
 * whose words L takes as they are). */
void radiance_board_add(uint32_t *L, const uint32_t *part, size_t words, int first);

#endif
