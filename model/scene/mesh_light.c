// SPDX-License-Identifier: Apache-2.0
/* mesh_light.c: area lights from emitting triangles: construction and photon sampling. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mesh_light.h"

int mesh_light_add(scene_t *s, const vec3 *c, size_t n, vec3 power, int is_flux, char *err, size_t errlen)
{
    light_tri_t *tris = malloc((n ? n : 1) * sizeof *tris);
    if (!tris) { snprintf(err, errlen, "out of memory for an area light"); return -1; }
    size_t k = 0;
    double area = 0;
    for (size_t i = 0; i < n; i++) {
        vec3 e1 = v3_sub(c[3 * i + 1], c[3 * i]), e2 = v3_sub(c[3 * i + 2], c[3 * i]);
        vec3 x = v3_cross(e1, e2);
        double a2 = sqrt(v3_dot(x, x));
        if (!(a2 > 0) || !isfinite(a2)) continue;
        light_tri_t *t = &tris[k++];
        t->p0 = c[3 * i]; t->e1 = e1; t->e2 = e2;
        t->n = v3_norm(x);
        area += 0.5 * a2;
        t->cdf = area;
    }
    if (k == 0 || !(area > 0)) {
        free(tris);
        snprintf(err, errlen, "area light has no area (every triangle is degenerate)");
        return -1;
    }
    for (size_t i = 0; i < k; i++) tris[i].cdf /= area;
    tris[k - 1].cdf = 1.0;
    light_t *arr = realloc(s->lights, (size_t)(s->num_lights + 1) * sizeof *arr);
    if (!arr) { free(tris); snprintf(err, errlen, "out of memory for an area light"); return -1; }
    s->lights = arr;
    light_t *l = &arr[s->num_lights++];
    memset(l, 0, sizeof *l);
    l->kind = LIGHT_AREA;
    l->flux = is_flux ? power : v3_scale(power, PREE_PI * area);
    l->radiance = is_flux ? v3_scale(power, 1.0 / (PREE_PI * area)) : power;
    l->tris = tris;
    l->num_tris = k;
    l->area = area;
    return 0;
}

void mesh_light_sample(const light_t *l, double u_tri, double u_pos, double u_phi, double u_cos,
                       vec3 *origin, vec3 *dir)
{
    /* First triangle whose cumulative share exceeds u_tri (binary search). */
    size_t lo = 0, hi = l->num_tris - 1;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (l->tris[mid].cdf > u_tri) hi = mid; else lo = mid + 1;
    }
    const light_tri_t *t = &l->tris[lo];
    double c0 = lo ? l->tris[lo - 1].cdf : 0.0;
    double u = (u_tri - c0) / (t->cdf - c0);
    if (!(u >= 0)) u = 0;
    if (u > 1) u = 1;
    /* Uniform point on the triangle: p0 + e1 * s (1 - v) + e2 * s v with s = sqrt(u). */
    double sq = sqrt(u);
    *origin = v3_add(t->p0, v3_add(v3_scale(t->e1, sq * (1.0 - u_pos)), v3_scale(t->e2, sq * u_pos)));
    /* Cosine-weighted direction about the front normal, with the diffuse bounce's frame. */
    double phi = 2.0 * PREE_PI * u_phi, st = sqrt(u_cos), ct = sqrt(1.0 - u_cos);
    vec3 w = t->n;
    vec3 a = v3_norm(v3_cross(fabs(w.x) > .1 ? v3(0, 1, 0) : v3(1, 0, 0), w));
    vec3 b = v3_cross(w, a);
    *dir = v3_norm(v3_add(v3_add(v3_scale(a, cos(phi) * st), v3_scale(b, sin(phi) * st)), v3_scale(w, ct)));
}
