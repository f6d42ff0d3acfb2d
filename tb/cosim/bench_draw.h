// SPDX-License-Identifier: Apache-2.0
/* bench_draw.h: the random draws of pree_top's benches (tb/cosim/top_bench.c and top_vecgen.c):
 * one 64-bit linear congruential stream (its high 31 bits a draw), uniform binary32 values, and
 * a photon's candidate hit points by scenario. Header-only, for the bench programs. */
#ifndef BENCH_DRAW_H
#define BENCH_DRAW_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "fp32_ops.h"

typedef enum { DRAW_RANDOM, DRAW_ONE, DRAW_DENSE, DRAW_MIXED } draw_scenario_t;

/* The most candidates a photon draws: 60 (dense) and hit point 0 (mixed). */
#define DRAW_MAX_CAND 61

static inline uint32_t draw_u32(uint64_t *st)
{
    *st = *st * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(*st >> 33);
}

/* Uniform in [lo, hi), 24 random bits; as binary32 bits. */
static inline uint32_t draw_f32_bits(uint64_t *st, float lo, float hi)
{
    return fp32_to_bits(lo + (hi - lo) * (float)(draw_u32(st) & 0xffffff) / 16777216.0f);
}

/* Photon p's candidates into cand (distinct, below nhp; returns how many):
 *   one    hit point 0 only;
 *   random 1 .. 40 anywhere;
 *   dense  1 .. 60 from a window of 80 hit points at a random base (few pixels, dense hit points);
 *   mixed  random, and every fourth photon also on hit point 0. */
static inline size_t draw_candidates(uint64_t *st, draw_scenario_t sc, int p, uint32_t nhp, uint32_t *cand)
{
    size_t n = 0;
    if (sc == DRAW_ONE) {
        cand[n++] = 0;
        return n;
    }
    const int dense = sc == DRAW_DENSE;
    size_t want = dense ? 1 + draw_u32(st) % 60 : 1 + draw_u32(st) % 40;
    uint32_t base = dense ? draw_u32(st) % nhp : 0;
    while (n < want && n < (size_t)nhp) {
        uint32_t h = dense ? (base + draw_u32(st) % 80) % nhp : draw_u32(st) % nhp;
        int dup = 0;
        for (size_t k = 0; k < n; k++) dup |= cand[k] == h;
        if (!dup) cand[n++] = h;
    }
    if (sc == DRAW_MIXED && p % 4 == 0) {
        int has0 = 0;
        for (size_t k = 0; k < n; k++) has0 |= cand[k] == 0;
        if (!has0) cand[n++] = 0;
    }
    return n;
}

/* The scenario named s (random, one, dense, mixed); -1 for another name. */
static inline int draw_scenario(const char *s, draw_scenario_t *sc)
{
    static const char *const names[] = {"random", "one", "dense", "mixed"};
    for (int k = 0; k < 4; k++)
        if (!strcmp(s, names[k])) { *sc = (draw_scenario_t)k; return 0; }
    return -1;
}

#endif
