// SPDX-License-Identifier: Apache-2.0
/* grid_cells.c: the default exact-cell grid: the hit points' safe-radius boxes numbered into
 * buckets (a dense array of every cell, or a hashed table of the touched ones), counted and filled
 * in lanes that threads take, in the parts that own the hit points. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "grid_table.h"
#include "pree_env.h"

#define CELL_LIMIT ((int64_t)1 << CELL_BITS)

/* The buckets of the cells looked up last, direct-mapped by key. The build walks the hit points
 * in spatial order, and neighbours share most of their cells, so this answers most look-ups from
 * L1 where the table (tens of MB at 1600x1200) answers from memory. It only remembers what the
 * table says: the numbering and the buckets are the same with it or without. */
#define CELL_CACHE 256

typedef struct {
    uint64_t key[CELL_CACHE];
    uint32_t bucket[CELL_CACHE];
} cell_cache_t;

static void cell_cache_init(cell_cache_t *c)
{
    for (size_t i = 0; i < CELL_CACHE; i++) c->key[i] = EMPTY_KEY;
}

static inline size_t cell_cache_at(uint64_t key)
{
    return (size_t)((key * 0x9E3779B97F4A7C15ull) >> 56);   /* the top 8 bits: CELL_CACHE */
}

int grid_cell_coords(const grid_t *g, vec3 x, int64_t c[3])
{
    const double v[3] = {(x.x - g->bmin.x) * g->inv_cell, (x.y - g->bmin.y) * g->inv_cell,
                         (x.z - g->bmin.z) * g->inv_cell};
    for (int a = 0; a < 3; a++) {
        if (!(v[a] >= 0.0) || v[a] >= (double)(g->cell_max[a] + 1)) return 0;
        c[a] = (int64_t)v[a];
    }
    return 1;
}

/* The range of cells that hit point p's safe-radius box touches. */
static void cell_box(const grid_t *g, const hp_hot_t *p, double rs, int64_t a[3], int64_t b[3])
{
    grid_cell_coords(g, v3(p->px - rs, p->py - rs, p->pz - rs), a);
    grid_cell_coords(g, v3(p->px + rs, p->py + rs, p->pz + rs), b);
}

/* Whether GRID_CELLS lists hit point i: all of them, or those of non-zero weight. */
static int listed(const hitpoints_t *h, size_t i, int include_zero)
{
    return include_zero || !hitpoints_zero_weight(h, i);
}

/* Visit every cell of hit point p's safe-radius box. */
typedef void (*cell_visit_t)(void *ctx, const grid_t *g, int64_t ix, int64_t iy, int64_t iz);
typedef uint32_t (*bucket_of_t)(const grid_t *g, cell_cache_t *cache, int64_t ix, int64_t iy, int64_t iz);

static void each_cell(const grid_t *g, const hp_hot_t *p, cell_visit_t visit, void *ctx)
{
    int64_t a[3], b[3];
    cell_box(g, p, g->r_safe, a, b);
    for (int64_t iz = a[2]; iz <= b[2]; iz++)
        for (int64_t iy = a[1]; iy <= b[1]; iy++)
            for (int64_t ix = a[0]; ix <= b[0]; ix++) visit(ctx, g, ix, iy, iz);
}

typedef struct {
    uint32_t *entries;    /* the part's entries */
    uint32_t *next;       /* where the lane writes its next entry of each bucket */
    uint32_t hp;
    bucket_of_t bucket_of;
    cell_cache_t cache;
} fill_ctx_t;

static void fill_cell(void *ctx, const grid_t *g, int64_t ix, int64_t iy, int64_t iz)
{
    fill_ctx_t *f = ctx;
    uint32_t s = f->bucket_of(g, &f->cache, ix, iy, iz);
    f->entries[f->next[s]++] = f->hp;
}

/* The grid is counted and filled in lanes that threads take: with several parts, lane p walks the
 * hit points part p owns; with one part, lane l the l-th of `lanes` index ranges (their entries
 * follow one another in each bucket, so every bucket stays in index order). */
static int lane_of(const grid_t *g, const hitpoints_t *h, int width, int lanes, size_t i)
{
    if (g->num_parts > 1) return grid_owner(h, i, width, g->num_parts);
    return (int)(i * (size_t)lanes / h->n);
}

/* Fill lane l's entries: every listed hit point of the lane, in index order, in each bucket its
 * safe-radius box touches, at next[bucket]. bucket_of maps a cell to its bucket. */
