// SPDX-License-Identifier: Apache-2.0
/* cosim_compare.h: what the co-simulation compares with the fp32 model: the PREE's hit-point
 * memory word for word, and its image with the model's radiance summed in the PREE's order. */
#ifndef PREE_COSIM_COMPARE_H
#define PREE_COSIM_COMPARE_H

#include <stddef.h>
#include <stdint.h>
#include "cosim_drv.h"
#include "cosim_layout.h"
#include "render.h"

/* Hit point i of the model in the PREE memory's words. */
void cosim_model_words(const hitpoints_t *hp, size_t i, preu_hpw_t *w);

/* The RTL's hit-point memory got[0..hp->n) against the model's hit points (got[i] holds the
 * model's hit point part->model[i], in rank r's PREE where part->lo[r] <= i < part->lo[r + 1];
 * or, where part is NULL, i): differing words; the hit points that
 * differ and the first (its index in got) in *points and *first (SIZE_MAX: none). The first
 * five are printed. PREE_TEST_CORRUPT_HP=N flips a bit of the model's hit point N first: the
 * failure path's check (tests/checks/fail_trace.sh, mpi_cosim.sh). */
unsigned long long cosim_compare_hit_points(const hp_read_t *got, const cosim_part_t *part, const hitpoints_t *hp,
                                            int dp, unsigned long long *points, size_t *first);

/* The pixel words of Lr that differ from Lm's; with print, the first five are printed. */
unsigned long long cosim_image_words_differ(const uint32_t *Lr, const uint32_t *Lm, size_t npix, int print);

/* The fp32 model's radiance pass over n hit points in a PREE's address order (order[a]: the
 * model's index of the hit point at address a; NULL: the model's own order, all of them), the
 * order in which that PREE's ADISO-REC adds them: into L (zeroed here). 0 or -1 (memory). */
int cosim_model_radiance(const render_result_t *res, const uint32_t *order, size_t n, int preu, int pipefast,
                         size_t npix, uint32_t *L);

/* The radiance pass in RTL (pixel words into Lr) and in the model (into Lm), in the same order
 * (order: as for cosim_model_radiance): the differing words (the first five printed), or -1 with a
 * message printed. */
long long cosim_compare_image(cosim_drv_t *drv, const render_result_t *res, const uint32_t *order, int preu,
                              int pipefast, size_t npix, uint32_t *Lr, uint32_t *Lm);

#endif
