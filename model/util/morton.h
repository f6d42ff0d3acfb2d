// SPDX-License-Identifier: Apache-2.0
/* morton.h: 3-D Morton (Z-order) codes, 21 bits an axis: the spatial orders of the hit points
 * (model/ppm/hp_order.c) and of the photon-map clustering (model/pm/cluster.c). */
#ifndef PREE_MORTON_H
#define PREE_MORTON_H

#include <stdint.h>

#define MORTON_BITS 21

/* The low 21 bits of v spread to every third bit. */
static inline uint64_t morton_spread3(uint64_t v)
{
    v &= 0x1FFFFFull;
    v = (v | v << 32) & 0x001F00000000FFFFull;
    v = (v | v << 16) & 0x001F0000FF0000FFull;
    v = (v | v << 8) & 0x100F00F00F00F00Full;
    v = (v | v << 4) & 0x10C30C30C30C30C3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
}

#endif
