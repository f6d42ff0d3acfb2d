// SPDX-License-Identifier: Apache-2.0
/* preu_vec.h: operation sequences for the PREU benches, with expected results from the C model,
 * for either datapath (0 paper: model/pree/preu_fp32.c; 1 stable: model/pree/preu_stable.c).
 *
 * API
 *   preu_vec_t            one operation: mode, idle cycles before it, inputs, expected outputs;
 *                         the hit-point state as the RTL's hp_state_i words (low word first)
 *   preu_seq_gen(...)     fill n operations: directed cases first, then random phases of update
 *                         and radiance operations (realistic magnitudes and special values, a
 *                         random alpha per update phase), back-to-back and with gaps
 *   preu_vec_expect(v, dp)   (re)compute v's expected outputs from its inputs
 *   preu_vec_words(...)   the PREU_VEC_WORDS layout of one operation in the Icarus vector file
 * The same seed always gives the same sequence. */
#ifndef PREE_TB_PREU_VEC_H
#define PREE_TB_PREU_VEC_H

#include <stdint.h>
#include "preu_fp32.h"
#include "preu_stable.h"
#include "preu_state.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PREU_VEC_WORDS 44

typedef struct {
    int mode;             /* 0 update, 1 radiance */
    int gap;              /* idle cycles before this operation is offered */
    preu_hpw_t hp;                   /* hit point: position, weight, state (hp_state_i words) */
    preu_photon_t ph;
    uint32_t alpha, kappa;           /* update: run-time constants, constant over a phase */
    uint32_t ne;          /* radiance: NE, constant over a radiance phase */
    uint32_t l[3];        /* radiance: the pixel sum driven on l_i */
    /* expected (update: every datapath output whether accepted or not) */
    int accept;
    uint32_t sto[PREU_STATE_MAX];    /* state_o words */
    uint32_t lo[3];
} preu_vec_t;

void preu_seq_gen(preu_vec_t *v, int n, uint64_t seed, int datapath);
void preu_vec_expect(preu_vec_t *v, int datapath);
void preu_vec_words(uint32_t w[PREU_VEC_WORDS], const preu_vec_t *v);

#ifdef __cplusplus
}
#endif

#endif
