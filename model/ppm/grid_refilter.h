// SPDX-License-Identifier: Apache-2.0
/* grid_refilter.h: drop the grid entries that the current radii rule out (GRID_CELLS). */
#ifndef PREE_GRID_REFILTER_H
#define PREE_GRID_REFILTER_H

#include "grid.h"
#include "update.h"

/* Compact g's buckets to the entries whose hit point's current safe radius still touches the
 * bucket's cell: the radius in precision prec's radius copy, or, when r2_bits is not NULL, the
 * binary32 radius squared r2_bits[i] (a NaN: not known, the entries kept). Other grid kinds are
 * left as they are. Returns the entries dropped, or -1 when out of memory (the grid is then
 * unchanged). */
long long grid_refilter(grid_t *g, const hitpoints_t *h, precision_t prec, const uint32_t *r2_bits, int nthreads);

#endif