static void cells_fill(grid_t *g, const hitpoints_t *h, int width, int include_zero, int lanes, int l,
                       uint32_t *entries, uint32_t *next, bucket_of_t bucket_of)
{
    fill_ctx_t f = {.entries = entries, .next = next, .bucket_of = bucket_of};
    cell_cache_init(&f.cache);
    const size_t n = h->n;
    /* One part: the lane's range of indices (lane_of's inverse); several: every index, those of
     * part l taken. */
    const int parts = g->num_parts > 1;
    const size_t lo = parts ? 0 : (n * (size_t)l + (size_t)lanes - 1) / (size_t)lanes;
    const size_t hi = parts ? n : (n * (size_t)(l + 1) + (size_t)lanes - 1) / (size_t)lanes;
    for (size_t i = lo; i < hi; i++) {
        if (!listed(h, i, include_zero) || (parts && lane_of(g, h, width, lanes, i) != l)) continue;
        f.hp = (uint32_t)i;
        each_cell(g, &h->hot[i], fill_cell, &f);
    }
}

static uint32_t dense_bucket(const grid_t *g, cell_cache_t *cache, int64_t ix, int64_t iy, int64_t iz)
{
    (void)cache;   /* the dense map is its own cache */
    return g->dense[grid_dense_index(g, ix, iy, iz)];
}

static uint32_t hashed_bucket(const grid_t *g, cell_cache_t *cache, int64_t ix, int64_t iy, int64_t iz)
{
    const uint64_t key = grid_cell_key(ix, iy, iz);
    const size_t at = cell_cache_at(key);
    if (cache->key[at] != key) {
        cache->key[at] = key;
        cache->bucket[at] = g->table[find_slot(g->table, g->table_mask, key)].bucket;
    }
    return cache->bucket[at];
}

/* The numbering pass: a cell's bucket is the order in which a listed hit point (in index order)
 * first touches it. The same pass counts each part's entries per bucket, in arrays that grow with
 * the buckets and become the parts' start[] (count of bucket b in [b + 1]): a second walk over
 * every (hit point, cell) pair only to count them cost as much as the numbering itself. */
typedef struct {
    grid_t *g;
    uint32_t **count;     /* count[l][b + 1]: lane l's entries in bucket b */
    int lanes;
    size_t cap;           /* buckets the count arrays hold */
    size_t distinct;      /* buckets numbered */
    int lane;             /* the lane of the hit point being visited */
    int failed;
    grid_slot_t *table;   /* hashed: open addressing on packed cell keys */
    size_t mask;
    cell_cache_t cache;
} number_ctx_t;

/* Double the count arrays (cap + 1 zeroed counts each, from 1024 buckets). 0 or -1 (memory). */
static int grow_counts(number_ctx_t *c)
{
    const size_t cap = c->cap ? 2 * c->cap : 1024, held = c->cap ? c->cap + 1 : 0;
    for (int l = 0; l < c->lanes; l++) {
        uint32_t *a = realloc(c->count[l], (cap + 1) * sizeof *a);
        if (!a) return -1;
        memset(a + held, 0, (cap + 1 - held) * sizeof *a);
        c->count[l] = a;
    }
    c->cap = cap;
    return 0;
}

/* The next bucket's number in *b, the count arrays grown to hold it. 0 or -1 (memory). */
static int new_bucket(number_ctx_t *c, uint32_t *b)
{
    if (c->distinct == c->cap && grow_counts(c)) return -1;
    *b = (uint32_t)c->distinct++;
    return 0;
}

static void number_dense(void *ctx, const grid_t *g, int64_t ix, int64_t iy, int64_t iz)
{
    number_ctx_t *c = ctx;
    uint32_t *d = &g->dense[grid_dense_index(g, ix, iy, iz)];
    if (c->failed) return;
    if (*d == GRID_NO_BUCKET && new_bucket(c, d)) { c->failed = 1; return; }
    c->count[c->lane][*d + 1]++;
}

/* The hashed table doubles before it is three quarters full, so it stays within 8/3 of the
 * distinct cells. (Doubling at half full, with 16-byte slots, took 33 MB more at 1600x1200.) */
static int hash_alloc(number_ctx_t *c, size_t size)
{
    c->table = malloc(size * sizeof *c->table);
    if (!c->table) return -1;
    for (size_t sl = 0; sl < size; sl++) c->table[sl] = (grid_slot_t){EMPTY_KEY, GRID_NO_BUCKET};
    c->mask = size - 1;
    return 0;
}

