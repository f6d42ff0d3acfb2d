/* preu_vec.h: operation sequences for the PREU benches, with expected results from the C model.
 *
 * API
 *   preu_vec_t            one operation: mode, idle cycles before it, inputs, expected outputs
 *   preu_seq_gen(...)     fill n operations: directed cases first, then random phases of update
 *                         and radiance operations (realistic magnitudes and special values),
 *                         back-to-back and with gaps; expected results from model/preu_fp32.c
 *   preu_vec_words(...)   the 32-word layout of one operation in the Icarus vector file
 * The same seed always gives the same sequence. */
#ifndef PREE_TB_PREU_VEC_H
#define PREE_TB_PREU_VEC_H

#include <stdint.h>
#include "preu_fp32.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PREU_VEC_WORDS 32

typedef struct {
    int mode;             /* 0 update, 1 radiance */
    int gap;              /* idle cycles before this operation is offered */
    preu_hp_t hp;
    preu_photon_t ph;
    uint32_t ne;          /* radiance: NE, constant over a radiance phase */
    uint32_t l[3];        /* radiance: the pixel sum driven on l_i */
    /* expected (update: every datapath output whether accepted or not) */
    int accept;
    uint32_t tau[3], r2, n;
    uint32_t lo[3];
} preu_vec_t;

void preu_seq_gen(preu_vec_t *v, int n, uint64_t seed);
void preu_vec_words(uint32_t w[PREU_VEC_WORDS], const preu_vec_t *v);

#ifdef __cplusplus
}
#endif

#endif
