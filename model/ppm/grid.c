/* grid.c: the reference hash grid, the default exact-cell grid and the brute-force list,
 * each stored per owning part as compressed bucket lists. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "grid.h"

#define CELL_LIMIT ((int64_t)1 << CELL_BITS)
#define EMPTY_KEY UINT64_MAX

/* x86-64 cvttsd2si: truncation toward zero; out of range or NaN gives INT_MIN. */
static inline int32_t trunc_i32(double v)
{
    if (!(v > -2147483649.0 && v < 2147483648.0)) return INT32_MIN;
    return (int32_t)v;
}

static inline uint32_t abs_u32(int32_t v) { return v < 0 ? 0u - (uint32_t)v : (uint32_t)v; }

/* The reference program's bucket of cell (ix, iy, iz): products wrap in 32 bits. */
static inline size_t smallppm_bucket(uint32_t ix, uint32_t iy, uint32_t iz, size_t nb)
{
    uint32_t hsh = (ix * 73856093u) ^ (iy * 19349663u) ^ (iz * 83492791u);
    return hsh % nb;
}


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
static size_t probe_from(const grid_slot_t *table, size_t mask, uint64_t key, size_t s)
{
    while (table[s].key != key && table[s].key != EMPTY_KEY) s = (s + 1) & mask;
    return s;
}

static size_t find_slot(const grid_slot_t *table, size_t mask, uint64_t key)
{
    return probe_from(table, mask, key, key_slot(key, mask));
}

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

static int alloc_parts(grid_t *g, int num_parts, size_t buckets, char *err, size_t errlen)
{
    g->num_parts = num_parts;
    g->num_buckets = buckets;
    g->parts = calloc((size_t)num_parts, sizeof *g->parts);
    if (!g->parts) goto oom;
    for (int p = 0; p < num_parts; p++) {
        g->parts[p].start = calloc(buckets + 1, sizeof(uint32_t));
        if (!g->parts[p].start) goto oom;
    }
    return 0;
oom:
    snprintf(err, errlen, "out of memory for the hit-point grid");
    return -1;
}

/* Turn per-bucket counts (in start[b+1]) into offsets and allocate the entries. */
static int finish_counts(grid_part_t *part, size_t buckets, char *err, size_t errlen)
{
    for (size_t b = 0; b < buckets; b++) part->start[b + 1] += part->start[b];
    part->num_entries = part->start[buckets];
    const size_t n = part->num_entries + GRID_ENTRY_PAD;
    part->hp = calloc(n, GRID_ENTRY_BYTES);   /* the padding reads as zeros: hit point 0 */
    if (!part->hp) { snprintf(err, errlen, "out of memory for the hit-point grid"); return -1; }
    return 0;
}

/* Cell range of hit point i on one axis in the reference grid. */
typedef struct { uint32_t lo[3], hi[3]; } cell_range_t;

static cell_range_t smallppm_range(const grid_t *g, const hp_hot_t *p)
{
    cell_range_t r;
    const double c[3] = {p->px, p->py, p->pz}, m[3] = {g->bmin.x, g->bmin.y, g->bmin.z};
    for (int a = 0; a < 3; a++) {
        r.lo[a] = abs_u32(trunc_i32(((c[a] - g->r0) - m[a]) * g->inv_cell));
        r.hi[a] = abs_u32(trunc_i32(((c[a] + g->r0) - m[a]) * g->inv_cell));
    }
    return r;
}

static int build_smallppm(grid_t *g, const hitpoints_t *h, int width, char *err, size_t errlen)
{
    vec3 lo = v3(1e20, 1e20, 1e20);
    for (size_t i = 0; i < h->n; i++) {
        const hp_hot_t *p = &h->hot[i];
        lo = v3(fmin(p->px - g->r0, lo.x), fmin(p->py - g->r0, lo.y), fmin(p->pz - g->r0, lo.z));
    }
    g->bmin = lo;
    g->inv_cell = 1.0 / (g->r0 * 2.0);
    size_t nb = h->n ? h->n : 1;
    if (alloc_parts(g, g->num_parts, nb, err, errlen)) return -1;
    /* Count, then fill. The reference prepends while walking hit points newest first, cells
     * z-outermost; filling each bucket from its end in that walk gives the same list order. */
    for (int pass = 0; pass < 2; pass++) {
        for (size_t k = h->n; k-- > 0;) {
            grid_part_t *part = &g->parts[grid_owner(h, k, width, g->num_parts)];
            cell_range_t r = smallppm_range(g, &h->hot[k]);
            for (uint32_t iz = r.lo[2]; iz <= r.hi[2]; iz++)
                for (uint32_t iy = r.lo[1]; iy <= r.hi[1]; iy++)
                    for (uint32_t ix = r.lo[0]; ix <= r.hi[0]; ix++) {
                        size_t b = smallppm_bucket(ix, iy, iz, nb);
                        if (pass == 0) part->start[b + 1]++;
                        else part->hp[--part->start[b + 1]] = (uint32_t)k;
                    }
        }
        if (pass == 0) {
            for (int p = 0; p < g->num_parts; p++) {
                if (finish_counts(&g->parts[p], nb, err, errlen)) return -1;
                /* Fill pointers start at each bucket's end: shift so start[b+1] = end of b. */
            }
        }
    }
    /* After filling from the ends, start[b+1] was decremented to bucket b's begin; restore. */
    for (int p = 0; p < g->num_parts; p++) {
        grid_part_t *part = &g->parts[p];
        for (size_t b = 0; b < nb; b++) part->start[b] = part->start[b + 1];
        part->start[nb] = (uint32_t)part->num_entries;
    }
    return 0;
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
    const int dense = cells <= GRID_DENSE_MAX && !getenv("PREE_GRID_HASHED");
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
            if (finish_counts(&g->parts[p], nb, err, errlen)) return -1;
            next[p] = g->parts[p].start;
        }
        return 0;
    }
    grid_part_t *part = &g->parts[0];
    part->start = calloc(nb + 1, sizeof *part->start);
    if (!part->start) goto oom;
    for (size_t b = 0; b < nb; b++)
        for (int l = 0; l < lanes; l++) part->start[b + 1] += count[l][b + 1];
    if (finish_counts(part, nb, err, errlen)) return -1;
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

