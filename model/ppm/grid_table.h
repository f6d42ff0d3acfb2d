// SPDX-License-Identifier: Apache-2.0
/* grid_table.h: inside the grid (grid.c builds the reference grid and the brute list and looks
 * cells up; grid_cells.c builds the exact-cell grid): the cells' open-addressing table and the
 * parts' allocation, which both use. Not for callers of grid.h. */
#ifndef PREE_GRID_TABLE_H
#define PREE_GRID_TABLE_H
#include <stddef.h>
#include <stdint.h>
#include "grid.h"

#define EMPTY_KEY UINT64_MAX

/* splitmix64's finaliser: every key bit reaches every slot bit. */
static inline size_t key_slot(uint64_t key, size_t mask)
{
    key ^= key >> 30;
    key *= 0xBF58476D1CE4E5B9ull;
    key ^= key >> 27;
    key *= 0x94D049BB133111EBull;
    key ^= key >> 31;
    return (size_t)key & mask;
}

/* The slot of key, or the empty slot where it would go, probing linearly from slot s. */
static inline size_t probe_from(const grid_slot_t *table, size_t mask, uint64_t key, size_t s)
{
    while (table[s].key != key && table[s].key != EMPTY_KEY) s = (s + 1) & mask;
    return s;
}

static inline size_t find_slot(const grid_slot_t *table, size_t mask, uint64_t key)
{
    return probe_from(table, mask, key, key_slot(key, mask));
}

/* g->parts (num_parts of them) with zeroed start[] of buckets + 1 counts. 0, or -1 with err. */
int grid_parts_alloc(grid_t *g, int num_parts, size_t buckets, char *err, size_t errlen);

/* Turn a part's per-bucket counts (in start[b+1]) into offsets and allocate its entries. */
int grid_part_finish(grid_part_t *part, size_t buckets, char *err, size_t errlen);

/* The GRID_CELLS grid of hit points h (grid_build's fields already set). 0, or -1 with err. */
int grid_build_cells(grid_t *g, const hitpoints_t *h, int width, int include_zero, char *err, size_t errlen);

#endif
