// SPDX-License-Identifier: Apache-2.0
/* preu_stable_fixtures.h: the stable-datapath unit tests' fixtures (test_preu_stable.c,
 * test_preu_stable_special.c): binary32 words of floats and back, a fresh hit point, a photon. */
#ifndef PREU_STABLE_FIXTURES_H
#define PREU_STABLE_FIXTURES_H

#include "preu_stable.h"

static inline uint32_t B(float f) { return fp32_to_bits(f); }
static inline float F(uint32_t b) { return fp32_from_bits(b); }

/* A fresh stable hit point at (10, 20, 30), weight (0.5, 0.25, 1), for radius squared r2. */
static inline preu_shp_t fresh(double r2)
{
    preu_shp_t hp = {{B(10.0f), B(20.0f), B(30.0f)}, {B(0.5f), B(0.25f), B(1.0f)}, {0, 0, 0}, 0, 0};
    preu_stable_init(&hp, r2);
    return hp;
}

static inline preu_photon_t photon_at(float x, float y, float z, float phi)
{
    preu_photon_t ph = {{B(x), B(y), B(z)}, {B(phi), B(phi), B(phi)}};
    return ph;
}

#endif
