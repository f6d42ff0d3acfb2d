// SPDX-License-Identifier: Apache-2.0
/* emitters.c: the emitted radiance an eye ray segment sees (emitters.h). */
#include <math.h>
#include <stdlib.h>
#include "emitters.h"

int emitters_init(emitters_t *em, const scene_t *s)
{
    *em = (emitters_t){NULL, 0, s->epsilon};
    int n = 0;
    for (int l = 0; l < s->num_lights; l++) n += s->lights[l].kind == LIGHT_AREA;
    if (!n) return 0;
    em->e = malloc((size_t)n * sizeof *em->e);
    if (!em->e) return -1;
    for (int l = 0; l < s->num_lights; l++) {
        const light_t *li = &s->lights[l];
        if (li->kind != LIGHT_AREA) continue;
        emitter_t *e = &em->e[em->n++];
        e->light = li;
        e->lo = v3(INFINITY, INFINITY, INFINITY);
        e->hi = v3(-INFINITY, -INFINITY, -INFINITY);
        for (size_t k = 0; k < li->num_tris; k++) {
            const light_tri_t *t = &li->tris[k];
            const vec3 c[3] = {t->p0, v3_add(t->p0, t->e1), v3_add(t->p0, t->e2)};
            for (int j = 0; j < 3; j++) {
                e->lo = v3(fmin(e->lo.x, c[j].x), fmin(e->lo.y, c[j].y), fmin(e->lo.z, c[j].z));
                e->hi = v3(fmax(e->hi.x, c[j].x), fmax(e->hi.y, c[j].y), fmax(e->hi.z, c[j].z));
            }
        }
    }
    return 0;
}

void emitters_free(emitters_t *em)
{
    free(em->e);
    *em = (emitters_t){NULL, 0, 0};
}

/* Does o + t d, t in [t0, t1], meet the box [lo - pad, hi + pad]? (slabs; a zero component of d
 * gives infinite slab distances, which compare correctly) */
static int box_met(vec3 lo, vec3 hi, double pad, vec3 o, vec3 d, double t0, double t1)
{
    const double ov[3] = {o.x, o.y, o.z}, dv[3] = {d.x, d.y, d.z};
    const double lv[3] = {lo.x - pad, lo.y - pad, lo.z - pad}, hv[3] = {hi.x + pad, hi.y + pad, hi.z + pad};
    for (int a = 0; a < 3; a++) {
        if (dv[a] == 0) {
            if (ov[a] < lv[a] || ov[a] > hv[a]) return 0;
            continue;
        }
        double ta = (lv[a] - ov[a]) / dv[a], tb = (hv[a] - ov[a]) / dv[a];
        if (ta > tb) { const double x = ta; ta = tb; tb = x; }
        t0 = fmax(t0, ta);
        t1 = fmin(t1, tb);
        if (t0 > t1) return 0;
    }
    return 1;
}

int emitters_seen(const emitters_t *em, vec3 o, vec3 d, double t_max, vec3 *L)
{
    double best = t_max + em->eps;
    const light_t *seen = NULL;
    for (int i = 0; i < em->n; i++) {
        const emitter_t *e = &em->e[i];
        if (!box_met(e->lo, e->hi, em->eps, o, d, em->eps, best)) continue;
        for (size_t k = 0; k < e->light->num_tris; k++) {
            const light_tri_t *t = &e->light->tris[k];
            if (!(v3_dot(t->n, d) < 0)) continue;   /* its back, or edge-on: nothing emitted */
            const vec3 p = v3_cross(d, t->e2);
            const double det = v3_dot(t->e1, p);
            if (det == 0) continue;
            const double inv = 1.0 / det;
            const vec3 s = v3_sub(o, t->p0);
            const double u = v3_dot(s, p) * inv;
            if (u < 0 || u > 1) continue;
            const vec3 q = v3_cross(s, t->e1);
            const double v = v3_dot(d, q) * inv;
            if (v < 0 || u + v > 1) continue;
            const double tt = v3_dot(t->e2, q) * inv;
            if (tt > em->eps && tt <= best) {
                best = tt;
                seen = e->light;
            }
        }
    }
    if (!seen) return 0;
    *L = seen->radiance;
    return 1;
}
