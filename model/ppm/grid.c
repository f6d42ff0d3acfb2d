// SPDX-License-Identifier: Apache-2.0
/* grid.c: the hit-point grid's front door: the reference hash grid and the brute-force list built
 * here, the default exact-cell grid in grid_cells.c, each stored per owning part as compressed
 * bucket lists; and the look-up of a photon's bucket. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "grid_table.h"

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

int grid_parts_alloc(grid_t *g, int num_parts, size_t buckets, char *err, size_t errlen)
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

int grid_part_finish(grid_part_t *part, size_t buckets, char *err, size_t errlen)
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
    if (grid_parts_alloc(g, g->num_parts, nb, err, errlen)) return -1;
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
                if (grid_part_finish(&g->parts[p], nb, err, errlen)) return -1;
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


static int build_brute(grid_t *g, const hitpoints_t *h, int width, char *err, size_t errlen)
{
    if (grid_parts_alloc(g, g->num_parts, 1, err, errlen)) return -1;
    for (size_t i = 0; i < h->n; i++) g->parts[grid_owner(h, i, width, g->num_parts)].start[1]++;
    for (int p = 0; p < g->num_parts; p++) {
        if (grid_part_finish(&g->parts[p], 1, err, errlen)) return -1;
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
    case GRID_CELLS: rc = grid_build_cells(g, h, width, include_zero_weight, err, errlen); break;
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