static int hash_double(number_ctx_t *c)
{
    grid_slot_t *old = c->table;
    const size_t old_mask = c->mask;
    if (hash_alloc(c, 2 * (old_mask + 1))) { c->table = old; c->mask = old_mask; return -1; }
    for (size_t sl = 0; sl <= old_mask; sl++)
        if (old[sl].key != EMPTY_KEY) c->table[find_slot(c->table, c->mask, old[sl].key)] = old[sl];
    free(old);
    return 0;
}

static void number_hashed(void *ctx, const grid_t *g, int64_t ix, int64_t iy, int64_t iz)
{
    (void)g;   /* the cell visitor's signature; the hashed numbering needs only the cell */
    number_ctx_t *c = ctx;
    if (c->failed) return;
    const uint64_t key = grid_cell_key(ix, iy, iz);
    const size_t at = cell_cache_at(key);
    if (c->cache.key[at] != key) {
        size_t sl = find_slot(c->table, c->mask, key);
        if (c->table[sl].key == EMPTY_KEY) {
            if (4 * (c->distinct + 1) > 3 * (c->mask + 1)) {
                if (hash_double(c)) { c->failed = 1; return; }
                sl = find_slot(c->table, c->mask, key);
            }
            uint32_t b;
            if (new_bucket(c, &b)) { c->failed = 1; return; }
            c->table[sl] = (grid_slot_t){key, b};
        }
        c->cache.key[at] = key;
        c->cache.bucket[at] = c->table[sl].bucket;
    }
    c->count[c->lane][c->cache.bucket[at] + 1]++;
}

/* Number the distinct cells that listed hit points touch (in a dense array of every cell when the
 * grid is small enough, else in an open-addressing table of packed keys, its size a power of two
 * of at least 4/3 of the distinct cells) and count each lane's entries into count[0 .. lanes)
 * (NULL on entry; the caller frees them). Sets g->num_buckets and g->dense or g->table. (The
 * table's buckets were once its slots, in hash order: at 1600x1200 the screening then walked the
 * hit points in random order. A first table sized for every (hit point, cell) pair took 512 MB at
 * 1600x1200.) 0 or -1 (memory). */
static int number_cells(grid_t *g, const hitpoints_t *h, int width, int include_zero, int lanes, uint32_t **count)
{
    const uint64_t cells = (uint64_t)(g->cell_max[0] + 1) * (uint64_t)(g->cell_max[1] + 1) * (uint64_t)(g->cell_max[2] + 1);
    const int dense = cells <= GRID_DENSE_MAX && !pree_env(PREE_ENV_GRID_HASHED);
    number_ctx_t c = {.g = g, .count = count, .lanes = lanes};
    cell_cache_init(&c.cache);
    if (grow_counts(&c)) return -1;
    if (dense) {
        g->dense = malloc(cells * sizeof *g->dense);
        if (!g->dense) return -1;
        memset(g->dense, 0xFF, cells * sizeof *g->dense);
    } else if (hash_alloc(&c, 1024)) {
        return -1;
    }
    for (size_t i = 0; i < h->n && !c.failed; i++) {
        if (!listed(h, i, include_zero)) continue;
        c.lane = lane_of(g, h, width, lanes, i);
        each_cell(g, &h->hot[i], dense ? number_dense : number_hashed, &c);
    }
    g->table = c.table;   /* grid_free frees it on every path from here */
    g->table_mask = c.mask;
    if (c.failed) return -1;
    g->num_buckets = c.distinct ? c.distinct : 1;
    return 0;
}

/* The parts' start[] and entries from the lanes' counts, and each lane's first entry of every
 * bucket in its own count array: with several parts a lane is a part (its counts become its
 * start[], which the fill advances); with one, lane l's entries of bucket b follow lanes 0 .. l-1's.
 * 0 or -1 (memory). */
