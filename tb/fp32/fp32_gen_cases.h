// SPDX-License-Identifier: Apache-2.0
/* fp32_gen_cases.h: what fp32_gen.c (the binary32 units' cases) and fp32_gen_wide.c (the stable
 * datapath's units' cases) share inside the test-case generator of fp32_gen.h: the case list
 * being built, the random draws and the binary32 operand helpers. Not for the benches. */
#ifndef PREE_TB_FP32_GEN_CASES_H
#define PREE_TB_FP32_GEN_CASES_H

#include <stddef.h>
#include <stdint.h>
#include "fp32_gen.h"

/* A directed list being built: cases are written to out when it is set, and counted in n. */
typedef struct { fp32_case_t *out; size_t n; fp32_unit_t unit; } list_t;

/* The special binary32 classes and some neighbours of interesting boundaries (fp32_gen.c). */
extern const uint32_t gen_specials[];
extern const size_t gen_n_specials;

uint32_t gen_rnd(uint64_t *rng, uint32_t n);            /* uniform in [0, n) */
int gen_range(uint64_t *rng, int lo, int hi);            /* uniform in [lo, hi] */
void gen_put(list_t *l, uint64_t a, uint32_t b, uint32_t sub);   /* append, expected result filled */
uint32_t gen_pack(uint32_t sign, uint32_t exp, uint32_t man);    /* binary32 from its fields */
uint32_t gen_mantissa(uint64_t *rng);                    /* a 23-bit significand field, varied */
uint32_t gen_operand(uint64_t *rng);                     /* any binary32, specials weighted */

/* fp32_gen_wide.c: the directed list of wacc or u2f (l->unit) and one random case. */
void gen_wide_directed(list_t *l, uint64_t *rng);
void gen_wide_random(fp32_unit_t unit, uint64_t *rng, fp32_case_t *c);

#endif
