/* hp_order.c: a spatial order of the hit points for the photon pass.
 *
 * The eye pass stores hit points in pixel order, so a photon's candidates (spatial neighbours)
 * lie scattered over the state arrays and every radius read and accepted update is a cache
 * miss. During the photon pass the hit points are held in the order of the owning part
 * (grid_owner), then the Morton code of their position, then their index; afterwards they
 * return to pixel order. Each hit point's own sequence of updates is the same in any order,
 * so results are unchanged to the bit. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grid.h"
#include "hp_order.h"
#include "morton.h"


/* Spread the low 21 bits of v to every third bit. */
static uint32_t quantize(double x, double lo, double scale)
{
    double q = (x - lo) * scale;
    if (!(q > 0)) return 0;
    if (q >= (double)((1u << MORTON_BITS) - 1)) return (1u << MORTON_BITS) - 1;
    return (uint32_t)q;
}

typedef struct { uint64_t key; uint32_t part, index; } sort_item_t;

uint32_t *hp_order_spatial(const hitpoints_t *h, int width, int num_parts, double cell)
{
    const size_t n = h->n;
    uint32_t *perm = malloc((n ? n : 1) * sizeof *perm);
    sort_item_t *items = malloc((n ? n : 1) * sizeof *items);
    if (!perm || !items) { free(perm); free(items); return NULL; }
    double lo[3] = {INFINITY, INFINITY, INFINITY};
    for (size_t i = 0; i < n; i++) {
        lo[0] = fmin(lo[0], h->hot[i].px);
        lo[1] = fmin(lo[1], h->hot[i].py);
        lo[2] = fmin(lo[2], h->hot[i].pz);
    }
    const double scale = cell > 0 ? 1.0 / cell : 1.0;
    for (size_t i = 0; i < n; i++) {
        const hp_hot_t *p = &h->hot[i];
        uint64_t key = morton_spread3(quantize(p->px, lo[0], scale)) | morton_spread3(quantize(p->py, lo[1], scale)) << 1 |
                       morton_spread3(quantize(p->pz, lo[2], scale)) << 2;
        items[i] = (sort_item_t){key, (uint32_t)grid_owner(h, i, width, num_parts), (uint32_t)i};
    }
    /* Stable LSD radix sort on (part, key); items start in index order, so ties keep it. */
    sort_item_t *tmp = malloc((n ? n : 1) * sizeof *tmp);
    if (!tmp) { free(perm); free(items); return NULL; }
    uint32_t max_part = 0;
    uint64_t key_bits = 0;
    for (size_t i = 0; i < n; i++) {
        max_part = items[i].part > max_part ? items[i].part : max_part;
        key_bits |= items[i].key;
    }
    for (int pass = 0; pass < 8 + 2; pass++) {
        /* Passes 0-7: the 64-bit key 8 bits at a time; 8-9: the part (16 bits). */
        const int shift = pass < 8 ? 8 * pass : 8 * (pass - 8);
        /* A digit that is 0 in every item leaves the order as it is. */
        if (pass < 8 && ((key_bits >> shift) & 0xFF) == 0) continue;
        if (pass >= 8 && (max_part >> shift) == 0) break;
        size_t count[257] = {0};
        for (size_t i = 0; i < n; i++) {
            const uint64_t v = pass < 8 ? items[i].key : items[i].part;
            count[((v >> shift) & 0xFF) + 1]++;
        }
        for (int d = 0; d < 256; d++) count[d + 1] += count[d];
        for (size_t i = 0; i < n; i++) {
            const uint64_t v = pass < 8 ? items[i].key : items[i].part;
            tmp[count[(v >> shift) & 0xFF]++] = items[i];
        }
        sort_item_t *t = items; items = tmp; tmp = t;
    }
    for (size_t k = 0; k < n; k++) perm[k] = items[k].index;
    free(items);
    free(tmp);
    return perm;
}

/* The arrays a permutation moves: the non-NULL ones of a hit-point set. */
#define PERMUTE_ARRAYS 9
typedef struct {
    unsigned char *a[PERMUTE_ARRAYS];
    size_t sz[PERMUTE_ARRAYS], off[PERMUTE_ARRAYS], n, bytes;   /* bytes: one element of each */
} hp_arrays_t;