static int lay_out_lanes(grid_t *g, int lanes, uint32_t **count, uint32_t **next, char *err, size_t errlen)
{
    const size_t nb = g->num_buckets;
    g->parts = calloc((size_t)g->num_parts, sizeof *g->parts);
    if (!g->parts) goto oom;
    if (g->num_parts > 1) {
        for (int p = 0; p < g->num_parts; p++) {
            uint32_t *a = realloc(count[p], (nb + 1) * sizeof *a);   /* give back the growth */
            g->parts[p].start = a ? a : count[p];
            count[p] = NULL;
            if (grid_part_finish(&g->parts[p], nb, err, errlen)) return -1;
            next[p] = g->parts[p].start;
        }
        return 0;
    }
    grid_part_t *part = &g->parts[0];
    part->start = calloc(nb + 1, sizeof *part->start);
    if (!part->start) goto oom;
    for (size_t b = 0; b < nb; b++)
        for (int l = 0; l < lanes; l++) part->start[b + 1] += count[l][b + 1];
    if (grid_part_finish(part, nb, err, errlen)) return -1;
    for (size_t b = 0; b < nb; b++) {
        uint32_t at = part->start[b];
        for (int l = 0; l < lanes; l++) {
            const uint32_t n = count[l][b + 1];   /* read before bucket b + 1's offset overwrites it */
            count[l][b] = at;
            at += n;
        }
    }
    for (int l = 0; l < lanes; l++) next[l] = count[l];
    return 0;
oom:
    snprintf(err, errlen, "out of memory for the hit-point grid");
    return -1;
}

/* Lanes of the one-part grid's counting and filling: one a thread, none below a few thousand hit
 * points a lane. */
#define FILL_LANES_MAX 64
static int fill_lanes(const grid_t *g, size_t n)
{
    if (g->num_parts > 1) return g->num_parts;
    int t = omp_get_max_threads();
    if (t > FILL_LANES_MAX) t = FILL_LANES_MAX;
    while (t > 1 && n / (size_t)t < 4096) t--;
    return t;
}

int grid_build_cells(grid_t *g, const hitpoints_t *h, int width, int include_zero, char *err, size_t errlen)
{
    vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3(-INFINITY, -INFINITY, -INFINITY);
    for (size_t i = 0; i < h->n; i++) {
        const hp_hot_t *p = &h->hot[i];
        lo = v3(fmin(p->px, lo.x), fmin(p->py, lo.y), fmin(p->pz, lo.z));
        hi = v3(fmax(p->px, hi.x), fmax(p->py, hi.y), fmax(p->pz, hi.z));
    }
    double rs = g->r_safe;
    g->bmin = v3(lo.x - rs, lo.y - rs, lo.z - rs);
    g->inv_cell = 1.0 / (GRID_CELL_FACTOR * g->r0);
    const double ext[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
    for (int a = 0; a < 3; a++) {
        double cells = h->n ? floor((ext[a] + 2 * rs) * g->inv_cell) : 0;
        if (cells >= (double)(CELL_LIMIT - 1)) {
            snprintf(err, errlen, "the scene spans more than %lld cells of the photon radius on one axis",
                     (long long)(CELL_LIMIT - 1));
            return -1;
        }
        g->cell_max[a] = (int64_t)cells + 1;   /* one spare cell absorbs rounding */
    }
    g->zero_weight_skipped = 0;
    for (size_t i = 0; i < h->n; i++) g->zero_weight_skipped += !listed(h, i, include_zero);
    const int lanes = fill_lanes(g, h->n);
    uint32_t **count = calloc((size_t)lanes, sizeof *count), **next = calloc((size_t)lanes, sizeof *next);
    int rc = -1;
    if (!count || !next || number_cells(g, h, width, include_zero, lanes, count)) {
        snprintf(err, errlen, "out of memory for the hit-point grid");
        goto done;
    }
    if (stop_requested(g->stop)) { snprintf(err, errlen, STOP_MESSAGE); goto done; }
    if (lay_out_lanes(g, lanes, count, next, err, errlen)) goto done;
    bucket_of_t bucket_of = g->dense ? dense_bucket : hashed_bucket;
    /* The lanes are filled in parallel. */
#pragma omp parallel for schedule(static, 1) num_threads(lanes)
    for (int l = 0; l < lanes; l++)
        cells_fill(g, h, width, include_zero, lanes, l, g->parts[g->num_parts > 1 ? l : 0].hp, next[l], bucket_of);
    /* Several parts: filling advanced start[s] to the end of bucket s: shift back. */
    for (int p = 0; g->num_parts > 1 && p < g->num_parts; p++) {
        grid_part_t *part = &g->parts[p];
        for (size_t sl = g->num_buckets; sl > 0; sl--) part->start[sl] = part->start[sl - 1];
        part->start[0] = 0;
    }
    rc = 0;
done:
    for (int l = 0; count && l < lanes; l++) free(count[l]);
    free(count);
    free(next);
    return rc;
}
