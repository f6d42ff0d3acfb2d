// SPDX-License-Identifier: Apache-2.0
/* hp_order.c: a spatial order of the hit points for the photon pass.
 *
 * The eye pass stores hit points in pixel order, so a photon's candidates (spatial neighbours)
 * lie scattered over the state arrays and every radius read and accepted update is a cache
 * miss. During the photon pass the hit points are held in the order of the owning part
 * (grid_owner), then the Morton code of their position, then their index; afterwards they
 * return to pixel order. Each hit point's own sequence of updates is the same in any order,
 * so results are unchanged to the bit. */
#include <math.h>
#include <omp.h>
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

/* Bytes of an element a permutation pass moves at most: an element is moved in slices of up to
 * this many bytes, each slice of every element through a scratch array of n slices. */
#define PERMUTE_SLICE 24

/* Move bytes [off, off + len) of every element of array a (elements of sz bytes) to its place:
 * gathered (new[k] = old[perm[k]]) or scattered (new[perm[k]] = old[k]), through scratch (n *
 * len bytes). Each pass is n independent random reads or writes, which the processor overlaps
 * and the threads share. */
static void permute_slice(unsigned char *a, size_t sz, size_t off, size_t len, size_t n, const uint32_t *perm,
                          int scatter, unsigned char *scratch)
{
    if (scatter) {
#pragma omp parallel for schedule(static)
        for (size_t k = 0; k < n; k++) memcpy(scratch + (size_t)perm[k] * len, a + k * sz + off, len);
    } else {
#pragma omp parallel for schedule(static)
        for (size_t k = 0; k < n; k++) memcpy(scratch + k * len, a + (size_t)perm[k] * sz + off, len);
    }
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < n; k++) memcpy(a + k * sz + off, scratch + k * len, len);
}

/* Permute every array of the hit points, slice by slice (PERMUTE_SLICE bytes): gathered
 * (new[k] = old[perm[k]]) or scattered (new[perm[k]] = old[k]). The scratch adds 24 bytes a
 * hit point to the memory of the moment, where a copy of each array would add up to 64 (and
 * an in-place walk along the permutation's cycles, one dependent cache miss after another, took
 * three times as long). 0 or -1 (memory). */
static int permute_all(hitpoints_t *h, const uint32_t *perm, int scatter)
{
    struct { void *a; size_t sz; } arr[] = {
        {h->hot, sizeof *h->hot}, {h->weight, sizeof *h->weight}, {h->acc, sizeof *h->acc},
        {h->object, sizeof *h->object},
        {h->r2, sizeof *h->r2}, {h->pixel, sizeof *h->pixel}, {h->dark, sizeof *h->dark},
        {h->fp32, sizeof *h->fp32}, {h->stable, sizeof *h->stable}, {h->r2_f32, sizeof *h->r2_f32},
    };
    const size_t n = h->n;
    if (!n) return 0;
    unsigned char *scratch = malloc(n * PERMUTE_SLICE);
    if (!scratch) return -1;
    for (size_t i = 0; i < sizeof arr / sizeof *arr; i++) {
        if (!arr[i].a) continue;
        for (size_t off = 0; off < arr[i].sz; off += PERMUTE_SLICE) {
            const size_t len = arr[i].sz - off < PERMUTE_SLICE ? arr[i].sz - off : PERMUTE_SLICE;
            permute_slice(arr[i].a, arr[i].sz, off, len, n, perm, scatter, scratch);
        }
    }
    free(scratch);
    return 0;
}

int hp_order_apply(hitpoints_t *h, const uint32_t *perm) { return permute_all(h, perm, 0); }

int hp_order_restore(hitpoints_t *h, const uint32_t *perm) { return permute_all(h, perm, 1); }
