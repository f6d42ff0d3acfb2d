/* fp32_gen.h: test cases for the binary32 RTL units (directed lists and random operands).
 *
 * Shared by the Verilator benches (fp32_bench.cpp) and the Icarus vector writer
 * (fp32_vecgen.c), so both simulators see the same kinds of case. Expected results come from
 * model/fp32_ops.h (host IEEE arithmetic plus the explicit x86-64 SSE NaN rule).
 *
 * API:
 *   fp32_unit_parse(name, &unit)   "add" "mul" "sqr" "div" "cmp" -> 0; else -1, unit unchanged.
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

typedef enum { FP32_ADD, FP32_MUL, FP32_SQR, FP32_DIV, FP32_CMP } fp32_unit_t;

typedef struct {
    uint32_t a, b;   /* operands (b is ignored by sqr and written as 0) */
    uint32_t sub;    /* add only: 1 for a - b */
    uint32_t y;      /* expected result bits, or cmp flags */
} fp32_case_t;

int         fp32_unit_parse(const char *name, fp32_unit_t *unit);
const char *fp32_unit_name(fp32_unit_t unit);
uint32_t    fp32_expect(fp32_unit_t unit, uint32_t a, uint32_t b, uint32_t sub);
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
