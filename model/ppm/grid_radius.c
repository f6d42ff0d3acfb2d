// SPDX-License-Identifier: Apache-2.0
/* grid_radius.c: the radii the grids are built for: smallppm's initial radius from the hit points'
 * bounding box, and the safe radius that covers every binary32 rounding of the distance test. */
#include <math.h>
#include "grid.h"

double grid_initial_radius(const hitpoints_t *h, int width, int height)
{
    vec3 lo = v3(1e20, 1e20, 1e20), hi = v3(-1e20, -1e20, -1e20);
    for (size_t i = 0; i < h->n; i++) {
        const hp_hot_t *p = &h->hot[i];
        lo = v3(fmin(p->px, lo.x), fmin(p->py, lo.y), fmin(p->pz, lo.z));
        hi = v3(fmax(p->px, hi.x), fmax(p->py, hi.y), fmax(p->pz, hi.z));
    }
    vec3 size = v3_sub(hi, lo);
    return ((size.x + size.y + size.z) / 3.0) / ((width + height) / 2.0) * 2.0;
}

double grid_safe_radius(double r0, double max_abs_coord)
{
    /* Binary32 rounding moves each coordinate of a hit point and a photon by at most
     * |coord| * 2^-24, so their distance by at most 2*sqrt(3)*2^-24*|coord| < 2.1e-7*|coord|;
     * the distance arithmetic adds a few ulps (relative 1e-6). Both margins are taken
     * five-fold. */
    return r0 * (1.0 + 5e-6) + 1e-6 * max_abs_coord;
}