static void arrays_add(hp_arrays_t *s, void *a, size_t sz)
{
    if (!a) return;
    s->a[s->n] = a;
    s->sz[s->n] = sz;
    s->off[s->n] = s->bytes;
    s->bytes += sz;
    s->n++;
}

/* One element of size sz: the fixed sizes inline, the rest through memcpy's call. */
static inline void move_elem(unsigned char *dst, const unsigned char *src, size_t sz)
{
    switch (sz) {
    case 1: *dst = *src; break;
    case 4: memcpy(dst, src, 4); break;
    case 8: memcpy(dst, src, 8); break;
    case 24: memcpy(dst, src, 24); break;
    case 56: memcpy(dst, src, 56); break;
    default: memcpy(dst, src, sz);
    }
}

/* Element j of every array to (or from) buf, packed. */
static void save_all(const hp_arrays_t *s, unsigned char *buf, size_t j)
{
    for (size_t i = 0; i < s->n; i++) move_elem(buf + s->off[i], s->a[i] + j * s->sz[i], s->sz[i]);
}

static void load_all(const hp_arrays_t *s, size_t j, const unsigned char *buf)
{
    for (size_t i = 0; i < s->n; i++) move_elem(s->a[i] + j * s->sz[i], buf + s->off[i], s->sz[i]);
}

/* Permute every array in place, cycle by cycle and all arrays in one walk (each step touches
 * the permutation and the scratch bits once for all of them): gathered (new[k] = old[perm[k]])
 * or scattered (new[perm[k]] = old[k]). A copy of an array would add up to 128 bytes a hit
 * point to the render's peak. 0 or -1 (memory). */
static int permute_all(hitpoints_t *h, const uint32_t *perm, int scatter)
{
    hp_arrays_t s = {0};
    arrays_add(&s, h->hot, sizeof *h->hot);
    arrays_add(&s, h->weight, sizeof *h->weight);
    arrays_add(&s, h->flux, sizeof *h->flux);
    arrays_add(&s, h->r2, sizeof *h->r2);
    arrays_add(&s, h->pixel, sizeof *h->pixel);
    arrays_add(&s, h->dark, sizeof *h->dark);
    arrays_add(&s, h->fp32, sizeof *h->fp32);
    arrays_add(&s, h->stable, sizeof *h->stable);
    arrays_add(&s, h->r2_f32, sizeof *h->r2_f32);
    const size_t n = h->n;
    uint64_t *done = calloc((n + 63) / 64 + 1, sizeof *done);
    unsigned char *carry = malloc(2 * s.bytes + 1), *t = carry + s.bytes;
    if (!done || !carry) { free(done); free(carry); return -1; }
#define DONE(i) (done[(i) >> 6] >> ((i) & 63) & 1)
#define MARK(i) (done[(i) >> 6] |= (uint64_t)1 << ((i) & 63))
    for (size_t k = 0; k < n; k++) {
        if (DONE(k)) continue;
        MARK(k);
        if (perm[k] == k) continue;
        save_all(&s, carry, k);
        if (scatter) {   /* carry old[k] to its place perm[k], taking what stood there on */
            for (size_t j = perm[k]; j != k; j = perm[j]) {
                save_all(&s, t, j);
                load_all(&s, j, carry);
                memcpy(carry, t, s.bytes);
                MARK(j);
            }
            load_all(&s, k, carry);
        } else {   /* pull old[perm[j]] into j along the cycle */
            size_t j = k;
            for (size_t next = perm[j]; next != k; j = next, next = perm[j]) {
                for (size_t i = 0; i < s.n; i++) move_elem(s.a[i] + j * s.sz[i], s.a[i] + next * s.sz[i], s.sz[i]);
                MARK(next);
            }
            load_all(&s, j, carry);
        }
    }
#undef DONE
#undef MARK
    free(done);
    free(carry);
    return 0;
}

int hp_order_apply(hitpoints_t *h, const uint32_t *perm) { return permute_all(h, perm, 0); }

int hp_order_restore(hitpoints_t *h, const uint32_t *perm) { return permute_all(h, perm, 1); }
