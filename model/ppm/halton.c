// SPDX-License-Identifier: Apache-2.0
/* halton.c: reverse-permuted radical inverse over the first 61 primes. */
#include <stdint.h>
#include "halton.h"

static const int halton_primes[HALTON_DIMENSIONS] = {
    2,   3,   5,   7,   11,  13,  17,  19,  23,  29,  31,  37,  41,  43,  47,  53,
    59,  61,  67,  71,  73,  79,  83,  89,  97,  101, 103, 107, 109, 113, 127, 131,
    137, 139, 149, 151, 157, 163, 167, 173, 179, 181, 191, 193, 197, 199, 211, 223,
    227, 229, 233, 239, 241, 251, 257, 263, 269, 271, 277, 281, 283};

/* k / p for k < 2^32 as the high half of k * (floor(2^64 / p) + 1): the product exceeds
 * 2^64 k / p by less than k / 2^64 < 2^-32, and the fractional part of k / p is at most
 * 1 - 1/p with p < 2^9, so the floor is exact. */
static inline uint32_t div_prime(uint32_t k, uint64_t magic)
{
    return (uint32_t)(((unsigned __int128)k * magic) >> 64);
}

/* Per dimension: 1 / p (the same rounded double the loop multiplies by) and the magic
 * multiplier floor(2^64 / p) + 1, made once instead of a division each on every call. */
typedef struct { double inv; uint64_t magic; } halton_dim_t;

static halton_dim_t dims[HALTON_DIMENSIONS];

__attribute__((constructor)) static void halton_dims_init(void)
{
    for (int b = 0; b < HALTON_DIMENSIONS; b++) {
        dims[b].inv = 1.0 / (double)halton_primes[b];
        dims[b].magic = UINT64_MAX / (uint64_t)halton_primes[b] + 1;
    }
}

double halton(int b, long long j)
{
    const int p = halton_primes[b];
    const double f = dims[b].inv;
    double h = 0.0, fct = f;
    if (p == 2 && j >= 0 && j <= 0xFFFFFFFFll) {
        /* Base 2: digit 1 stays 1, fct is an exact power of two and every partial sum has at
         * most 32 significant bits, so the loop's result is exactly the bit-reversed index
         * over 2^32. */
        uint32_t k = (uint32_t)j;
        k = (k >> 16) | (k << 16);
        k = ((k & 0xFF00FF00u) >> 8) | ((k & 0x00FF00FFu) << 8);
        k = ((k & 0xF0F0F0F0u) >> 4) | ((k & 0x0F0F0F0Fu) << 4);
        k = ((k & 0xCCCCCCCCu) >> 2) | ((k & 0x33333333u) << 2);
        k = ((k & 0xAAAAAAAAu) >> 1) | ((k & 0x55555555u) << 1);
        return (double)k * 0x1p-32;
    }
    if (j >= 0 && j <= 0xFFFFFFFFll) {
        /* The same digits without a division instruction. */
        const uint32_t up = (uint32_t)p;
        const uint64_t magic = dims[b].magic;
        uint32_t k = (uint32_t)j;
        while (k > 0) {
            uint32_t q = div_prime(k, magic), digit = k - q * up;
            h += (double)(digit == 0 ? 0 : up - digit) * fct;
            k = q;
            fct *= f;
        }
        return h;
    }
    while (j > 0) {
        /* Reverse permutation: digit d maps to p - d, and 0 stays 0. */
        int digit = (int)(j % p);
        h += (double)(digit == 0 ? 0 : p - digit) * fct;
        j /= p;
        fct *= f;
    }
    return h;
}
