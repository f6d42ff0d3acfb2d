// SPDX-License-Identifier: Apache-2.0
/* grid.h: spatial look-up of hit points for photons, split into parts that threads own.
 *
 * Three kinds:
 *   GRID_SMALLPPM  the reference program's hash grid, exactly: cells of side 2*r0 hashed into
 *                  as many buckets as there are hit points; buckets of different cells may
 *                  coincide and a hit point may stand in one bucket twice. Nothing is skipped.
 *   GRID_CELLS     the default: exact cells of side 2*r0 (no shared buckets, a hit point at most
 *                  once per cell), hit points of weight zero left out, and a hit point listed
 *                  in every cell its safe radius touches (see grid_safe_radius). Buckets are
 *                  numbered in the order the hit points (held in spatial order) first touch
 *                  their cells, so neighbouring buckets hold neighbouring hit points.
 *   GRID_BRUTE     every hit point is a candidate for every photon: the test oracle.
 * Part p holds only the hit points that part owns (grid_owner), in the same relative order,
 * so threads update disjoint hit points and each hit point sees photons in index order. */
#ifndef PREE_GRID_H
#define PREE_GRID_H

#include <stddef.h>
#include <stdint.h>
#include "hitpoints.h"
#include "stop.h"

typedef enum { GRID_CELLS = 0, GRID_SMALLPPM = 1, GRID_BRUTE = 2 } grid_kind_t;

/* GRID_CELLS cell side in units of r0. Measured on cornell3 320x240 (one thread): side r0 gives
 * 3.8 M entries and 30.7 M candidates, 2 r0 gives 1.1 M entries (2.5x less memory) and 54.5 M
 * candidates, scanned in sequence and mostly rejected by the radius prefilter, and was fastest. */
#define GRID_CELL_FACTOR 2.0
#define GRID_NO_BUCKET ((uint32_t)0xFFFFFFFFu)
/* GRID_CELLS numbers its cells in a dense array (4 bytes per cell of the hit points' bounding box)
 * up to this many cells, else in a hash table of the cells in use. */
#define GRID_DENSE_MAX ((uint64_t)1 << 23)
/* Entries allocated beyond the last, so that four-wide loads at a bucket's end stay in bounds. */
#define GRID_ENTRY_PAD 4
/* Bytes per entry (grid_part_t: a hit-point index). */
#define GRID_ENTRY_BYTES sizeof(uint32_t)
/* GRID_CELLS cell coordinates take CELL_BITS bits each in a packed key. */
#define CELL_BITS 21

/* A part's entries (candidates): entry k is the index hp[k] of a hit point, whose geometry is read
 * from the hit points themselves (grid_t.hot). The photon pass holds the hit points in spatial
 * order (hp_order.c) and a bucket lists its hit points in index order, so a bucket's geometry lies
 * close together; a copy per entry (52 bytes against 4) measured 2.18 GB at 1600x1200. */
typedef struct {
    uint32_t *start;       /* bucket b's entries are [start[b] .. start[b+1]) */
    uint32_t *hp;          /* hit-point index (GRID_ENTRY_PAD zeros beyond the last) */
    size_t num_entries;
} grid_part_t;

/* A slot of the hashed cell table: a packed cell key (UINT64_MAX: empty) and its bucket. Key and
 * bucket share a slot so that a photon's look-up reads one line. */
typedef struct {
    uint64_t key;
    uint32_t bucket;
} grid_slot_t;

/* One bucket's candidates in one part: hit points hot[hp[0 .. count-1]]. */
typedef struct {
    const hp_hot_t *hot;   /* every hit point's geometry (not the bucket's) */
    const uint32_t *hp;
    size_t count;
} grid_cands_t;

