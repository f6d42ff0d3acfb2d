// SPDX-License-Identifier: Apache-2.0
/* fp32_gen.h: test cases for the binary32 RTL units (directed lists and random operands).
 *
 * Shared by the Verilator benches (fp32_bench.cpp) and the Icarus vector writer
 * (fp32_vecgen.c), so both simulators see the same kinds of case. Expected results come from
 * model/pree/fp32_ops.h (host IEEE arithmetic plus the explicit x86-64 SSE NaN rule) and, for the
 * stable datapath's two units, model/pree/wide_acc.h:
 *   wacc  pree_wacc:        a = wide accumulator word (64 bits), b = binary32 term t,
 *                           y = wide_add(a, t) (64 bits)
 *   u2f   pree_u64_to_f32:  a = unsigned 64-bit integer, y = u64_to_f32(a) (binary32)
 * a and y are 64-bit fields; for the binary32 units only their low 32 bits are used.
 *
 * API:
 *   fp32_unit_parse(name, &unit)   "add" "mul" "sqr" "div" "cmp" "wacc" "u2f" -> 0; else -1,
 *                                  unit unchanged.
 *   fp32_unit_name(unit)           the short name.
 *   fp32_expect(unit, a, b, sub)   the reference result; for cmp the flags
 *                                  {unordered, eq, le, lt} in bits 3..0.
 *   fp32_directed_count(unit)      number of directed cases.
 *   fp32_directed(unit, i, &c)     directed case i (0 <= i < count), expected result filled in.
 *   fp32_random(unit, &rng, &c)    one random case, expected result filled in.
 *   fp32_sweep_count(unit)         cases of the exhaustive significand sweep: the squarer only
 *                                  (6 exponents x 2^23 significands), 0 for the other units.
 *   fp32_sweep(unit, i, &c)        sweep case i (0 <= i < count), expected result filled in.
 * Random cases come from a seeded xorshift generator, so a run is reproducible from its seed.
 */
#ifndef PREE_TB_FP32_GEN_H
#define PREE_TB_FP32_GEN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { FP32_ADD, FP32_MUL, FP32_SQR, FP32_DIV, FP32_CMP, FP32_WACC, FP32_U2F } fp32_unit_t;
#define FP32_N_UNITS 7

typedef struct {
    uint64_t a;      /* first operand (64 bits for wacc and u2f, else binary32) */
    uint32_t b;      /* second operand (ignored by sqr and u2f and written as 0) */
    uint32_t sub;    /* add only: 1 for a - b */
    uint64_t y;      /* expected result bits (64 bits for wacc), or cmp flags */
} fp32_case_t;

int         fp32_unit_parse(const char *name, fp32_unit_t *unit);
const char *fp32_unit_name(fp32_unit_t unit);
uint64_t    fp32_expect(fp32_unit_t unit, uint64_t a, uint32_t b, uint32_t sub);
size_t      fp32_directed_count(fp32_unit_t unit);
void        fp32_directed(fp32_unit_t unit, size_t i, fp32_case_t *c);
void        fp32_random(fp32_unit_t unit, uint64_t *rng, fp32_case_t *c);
size_t      fp32_sweep_count(fp32_unit_t unit);
void        fp32_sweep(fp32_unit_t unit, size_t i, fp32_case_t *c);
uint64_t    fp32_rng_next(uint64_t *rng);

#ifdef __cplusplus
}
#endif

#endif
