// SPDX-License-Identifier: Apache-2.0
/* photon_pass.c: photons from point and area lights through diffuse, mirror and glass bounces. */
#include <stdlib.h>
#include "halton.h"
#include "mesh_light.h"
#include "optics.h"
#include "photon_pass.h"

static int record(photon_hits_t *out, vec3 x, vec3 n, vec3 flux, uint64_t i)
{
    if (out->n == out->cap) {
        size_t cap = out->cap ? out->cap * 2 : 4096;
        photon_hit_t *h = realloc(out->hits, cap * sizeof *h);
        if (!h) return -1;
        out->hits = h;
        out->cap = cap;
    }
    photon_hit_t *h = &out->hits[out->n++];
    h->x = x; h->n = n; h->flux = flux; h->photon = i;
    h->bucket = 0;
    return 0;
}

typedef struct {
    const scene_t *scene;
    const tracer_t *tr;
    photon_hits_t *out;
    uint64_t i;
} photon_ctx_t;

/* Follow one photon segment; depth counts segments (the first hit has depth 1). With
 * --max-bounces W the path ends at its hit of depth W + 1: stored there if diffuse, not
 * scattered again (paper 001's forced stop). */
static int photon_segment(photon_ctx_t *c, vec3 o, vec3 d, int depth, vec3 flux)
{
    hit_t h;
    depth++;
    c->out->segments++;
    if (depth >= c->scene->max_depth || !tracer_intersect(c->tr, o, d, &h)) return 0;
    const int d3 = depth * 3;
    const material_t *m = &c->scene->materials[h.material];
    const int last = c->scene->max_bounces > 0 && depth > c->scene->max_bounces;
    if (last && m->kind != MAT_DIFFUSE) return 0;
    vec3 nl = v3_dot(h.n, d) < 0 ? h.n : v3_scale(h.n, -1.0);
    switch (m->kind) {
    case MAT_DIFFUSE: {
        if (record(c->out, h.x, h.n, flux, c->i)) return -1;
        if (last) return 0;
        /* Russian roulette on the largest reflectance, then a cosine-weighted bounce. */
        double p = v3_max_comp(m->colour);
        if (!(halton(d3 + 1, (long long)c->i) < p)) return 0;
        double s1 = 2.0 * PREE_PI * halton(d3 - 1, (long long)c->i);
        double s2 = halton(d3, (long long)c->i), s2s = sqrt(s2);
        vec3 w = nl;
        vec3 u = v3_norm(v3_cross(fabs(w.x) > .1 ? v3(0, 1, 0) : v3(1, 0, 0), w));
        vec3 v = v3_cross(w, u);
        vec3 dir = v3_norm(v3_add(v3_add(v3_scale(v3_scale(u, cos(s1)), s2s), v3_scale(v3_scale(v, sin(s1)), s2s)),
                                  v3_scale(w, sqrt(1 - s2))));
        return photon_segment(c, h.x, dir, depth, v3_scale(v3_mul(m->colour, flux), 1.0 / p));
    }
    case MAT_MIRROR:
        return photon_segment(c, h.x, optics_reflect(d, h.n), depth, v3_mul(m->colour, flux));
    case MAT_GLASS: {
        vec3 lr = optics_reflect(d, h.n);
        refraction_t rf = optics_refract(d, h.n, nl, m->ior);
        if (rf.total_internal) return photon_segment(c, h.x, lr, depth, flux);
        /* One branch, chosen with probability Re; the flux passes on unchanged. */
        if (halton(d3 - 1, (long long)c->i) < rf.Re) return photon_segment(c, h.x, lr, depth, flux);
        return photon_segment(c, h.x, rf.refracted, depth, flux);
    }
    }
    return 0;
}

/* Halton dimensions of the area-light position: above every bounce's (depth <= 19 uses at
 * most dimension 58), so a photon's path numbers are the same as from a point light. */
#define AREA_DIM_TRI 59
#define AREA_DIM_POS 60

/* The light of photon i, its photon's flux, and the number that picks an area light's triangle:
 * light i mod L with L times its flux (uniform), or by power (scene->light_cdf): u = H(59, i)
 * picks the light with probability p (its share of the flux), the flux divided by p, and u
 * rescaled within the light's share picks the triangle. */
static const light_t *pick_light(const scene_t *scene, uint64_t i, vec3 *flux, double *u_tri)
{
    const int nl = scene->num_lights;
    if (!scene->light_cdf || nl == 1) {
        const light_t *light = &scene->lights[i % (uint64_t)nl];
        *flux = nl == 1 ? light->flux : v3_scale(light->flux, (double)nl);
        *u_tri = light->kind == LIGHT_AREA ? halton(AREA_DIM_TRI, (long long)i) : 0.0;
        return light;
    }
    const double *cdf = scene->light_cdf, u = halton(AREA_DIM_TRI, (long long)i);
    int lo = 0, hi = nl - 1;
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (u < cdf[mid]) hi = mid;
        else lo = mid + 1;
    }
    const double below = lo ? cdf[lo - 1] : 0.0, p = cdf[lo] - below;
    const double r = (u - below) / p;
    *u_tri = r < 1.0 ? r : 0x1.fffffffffffffp-1;
    *flux = v3_scale(scene->lights[lo].flux, 1.0 / p);
    return &scene->lights[lo];
}

int photon_trace(const scene_t *scene, const tracer_t *tr, uint64_t i, photon_hits_t *out)
{
    vec3 flux;
    double u_tri;
    const light_t *light = pick_light(scene, i, &flux, &u_tri);
    photon_ctx_t c = {scene, tr, out, i};
    if (light->kind == LIGHT_AREA) {
        /* Uniform over the area, cosine-weighted about the front normal. */
        vec3 o, d;
        mesh_light_sample(light, u_tri, halton(AREA_DIM_POS, (long long)i),
                          halton(0, (long long)i), halton(1, (long long)i), &o, &d);
        return photon_segment(&c, o, d, 0, flux);
    }
    /* Uniform direction on the sphere from Halton dimensions 0 and 1. */
    double phi = 2. * PREE_PI * halton(0, (long long)i);
    double theta = 2. * acos(sqrt(1. - halton(1, (long long)i)));
    double st = sin(theta);
    vec3 d = v3(cos(phi) * st, cos(theta), sin(phi) * st);
    return photon_segment(&c, light->position, d, 0, flux);
}

void photon_hits_free(photon_hits_t *h)
{
    free(h->hits);
    h->hits = NULL;
    h->n = h->cap = 0;
}
