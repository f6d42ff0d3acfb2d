// SPDX-License-Identifier: Apache-2.0
/* fp32_ops.h: IEEE-754 binary32 arithmetic with the NaN rules of x86-64 SSE, made explicit.
 *
 * The golden reference for the RTL floating-point units and for the PREU datapath model.
 * Every non-NaN result is the host's own binary32 arithmetic (round to nearest even,
 * subnormals in full; the project is compiled with -ffp-contract=off and no fast-math).
 * NaN results follow the SSE rule, applied here so that operand order chosen by the
 * compiler cannot change them:
 *   a is NaN -> a, quieted;  else b is NaN -> b, quieted (for a - b: b's sign unchanged);
 *   else an invalid operation (inf - inf, 0 * inf, 0 / 0, inf / inf) -> 0xFFC00000.
 * Values travel as uint32_t bit patterns so that no conversion can touch a payload.
 */
#ifndef PREE_FP32_OPS_H
#define PREE_FP32_OPS_H

#include <stdint.h>
#include <string.h>

#define FP32_DEFAULT_NAN 0xFFC00000u
#define FP32_QUIET_BIT   0x00400000u

static inline float fp32_from_bits(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }
static inline uint32_t fp32_to_bits(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }
static inline int fp32_is_nan(uint32_t u) { return (u & 0x7FFFFFFFu) > 0x7F800000u; }

/* The NaN an operation returns when an input is NaN (a first), or 0 when neither is. */
static inline uint32_t fp32_nan_propagate(uint32_t a, uint32_t b)
{
    if (fp32_is_nan(a)) return a | FP32_QUIET_BIT;
    if (fp32_is_nan(b)) return b | FP32_QUIET_BIT;
    return 0;
}

/* Result bits of a host operation; an invalid operation's NaN becomes the default NaN. */
static inline uint32_t fp32_result(float r)
{
    uint32_t u = fp32_to_bits(r);
    return fp32_is_nan(u) ? FP32_DEFAULT_NAN : u;
}

static inline uint32_t fp32_add(uint32_t a, uint32_t b)
{
    uint32_t n = fp32_nan_propagate(a, b);
    return n ? n : fp32_result(fp32_from_bits(a) + fp32_from_bits(b));
}

static inline uint32_t fp32_sub(uint32_t a, uint32_t b)
{
    uint32_t n = fp32_nan_propagate(a, b);
    return n ? n : fp32_result(fp32_from_bits(a) - fp32_from_bits(b));
}

static inline uint32_t fp32_mul(uint32_t a, uint32_t b)
{
    uint32_t n = fp32_nan_propagate(a, b);
    return n ? n : fp32_result(fp32_from_bits(a) * fp32_from_bits(b));
}

static inline uint32_t fp32_sqr(uint32_t a) { return fp32_mul(a, a); }

static inline uint32_t fp32_div(uint32_t a, uint32_t b)
{
    uint32_t n = fp32_nan_propagate(a, b);
    return n ? n : fp32_result(fp32_from_bits(a) / fp32_from_bits(b));
}

/* Comparator flags, as pree_fp32_cmp: all false except unordered when either is NaN. */
typedef struct { int lt, le, eq, unordered; } fp32_cmp_t;

static inline fp32_cmp_t fp32_cmp(uint32_t a, uint32_t b)
{
    fp32_cmp_t c = {0, 0, 0, 0};
    if (fp32_is_nan(a) || fp32_is_nan(b)) { c.unordered = 1; return c; }
    float x = fp32_from_bits(a), y = fp32_from_bits(b);
    c.lt = x < y; c.le = x <= y; c.eq = x == y;
    return c;
}

#endif
