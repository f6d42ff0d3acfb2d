// SPDX-License-Identifier: Apache-2.0
/* cosim_refilter.h: the host's re-filter of the engine's grid with radii read back from the PREE.
 *
 * Radii only shrink, so the engine drops the grid entries that the current radii rule out after
 * photon blocks 1, 2, 4, 8, ... (model/ppm/grid_refilter.c). When it records the PREE's
 * operations it does not read its own state for that: the host does what an FPGA host could. At
 * such a point, between two blocks, it drains the PREE (every operation sent applied, idle), reads
 * every hit point of its memory back through the host port (one cycle each; pree_axi: CMD 2
 * blocks) and gives the engine the radius bound of each (preu_hpw_screen_r2); the engine then
 * streams fewer candidates. The images and hit-point states stay those of a run without it.
 *
 * API
 *   cosim_refilter(drv, rs, hp, part, dp, model_only, st, err, errlen)  when the engine says one is
 *       due (render_refilter_due): drain, read back, re-filter. Another rank's hit points (under
 *       mpirun) are not known here and keep their entries. With --model-only no PREE runs: the
 *       radii are then the model's words, which the RTL reproduces bit for bit. 0, or -1 with err. */
#ifndef PREE_COSIM_REFILTER_H
#define PREE_COSIM_REFILTER_H

#include "cosim_drv.h"
#include "cosim_layout.h"
#include "render.h"

typedef struct {
    unsigned long long refilters;        /* re-filters made */
    unsigned long long hit_points_read;  /* hit points read back for them */
} cosim_refilter_stats_t;

int cosim_refilter(cosim_drv_t *drv, render_session_t *rs, const hitpoints_t *hp, const cosim_part_t *part, int dp,
                   int model_only, cosim_refilter_stats_t *st, char *err, size_t errlen);

#endif
