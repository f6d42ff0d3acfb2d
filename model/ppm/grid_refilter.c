// SPDX-License-Identifier: Apache-2.0
/* grid_refilter.c: drop the GRID_CELLS entries that the current radii rule out.
 * Radii only shrink, so a hit point whose safe box, taken on its CURRENT radius, no longer
 * touches a cell can never accept a photon of that cell again. The safe radius is the build's
 * (grid_safe_radius: every binary32 rounding of positions and of the distance arithmetic) on
 * the current radius bound instead of r0, so no candidate the datapath could accept is lost;
 * dropping the others changes no image or state bit, only the candidates scanned. Buckets keep
 * their numbers (the cell map is untouched) and their entries keep their order. The radii come
 * from the hit points' state, or from a caller (the co-simulation host, which reads them back
 * from the PREE). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "fp32_ops.h"
#include "grid_refilter.h"

/* The cell of every bucket, as a packed key (UINT64_MAX: no cell), from the dense map or the
 * hashed table. NULL when out of memory. */
static uint64_t *bucket_cells(const grid_t *g)
{
    uint64_t *key = malloc(g->num_buckets * sizeof *key);
    if (!key) return NULL;
    for (size_t b = 0; b < g->num_buckets; b++) key[b] = UINT64_MAX;
    if (g->table) {
        for (size_t sl = 0; sl <= g->table_mask; sl++)
            if (g->table[sl].bucket != GRID_NO_BUCKET) key[g->table[sl].bucket] = g->table[sl].key;
        return key;
    }
    for (int64_t iz = 0; iz <= g->cell_max[2]; iz++)
        for (int64_t iy = 0; iy <= g->cell_max[1]; iy++)
            for (int64_t ix = 0; ix <= g->cell_max[0]; ix++) {
                const uint32_t b = g->dense[grid_dense_index(g, ix, iy, iz)];
                if (b != GRID_NO_BUCKET) key[b] = grid_cell_key(ix, iy, iz);
            }
    return key;
}

/* The cells that hit point i may still accept photons in: its safe box on its current radius,
 * from cell a to cell b on each axis, or every cell (all) when that cannot be proven smaller. */
typedef struct {
    uint32_t hp, all;
    int64_t a[3], b[3];
} reach_t;

/* Where the radii squared come from: binary32 bits (fp32 mode's copy, or a caller's), else double. */
typedef struct {
    const uint32_t *f32;
    const double *f64;
} radii_t;

static void reach_of(const grid_t *g, const hitpoints_t *h, const radii_t *r, uint32_t i, reach_t *m)
{
    m->hp = i;
    m->all = 1;
    const double r2 = r->f32 ? (double)fp32_from_bits(r->f32[i]) : r->f64[i];
    if (!(r2 >= 0)) return;   /* nothing to prove: keep */
    const double rs = grid_safe_radius(sqrt(r2), g->max_abs_coord);
    if (rs >= g->r_safe) return;
    const hp_hot_t *p = &h->hot[i];
    if (!grid_cell_coords(g, v3(p->px - rs, p->py - rs, p->pz - rs), m->a) ||
        !grid_cell_coords(g, v3(p->px + rs, p->py + rs, p->pz + rs), m->b)) return;
    m->all = 0;
}

/* Whether the cell of key k (UINT64_MAX: none) lies in m's cells. */
static int reaches(const reach_t *m, uint64_t k)
{
    if (m->all || k == UINT64_MAX) return 1;
    const uint64_t mask = ((uint64_t)1 << CELL_BITS) - 1;
    const int64_t c[3] = {(int64_t)(k & mask), (int64_t)((k >> CELL_BITS) & mask), (int64_t)(k >> (2 * CELL_BITS))};
    for (int ax = 0; ax < 3; ax++)
        if (c[ax] < m->a[ax] || c[ax] > m->b[ax]) return 0;
    return 1;
}

/* A hit point's entries stand in neighbouring buckets: its cells are remembered in a small
 * direct-mapped table (a power of two of slots, by hit-point index). */
#define REACH_MEMO 1024
/* How many entries ahead a hit point's position and radius are fetched: the hit points of a big
 * frame do not fit in the caches, and each entry would otherwise wait for its own. */
#define REACH_AHEAD 16

/* Bucket ranges that threads compact at once (more than threads, for balance). */
#define REFILTER_RANGES 256

/* Compact the buckets [b0, b1) of a part in place within their own entries, which start at lo
 * and end at hi (start[b0] and start[b1] before any change): start[b] becomes the bucket's new
 * first entry; memo: the calling thread's table (reach_t). Returns the entries kept. */
