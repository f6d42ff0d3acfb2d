// SPDX-License-Identifier: Apache-2.0
/* preu_state.h: a hit point as the PREE's hit-point memory holds it, for either datapath.
 *
 * The memory's words (rtl/pree_top.v, host port hp_wdata_i) are {pixel, f, pos, state}; the
 * state part's layout is the datapath's (rtl/pree_preu.v hp_state_i, low word first):
 *   paper  (5 words):  tau r, g, b, r2, n                            (model/pree/preu_fp32.h)
 *   stable (10 words): T r, g, b, w, k as 64-bit words, low half first (model/pree/preu_stable.h)
 * The co-simulation host and the PREU benches move hit points in this form.
 *
 * API
 *   preu_hpw_t                      position, weight and state words of one hit point
 *   preu_state_words(datapath)      5 or 10
 *   preu_hpw_from_paper / _to_paper, preu_hpw_from_stable / _to_stable   conversions
 *   preu_hpw_screen_r2(w, datapath)  the radius bound the engine screens with */
#ifndef PREE_PREU_STATE_H
#define PREE_PREU_STATE_H

#include <stdint.h>
#include <string.h>
#include "preu_fp32.h"
#include "preu_stable.h"

#define PREU_STATE_MAX 10

typedef struct {
    uint32_t pos[3], f[3];
    uint32_t st[PREU_STATE_MAX];
} preu_hpw_t;

static inline int preu_state_words(int datapath) { return datapath ? 10 : 5; }

static inline void preu_hpw_from_paper(preu_hpw_t *w, const preu_hp_t *hp)
{
    memset(w, 0, sizeof *w);
    memcpy(w->pos, hp->pos, sizeof w->pos);
    memcpy(w->f, hp->f, sizeof w->f);
    memcpy(w->st, hp->tau, sizeof hp->tau);
    w->st[3] = hp->r2;
    w->st[4] = hp->n;
}

static inline void preu_hpw_to_paper(const preu_hpw_t *w, preu_hp_t *hp)
{
    memcpy(hp->pos, w->pos, sizeof hp->pos);
    memcpy(hp->f, w->f, sizeof hp->f);
    memcpy(hp->tau, w->st, sizeof hp->tau);
    hp->r2 = w->st[3];
    hp->n = w->st[4];
}

static inline uint64_t preu_hpw_word64(const uint32_t *st, int i)
{
    return (uint64_t)st[2 * i + 1] << 32 | st[2 * i];
}

static inline void preu_hpw_put64(uint32_t *st, int i, uint64_t x)
{
    st[2 * i] = (uint32_t)x;
    st[2 * i + 1] = (uint32_t)(x >> 32);
}

static inline void preu_hpw_from_stable(preu_hpw_t *w, const preu_shp_t *hp)
{
    memcpy(w->pos, hp->pos, sizeof w->pos);
    memcpy(w->f, hp->f, sizeof w->f);
    for (int c = 0; c < 3; c++) preu_hpw_put64(w->st, c, hp->T[c]);
    preu_hpw_put64(w->st, 3, hp->w);
    preu_hpw_put64(w->st, 4, hp->k);
}

static inline void preu_hpw_to_stable(const preu_hpw_t *w, preu_shp_t *hp)
{
    memcpy(hp->pos, w->pos, sizeof hp->pos);
    memcpy(hp->f, w->f, sizeof hp->f);
    for (int c = 0; c < 3; c++) hp->T[c] = preu_hpw_word64(w->st, c);
    hp->w = preu_hpw_word64(w->st, 3);
    hp->k = preu_hpw_word64(w->st, 4);
}

/* The binary32 radius squared that the engine screens candidates with (hitpoints_t.r2_f32), from
 * a hit point's words: the paper's r2 word, or the stable datapath's bound from its w. */
static inline uint32_t preu_hpw_screen_r2(const preu_hpw_t *w, int datapath)
{
    return datapath ? preu_stable_screen_r2(preu_hpw_word64(w->st, 3)) : w->st[3];
}

#endif
