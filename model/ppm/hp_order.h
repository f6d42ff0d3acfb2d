// SPDX-License-Identifier: Apache-2.0
/* hp_order.h: a spatial order of the hit points for the photon pass (see hp_order.c). */
#ifndef PREE_HP_ORDER_H
#define PREE_HP_ORDER_H

#include <stdint.h>
#include "hitpoints.h"

/* The order: perm[k] is the pixel-order index of the hit point placed at k. Sorted by owning
 * part (grid_owner with width and num_parts), then Morton code over cells of side `cell`,
 * then index. NULL when out of memory. */
uint32_t *hp_order_spatial(const hitpoints_t *h, int width, int num_parts, double cell);

/* Rearrange every array of h into that order, and back, each array in its own memory (through a
 * scratch of 24 bytes a hit point). 0, or -1 when out of memory (nothing is moved). */
int hp_order_apply(hitpoints_t *h, const uint32_t *perm);
int hp_order_restore(hitpoints_t *h, const uint32_t *perm);

#endif