static size_t refilter_range(const grid_t *g, const hitpoints_t *h, const radii_t *r, grid_part_t *part,
                             const uint64_t *key, reach_t *memo, size_t b0, size_t b1, size_t lo, size_t hi)
{
    size_t w = lo, from = lo;
    for (size_t b = b0; b < b1; b++) {
        const size_t to = b + 1 == b1 ? hi : part->start[b + 1];
        part->start[b] = (uint32_t)w;
        for (size_t k = from; k < to; k++) {
            if (k + REACH_AHEAD < hi) {   /* the entries ahead are not yet moved (w <= k) */
                const uint32_t ahead = part->hp[k + REACH_AHEAD];
                __builtin_prefetch(&h->hot[ahead]);
                __builtin_prefetch(r->f32 ? (const void *)&r->f32[ahead] : (const void *)&r->f64[ahead]);
            }
            const uint32_t i = part->hp[k];
            reach_t *m = &memo[i & (REACH_MEMO - 1)];
            if (m->hp != i) reach_of(g, h, r, i, m);
            if (reaches(m, key[b])) part->hp[w++] = i;
        }
        from = to;
    }
    return w - lo;
}

/* Compact part p's buckets in place: ranges of buckets in parallel, then each range's entries
 * moved down to follow the previous range's. Returns the entries dropped, or -1 (memory). */
static long long refilter_part(grid_t *g, const hitpoints_t *h, const radii_t *rad, int p, const uint64_t *key,
                               reach_t *memo, int nthreads)
{
    grid_part_t *part = &g->parts[p];
    const size_t nb = g->num_buckets, nr = nb < REFILTER_RANGES ? nb : REFILTER_RANGES;
    size_t *edge = malloc((nr + 1) * sizeof *edge), *kept = malloc((nr ? nr : 1) * sizeof *kept);
    if (!edge || !kept) { free(edge); free(kept); return -1; }
    for (size_t r = 0; r <= nr; r++) edge[r] = part->start[nb * r / nr];
#pragma omp parallel for num_threads(nthreads) schedule(dynamic, 1)
    for (size_t r = 0; r < nr; r++)
        kept[r] = refilter_range(g, h, rad, part, key, memo + (size_t)omp_get_thread_num() * REACH_MEMO,
                                 nb * r / nr, nb * (r + 1) / nr, edge[r], edge[r + 1]);
    size_t w = 0;
    for (size_t r = 0; r < nr; r++) {
        const size_t shift = edge[r] - w;
        if (shift) {
            memmove(part->hp + w, part->hp + edge[r], kept[r] * sizeof *part->hp);
            for (size_t b = nb * r / nr; b < nb * (r + 1) / nr; b++) part->start[b] -= (uint32_t)shift;
        }
        w += kept[r];
    }
    free(edge);
    free(kept);
    part->start[nb] = (uint32_t)w;
    const size_t dropped = part->num_entries - w;
    part->num_entries = w;
    /* The padding beyond the last entry is zeros again, and the space dropped goes back. */
    for (size_t k = w; k < w + GRID_ENTRY_PAD; k++) part->hp[k] = 0;
    uint32_t *shrunk = realloc(part->hp, (w + GRID_ENTRY_PAD) * sizeof *part->hp);
    if (shrunk) part->hp = shrunk;
    return dropped;
}

long long grid_refilter(grid_t *g, const hitpoints_t *h, precision_t prec, const uint32_t *r2_bits, int nthreads)
{
    if (g->kind != GRID_CELLS || !g->parts) return 0;
    uint64_t *key = bucket_cells(g);
    if (!key) return -1;
    /* One memo table a thread, valid for the whole re-filter (the radii do not change in it). */
    reach_t *memo = malloc((size_t)nthreads * REACH_MEMO * sizeof *memo);
    if (!memo) { free(key); return -1; }
    for (size_t m = 0; m < (size_t)nthreads * REACH_MEMO; m++) memo[m].hp = UINT32_MAX;
    const radii_t rad = {r2_bits ? r2_bits : prec == PRECISION_DOUBLE ? NULL : h->r2_f32, h->r2};
    long long dropped = 0;
    for (int p = 0; p < g->num_parts && dropped >= 0; p++) {
        const long long d = refilter_part(g, h, &rad, p, key, memo, nthreads);
        dropped = d < 0 ? -1 : dropped + d;
    }
    free(key);
    free(memo);
    return dropped;
}
