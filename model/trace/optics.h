// SPDX-License-Identifier: Apache-2.0
/* optics.h: reflection and refraction as the reference program computes them, shared by
 * the eye pass and the photon pass. */
#ifndef PREE_OPTICS_H
#define PREE_OPTICS_H

#include "vec3.h"

/* Mirror direction d - n*2*(n.d). */
static inline vec3 optics_reflect(vec3 d, vec3 n)
{
    return v3_sub(d, v3_scale(v3_scale(n, 2.0), v3_dot(n, d)));
}

typedef struct {
    int total_internal;   /* 1: no refracted ray; follow the reflection */
    vec3 refracted;       /* unit refracted direction */
    double Re;            /* Fresnel reflectance (Schlick) */
} refraction_t;

/* Dielectric interface between the outside (index 1) and a medium of index ior: d incoming
 * direction, n outward normal, nl the normal facing d. */
static inline refraction_t optics_refract(vec3 d, vec3 n, vec3 nl, double ior)
{
    refraction_t r = {0, {0, 0, 0}, 0.0};
    const double nc = 1.0, nt = ior;
    int into = v3_dot(n, nl) > 0;
    double nnt = into ? nc / nt : nt / nc;
    double ddn = v3_dot(d, nl);
    double cos2t = 1 - nnt * nnt * (1 - ddn * ddn);
    if (cos2t < 0) { r.total_internal = 1; return r; }
    r.refracted = v3_norm(v3_sub(v3_scale(d, nnt), v3_scale(n, (into ? 1 : -1) * (ddn * nnt + sqrt(cos2t)))));
    double a = nt - nc, b = nt + nc;
    double R0 = a * a / (b * b);
    double c = 1 - (into ? -ddn : v3_dot(r.refracted, n));
    r.Re = R0 + (1 - R0) * c * c * c * c * c;
    return r;
}

#endif
