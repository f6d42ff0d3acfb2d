// SPDX-License-Identifier: Apache-2.0
/* wide_acc.h: the stable datapath's wide accumulator format and its two operations.
 *
 * A wide word is 64 bits: e = bits 63..56, an 8-bit exponent biased as binary32's, and
 * M = bits 55..0, a 56-bit significand whose leading bit is stored (M[55] = 1 when e >= 1).
 *   e = 0:         value M * 2^-181 (M[55] = 0: zero or "subnormal", as binary32's e = 0)
 *   1 <= e <= 254: value M * 2^(e - 182)
 *   e = 255:       +infinity when M = 0, else NaN (the accumulator's NaN is WIDE_NAN)
 * Values are never negative. {0, e, M[54:32]} is binary32's layout, so wide_f32 (the value
 * truncated to binary32) is a bit slice: the low 32 significand bits are dropped, and
 * infinity/NaN map to binary32 infinity/NaN (the NaN keeps M[54], binary32's quiet bit).
 *
 * wide_add(A, t) adds a binary32 t to A, as rtl/pree_wacc.v does:
 *   - A NaN -> A; t NaN -> WIDE_NAN; A infinite -> A; t negative (not NaN) -> A unchanged
 *     (the datapath's terms are products of non-negative values; a negative one is dropped,
 *     a documented clamp, and the host never sends one); t = +inf -> WIDE_MAX;
 *   - else the operand with the smaller effective exponent (max(e, 1)) is shifted right by the
 *     difference (bits shifted out are dropped: truncation), the significands are added, a
 *     carry out of bit 55 shifts the sum right by one (truncating) and raises the exponent,
 *     and an exponent reaching 255 gives WIDE_MAX.
 * Saturation: an accumulator never overflows to infinity; it stops at WIDE_MAX, the largest
 * finite wide value, whose binary32 view is FLT_MAX (the host counts saturated hit points).
 * An infinite A can only come from the host.
 * Truncation loses at most 2^-55 of A per addition (2^-23 after 2^32 additions, always
 * downward); docs/numerics.md has the measured effect. */
#ifndef PREE_WIDE_ACC_H
#define PREE_WIDE_ACC_H

#include <math.h>
#include <stdint.h>

#define WIDE_M_BITS 56
#define WIDE_M_MASK ((UINT64_C(1) << WIDE_M_BITS) - 1)
#define WIDE_LEAD   (UINT64_C(1) << 55)
#define WIDE_INF    (UINT64_C(0xFF) << 56)
#define WIDE_NAN    (WIDE_INF | (UINT64_C(1) << 54))
#define WIDE_MAX    ((UINT64_C(0xFE) << 56) | WIDE_M_MASK)
#define WIDE_ZERO   UINT64_C(0)

static inline unsigned wide_exp(uint64_t a) { return (unsigned)(a >> 56); }
static inline uint64_t wide_sig(uint64_t a) { return a & WIDE_M_MASK; }
static inline int wide_is_nan(uint64_t a) { return wide_exp(a) == 255 && wide_sig(a) != 0; }

/* The value truncated to binary32 (bit slice; see above). */
static inline uint32_t wide_f32(uint64_t a)
{
    return ((uint32_t)wide_exp(a) << 23) | (uint32_t)((a >> 32) & 0x7FFFFFu);
}

static inline uint64_t wide_add(uint64_t a, uint32_t t)
{
    const unsigned ea = wide_exp(a), et = (t >> 23) & 0xFFu;
    const uint32_t ft = t & 0x7FFFFFu;
    if (ea == 255 && wide_sig(a)) return a;       /* A NaN */
    if (et == 255 && ft) return WIDE_NAN;         /* t NaN */
    if (ea == 255) return a;                      /* A infinite */
    if (t >> 31) return a;                        /* t negative: dropped */
    if (et == 255) return WIDE_MAX;               /* t = +inf: saturate */
    const uint64_t mt = (uint64_t)((et ? 0x800000u : 0u) | ft) << 32;
    const unsigned xa = ea ? ea : 1, xt = et ? et : 1;
    uint64_t big = wide_sig(a), small = mt;
    unsigned e = xa, sh = xa - xt;
    if (xt > xa) { big = mt; small = wide_sig(a); e = xt; sh = xt - xa; }
    uint64_t s = big + (sh >= WIDE_M_BITS ? 0 : small >> sh);
    if (s >> WIDE_M_BITS) { s >>= 1; e++; }
    if (e >= 255) return WIDE_MAX;                /* overflow: saturate */
    return ((uint64_t)((s & WIDE_LEAD) ? e : 0) << 56) | s;
}

/* Host side: a non-negative double, exactly (53 significant bits fit in 56) when it is in
 * range; below the wide range it truncates, above it gives WIDE_INF; NaN or negative gives
 * WIDE_NAN (the host checks its values before they get here). */
static inline uint64_t wide_from_double(double x)
{
    if (!(x >= 0)) return WIDE_NAN;
    if (x == 0) return WIDE_ZERO;
    if (isinf(x)) return WIDE_INF;
    int ex;
    double fr = frexp(x, &ex);                   /* x = fr * 2^ex, 0.5 <= fr < 1 */
    int e = ex + 126;                            /* value = (fr * 2^56) * 2^(e - 182) */
    if (e >= 255) return WIDE_INF;
    if (e >= 1) return ((uint64_t)e << 56) | (uint64_t)ldexp(fr, 56);
    if (e < -56) return WIDE_ZERO;
    return (uint64_t)ldexp(fr, 56 + e - 1);      /* e field 0: value M * 2^-181 */
}

/* Host side: the value as the nearest double (56 -> 53 bits, round to nearest even). */
static inline double wide_to_double(uint64_t a)
{
    const unsigned e = wide_exp(a);
    if (e == 255) return wide_sig(a) ? NAN : INFINITY;
    return ldexp((double)wide_sig(a), (e ? (int)e : 1) - 182);
}

/* An unsigned 64-bit count rounded once to binary32 (round to nearest even), as
 * rtl/pree_u64_to_f32.v does: exact up to 2^24. */
static inline uint32_t u64_to_f32(uint64_t k)
{
    if (!k) return 0;
    const int lz = __builtin_clzll(k);
    const int msb = 63 - lz;                     /* value in [2^msb, 2^(msb+1)) */
    uint32_t sig, exp = (uint32_t)(msb + 127);
    if (msb <= 23) {
        sig = (uint32_t)(k << (23 - msb));
    } else {
        const int sh = msb - 23;
        sig = (uint32_t)(k >> sh);
        const uint64_t rem = k & ((UINT64_C(1) << sh) - 1), half = UINT64_C(1) << (sh - 1);
        if (rem > half || (rem == half && (sig & 1))) sig++;
        if (sig >> 24) { sig >>= 1; exp++; }
    }
    return (exp << 23) | (sig & 0x7FFFFFu);
}

#endif
