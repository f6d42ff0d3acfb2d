// SPDX-License-Identifier: Apache-2.0
/* cosim_dist.h: a board of PREEs under mpirun: each rank's PREE memory and radiance pass
 * gathered on rank 0 (docs/scale_out.md, "Multi-PREE co-simulation"). */
#ifndef PREE_COSIM_DIST_H
#define PREE_COSIM_DIST_H

#include <stddef.h>
#include "cosim_compare.h"
#include "cosim_report.h"

/* Under mpirun, after the update pass (every rank alike; fail: this rank's state so far): the
 * ranks' PREE memories gathered into rank 0's got (photon-pass order); each PREE's radiance pass
 * over its own hit points, and the model's over the same hit points in the same order, compared
 * (mine->image_words_differing); rank 0 adds the ranks' pixel words in rank order in binary32,
 * as the host of a board of PREEs would, into Lr (the RTL's) and Lm (the model's); every rank's
 * figures into figs on rank 0. 0, or 1 when any rank failed (its message printed by it). */
int cosim_dist_gather(cosim_drv_t *drv, const cosim_part_t *p, const render_result_t *res, int preu, int pipefast,
                      size_t npix, int fail, hp_read_t *got, uint32_t *Lr, uint32_t *Lm, cosim_rank_t *mine,
                      cosim_rank_t *figs);

#endif
