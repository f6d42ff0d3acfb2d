// SPDX-License-Identifier: Apache-2.0
/* vec3.h: double 3-vectors with the exact operation order of the reference program.
 * dot is x*x' + y*y' + z*z' summed left to right; normalize multiplies each component by
 * 1/sqrt(x*x + y*y + z*z). The byte-exact reproduction depends on these orders. */
#ifndef PREE_VEC3_H
#define PREE_VEC3_H

#include <math.h>

typedef struct { double x, y, z; } vec3;

static inline vec3 v3(double x, double y, double z) { vec3 r = {x, y, z}; return r; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_scale(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline double v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline vec3 v3_norm(vec3 a) { return v3_scale(a, 1.0 / sqrt(a.x * a.x + a.y * a.y + a.z * a.z)); }
static inline double v3_max_comp(vec3 a)
{
    return (a.x > a.y && a.x > a.z) ? a.x : (a.y > a.z ? a.y : a.z);
}
static inline int v3_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

#endif