typedef struct {
    grid_kind_t kind;
    int num_parts;
    grid_part_t *parts;
    size_t num_buckets;      /* smallppm: number of hit points; cells: distinct cells */
    uint32_t *dense;         /* GRID_CELLS with at most GRID_DENSE_MAX cells: cell -> bucket or GRID_NO_BUCKET */
    grid_slot_t *table;      /* GRID_CELLS with more cells: open addressing on the packed cell key */
    size_t table_mask;       /* table size - 1 (a power of two, at least 4/3 of the distinct cells) */
    vec3 bmin;               /* cell origin */
    double inv_cell;         /* 1 / cell side */
    int64_t cell_max[3];     /* GRID_CELLS: valid cell coordinates are 0 .. cell_max */
    double r0;               /* initial radius */
    double r_safe;           /* radius within which the fp32 datapath could ever accept */
    double max_abs_coord;    /* the coordinate magnitude r_safe's rounding margin covers */
    size_t zero_weight_skipped;
    const hp_hot_t *hot;     /* the geometry the entries index: the hit points' (which stay in place
                              * and in the build's order while the grid is used) */
    const stop_flag_t *stop; /* build: polled between the passes over the hit points */
} grid_t;

/* The reference program's initial radius: mean bbox side over mean image side, times 2. */
double grid_initial_radius(const hitpoints_t *h, int width, int height);

/* r0 enlarged by a margin that covers binary32 rounding of positions (magnitude up to
 * max_abs_coord) and of the distance arithmetic, so that a candidate farther than it from
 * a photon can never be accepted in either precision. */
double grid_safe_radius(double r0, double max_abs_coord);

/* Which part owns hit point i (bands of 8 image rows, dealt round-robin). */
static inline int grid_owner(const hitpoints_t *h, size_t i, int width, int num_parts)
{
    return (int)((h->pixel[i] / width / 8) % num_parts);
}

/* Build the grid. include_zero_weight: list hit points of weight zero too (GRID_CELLS
 * leaves them out otherwise; the other kinds always list them). 0, or -1 with err (STOP_MESSAGE
 * when stop was set between passes). */
int grid_build(grid_t *g, grid_kind_t kind, const hitpoints_t *h, double r0, int width,
               int num_parts, int include_zero_weight, const stop_flag_t *stop, char *err, size_t errlen);

void grid_free(grid_t *g);

/* The bucket of a photon at x, the same for every part, or GRID_NO_BUCKET when no hit point
 * can be near x (GRID_CELLS only: an empty cell). */
uint32_t grid_bucket(const grid_t *g, vec3 x);

/* grid_bucket in two halves, so that a run of look-ups overlaps its cache misses: begin finds
 * x's cell and where its bucket number lies (the dense map's entry or the table's first slot to
 * probe) and starts fetching it; end reads it. */
typedef struct {
    uint64_t key;   /* GRID_CELLS hashed: the packed cell key */
    size_t at;      /* the dense map's index, the table's first slot, or (other kinds) the bucket */
    int none;       /* x lies in no cell of the grid: GRID_NO_BUCKET */
} grid_probe_t;
grid_probe_t grid_probe_begin(const grid_t *g, vec3 x);
uint32_t grid_probe_end(const grid_t *g, grid_probe_t p);

/* Part p's candidates in bucket b (not GRID_NO_BUCKET). */
static inline grid_cands_t grid_bucket_cands(const grid_t *g, int p, uint32_t b)
{
    const grid_part_t *part = &g->parts[p];
    const size_t k = part->start[b];
    grid_cands_t c = {g->hot, part->hp + k, part->start[b + 1] - k};
    return c;
}


/* GRID_CELLS: the cell that x lies in, in c; 0 when x is outside the grid. */
int grid_cell_coords(const grid_t *g, vec3 x, int64_t c[3]);

static inline uint64_t grid_cell_key(int64_t ix, int64_t iy, int64_t iz)
{
    return (uint64_t)ix | ((uint64_t)iy << CELL_BITS) | ((uint64_t)iz << (2 * CELL_BITS));
}

/* Linear index of a cell in the dense map (GRID_CELLS with few enough cells). */
static inline size_t grid_dense_index(const grid_t *g, int64_t ix, int64_t iy, int64_t iz)
{
    return ((size_t)iz * (size_t)(g->cell_max[1] + 1) + (size_t)iy) * (size_t)(g->cell_max[0] + 1) + (size_t)ix;
}

#endif
