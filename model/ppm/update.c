// SPDX-License-Identifier: Apache-2.0
/* update.c: the candidate loop of the photon pass: grid look-up, tests, update.
 * Candidates are read from the grid's entry copies in sequence; only an accepted update
 * touches the hit point's own state (and rewrites the radius copies). */
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "update.h"

/* Radii are prefetched this many candidates ahead within a bucket. */
#define RADIUS_AHEAD 6

/* Double mode: the reference program's tests, normal first, then distance. */
static void scan_double(hitpoints_t *h, grid_t *g, int skip_radius, const photon_hit_t *ph,
                        const grid_cands_t *e, update_stats_t *s)
{
    const double rs2 = g->r_safe * g->r_safe;
    const double x = ph->x.x, y = ph->x.y, z = ph->x.z;
    const double nx = ph->n.x, ny = ph->n.y, nz = ph->n.z;
    for (size_t c = 0; c < e->count; c++) {
        if (c + RADIUS_AHEAD < e->count) {
            __builtin_prefetch(&h->r2[e->hp[c + RADIUS_AHEAD]]);
            __builtin_prefetch(&e->hot[e->hp[c + RADIUS_AHEAD]]);
        }
        const hp_hot_t *q = &e->hot[e->hp[c]];
        double vx = q->px - x, vy = q->py - y, vz = q->pz - z;
        double v2 = vx * vx + vy * vy + vz * vz;
        /* Radii only shrink: a candidate beyond the safe initial radius never accepts. */
        if (skip_radius && v2 > rs2) { s->skipped_radius++; continue; }
        if (!(q->nx * nx + q->ny * ny + q->nz * nz > UPDATE_NORMAL_COS)) continue;
        s->normal_passed++;
        if (v2 <= h->r2[e->hp[c]]) {
            update_accept_double(h, e->hp[c], ph->flux);
            s->accepted++;
        }
    }
}

/* fp32 mode: the host's normal test in double, then the PREU datapath in binary32. The
 * distance test reads the entry's position rounded to binary32 (= the PREU's stored
 * position) and the compact copy of the PREU's r2, as preu_update_inline does. */
void update_ops_clear(update_ops_t *o)
{
    o->n_hits = o->n_ops = 0;
    o->failed = 0;
}

void update_ops_free(update_ops_t *o)
{
    free(o->ph);
    free(o->end);
    free(o->hp);
    memset(o, 0, sizeof *o);
}

/* Room in ops for one more photon hit with up to count operations: 0, or -1 (memory). */
static int ops_reserve(update_ops_t *o, size_t count)
{
    if (grow_array((void **)&o->hp, &o->cap_ops, o->n_ops + count, sizeof *o->hp)) return -1;
    if (o->n_hits < o->cap_hits) return 0;
    size_t cap = o->cap_hits;
    if (grow_array((void **)&o->end, &cap, o->n_hits + 1, sizeof *o->end)) return -1;
    preu_photon_t *ph = realloc(o->ph, cap * sizeof *ph);
    if (!ph) return -1;
    o->ph = ph;
    o->cap_hits = cap;
    return 0;
}

static void scan_fp32(hitpoints_t *h, grid_t *g, int skip_radius, const photon_hit_t *ph,
                      const grid_cands_t *e, update_stats_t *s, update_ops_t *ops)
{
    const size_t count = e->count;
    if (ops && ops_reserve(ops, count)) { ops->failed = 1; return; }
    const double rs2 = g->r_safe * g->r_safe;
    const preu_photon_t ph32 = update_photon_fp32(ph);
    const float fx = fp32_from_bits(ph32.pos[0]), fy = fp32_from_bits(ph32.pos[1]), fz = fp32_from_bits(ph32.pos[2]);
    const double nx = ph->n.x, ny = ph->n.y, nz = ph->n.z;
    for (size_t c = 0; c < count; c++) {
        const hp_hot_t *q = &e->hot[e->hp[c]];
        if (skip_radius) {
            double vx = q->px - ph->x.x, vy = q->py - ph->x.y, vz = q->pz - ph->x.z;
            if (vx * vx + vy * vy + vz * vz > rs2) { s->skipped_radius++; continue; }
        }
        if (!(q->nx * nx + q->ny * ny + q->nz * nz > UPDATE_NORMAL_COS)) continue;
        s->normal_passed++;
        const uint32_t hp = e->hp[c];
        if (ops) ops->hp[ops->n_ops++] = hp;
        float dx = (float)q->px - fx, dy = (float)q->py - fy, dz = (float)q->pz - fz;
        float d2 = (dx * dx + dy * dy) + dz * dz;
        if (!(d2 <= fp32_from_bits(h->r2_f32[hp]))) continue;
        s->accepted += (unsigned long long)update_apply_fp32(h, hp, &ph32, d2);
    }
    if (ops) {
        ops->ph[ops->n_hits] = ph32;
        ops->end[ops->n_hits++] = ops->n_ops;
    }
}

/* Look-ups run this many photon hits ahead of the scan, with their first entries and
 * radii prefetched: the loop is bound by memory latency, not arithmetic. */
#define LOOKAHEAD 8

typedef grid_cands_t lookup_t;

static inline lookup_t lookup(const grid_t *g, int p, const photon_hit_t *ph)
{
    if (ph->bucket != GRID_NO_BUCKET) return grid_bucket_cands(g, p, ph->bucket);
    lookup_t none = {0};
    return none;
}

static inline void prefetch_lookup(const hitpoints_t *h, precision_t prec, const lookup_t *l)
{
    if (!l->count) return;
    __builtin_prefetch(l->hp);
    for (size_t c = 0; c < l->count && c < 4; c++) {
        __builtin_prefetch(&l->hot[l->hp[c]]);
        if (prec == PRECISION_DOUBLE) __builtin_prefetch(&h->r2[l->hp[c]]);
    }
}

void update_part(hitpoints_t *h, grid_t *g, int p, precision_t prec, int skip_radius,
                 const photon_hit_t *hits, size_t n, update_stats_t *st, update_ops_t *ops)
{
    update_stats_t s = *st;
    lookup_t ring[LOOKAHEAD];
    for (size_t k = 0; k < n && k < LOOKAHEAD; k++) {
        ring[k] = lookup(g, p, &hits[k]);
        if (ring[k].count) __builtin_prefetch(ring[k].hp);
    }
    for (size_t k = 0; k < n; k++) {
        lookup_t cur = ring[k % LOOKAHEAD];
        if (k + LOOKAHEAD < n) {
            lookup_t *next = &ring[k % LOOKAHEAD];
            *next = lookup(g, p, &hits[k + LOOKAHEAD]);
            prefetch_lookup(h, prec, next);
        }
        s.candidates += cur.count;
        if (prec == PRECISION_DOUBLE) { if (cur.count) scan_double(h, g, skip_radius, &hits[k], &cur, &s); }
        else if (!(ops && ops->failed)) scan_fp32(h, g, skip_radius, &hits[k], &cur, &s, ops);
    }
    *st = s;
}