static int build_cells(grid_t *g, const hitpoints_t *h, int width, int include_zero, char *err, size_t errlen)
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

static int build_brute(grid_t *g, const hitpoints_t *h, int width, char *err, size_t errlen)
{
    if (alloc_parts(g, g->num_parts, 1, err, errlen)) return -1;
    for (size_t i = 0; i < h->n; i++) g->parts[grid_owner(h, i, width, g->num_parts)].start[1]++;
    for (int p = 0; p < g->num_parts; p++) {
        if (finish_counts(&g->parts[p], 1, err, errlen)) return -1;
        g->parts[p].num_entries = 0;
    }
    for (size_t i = 0; i < h->n; i++) {
        grid_part_t *part = &g->parts[grid_owner(h, i, width, g->num_parts)];
        part->hp[part->num_entries++] = (uint32_t)i;
    }
    return 0;
}

int grid_build(grid_t *g, grid_kind_t kind, const hitpoints_t *h, double r0, int width,
               int num_parts, int include_zero_weight, const stop_flag_t *stop, char *err, size_t errlen)
{
    memset(g, 0, sizeof *g);
    g->stop = stop;
    g->kind = kind;
    g->num_parts = num_parts;
    g->r0 = r0;
    g->hot = h->hot;
    double max_abs = 0;
    for (size_t i = 0; i < h->n; i++) {
        const hp_hot_t *p = &h->hot[i];
        max_abs = fmax(max_abs, fmax(fabs(p->px), fmax(fabs(p->py), fabs(p->pz))));
    }
    g->max_abs_coord = max_abs + 4 * r0;
    g->r_safe = grid_safe_radius(r0, g->max_abs_coord);
    int rc;
    switch (kind) {
    case GRID_SMALLPPM: rc = build_smallppm(g, h, width, err, errlen); break;
    case GRID_CELLS: rc = build_cells(g, h, width, include_zero_weight, err, errlen); break;
    default: rc = build_brute(g, h, width, err, errlen); break;
    }
    if (rc == 0 && stop_requested(stop)) { snprintf(err, errlen, STOP_MESSAGE); rc = -1; }
    if (rc) grid_free(g);
    return rc;
}

void grid_free(grid_t *g)
{
    if (g->parts) {
        for (int p = 0; p < g->num_parts; p++) {
            free(g->parts[p].start);
            free(g->parts[p].hp);
        }
    }
    free(g->parts);
    free(g->dense);
    free(g->table);
    memset(g, 0, sizeof *g);
}

grid_probe_t grid_probe_begin(const grid_t *g, vec3 x)
{
    grid_probe_t p = {0, 0, 0};
    switch (g->kind) {
    case GRID_SMALLPPM: {
        uint32_t ix = abs_u32(trunc_i32((x.x - g->bmin.x) * g->inv_cell));
        uint32_t iy = abs_u32(trunc_i32((x.y - g->bmin.y) * g->inv_cell));
        uint32_t iz = abs_u32(trunc_i32((x.z - g->bmin.z) * g->inv_cell));
        p.at = smallppm_bucket(ix, iy, iz, g->num_buckets);
        return p;
    }
    case GRID_CELLS: {
        int64_t c[3];
        if (!grid_cell_coords(g, x, c)) { p.none = 1; return p; }
        if (g->dense) {
            p.at = grid_dense_index(g, c[0], c[1], c[2]);
            __builtin_prefetch(&g->dense[p.at]);
        } else {
            p.key = grid_cell_key(c[0], c[1], c[2]);
            p.at = key_slot(p.key, g->table_mask);
            __builtin_prefetch(&g->table[p.at]);
        }
        return p;
    }
    default:
        return p;
    }
}

uint32_t grid_probe_end(const grid_t *g, grid_probe_t p)
{
    if (p.none) return GRID_NO_BUCKET;
    if (g->kind != GRID_CELLS) return (uint32_t)p.at;
    if (g->dense) return g->dense[p.at];
    const grid_slot_t *slot = &g->table[probe_from(g->table, g->table_mask, p.key, p.at)];
    return slot->key == p.key ? slot->bucket : GRID_NO_BUCKET;
}

uint32_t grid_bucket(const grid_t *g, vec3 x)
{
    return grid_probe_end(g, grid_probe_begin(g, x));
}
