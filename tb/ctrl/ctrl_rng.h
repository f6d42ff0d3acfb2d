// SPDX-License-Identifier: Apache-2.0
/* ctrl_rng.h: small deterministic random source (splitmix64) for the controller benches. */
#ifndef CTRL_RNG_H
#define CTRL_RNG_H

#include <math.h>
#include <stdint.h>

static inline uint64_t ctrl_rng_next(uint64_t *s)
{
  uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/* Uniform in [0, n), n > 0. */
static inline uint32_t ctrl_rng_below(uint64_t *s, uint32_t n)
{
  return (uint32_t)(ctrl_rng_next(s) % n);
}

/* Uniform double in [0, 1). */
static inline double ctrl_rng_unit(uint64_t *s)
{
  return (double)(ctrl_rng_next(s) >> 11) * (1.0 / 9007199254740992.0);
}

/* Geometric on {0, 1, 2, ...} with the given mean (mean > 0). */
static inline uint32_t ctrl_rng_geometric(uint64_t *s, double mean)
{
  double p = 1.0 / (mean + 1.0);
  double u = ctrl_rng_unit(s);
  double k = floor(log1p(-u) / log1p(-p));
  return k > 4e9 ? 4000000000u : (uint32_t)k;
}

#endif
