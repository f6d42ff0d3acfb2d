// SPDX-License-Identifier: Apache-2.0
/* stress_refs.c: the stress program's references (tests/stress/stress_hitpoint.h): the relative
 * error, the closed form of the radius product, the flux sequence's splitmix64. */
#include <math.h>
#include <stdio.h>

#include "stress_hitpoint.h"

double relerr(long double x, long double ref)
{
    if (x == ref) return 0;
    if (isnan(x) || isnan(ref)) return NAN;
    if (ref == 0 || isinf(ref)) return x > ref ? INFINITY : -INFINITY;
    return (double)((x - ref) / ref);
}

uint64_t splitmix64(uint64_t *s)
{
    uint64_t z = (*s += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* ---- The closed form of the radius product ----------------------------------------------
 * smallppm's g_j = (j a + a) / (j a + 1) = (j + 1) / (j + c), c = 1 / a, so after k accepts
 *   r2_k / r2_0 = R(k) = prod_{j<k} (j + 1) / (j + c) = Gamma(k + 1) Gamma(c) / Gamma(k + c).
 * ln R(k) = lgamma(c) + D(k), D(k) = lnGamma(k + 1) - lnGamma(k + c). For k < 64 the product
 * itself in long double; above, D from Stirling's series written so that nothing large cancels:
 * with x = k + 1, y = k + c, delta = 1 - c,
 *   D = delta ln y + (x - 1/2) log1p(delta / y) - delta + S(x) - S(y),
 *   S(z) = 1/(12 z) - 1/(360 z^3) + 1/(1260 z^5) - 1/(1680 z^7) + 1/(1188 z^9)
 * (truncation below 1e-19 for z >= 64). */
static long double stirling_s(long double z)
{
    long double iz = 1.0L / z, iz2 = iz * iz;
    return iz * (1.0L / 12 - iz2 * (1.0L / 360 - iz2 * (1.0L / 1260 - iz2 * (1.0L / 1680 - iz2 / 1188))));
}

long double closed_lnR(uint64_t k, long double c)
{
    if (k < CLOSED_K0) {
        long double p = 1.0L;
        for (uint64_t j = 0; j < k; j++) p *= ((long double)j + 1.0L) / ((long double)j + c);
        return logl(p);
    }
    const long double delta = 1.0L - c;
    const long double x = (long double)k + 1.0L, y = (long double)k + c;
    return lgammal(c) + delta * logl(y) + (x - 0.5L) * log1pl(delta / y) - delta + stirling_s(x) - stirling_s(y);
}

void fmt_err(char *b, size_t n, double e)
{
    if (e == 0) snprintf(b, n, "0");
    else if (isnan(e)) snprintf(b, n, "nan");
    else snprintf(b, n, "%+.2e", e);
}

