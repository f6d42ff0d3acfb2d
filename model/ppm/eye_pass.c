// SPDX-License-Identifier: Apache-2.0
/* eye_pass.c: eye rays from the camera to their diffuse hit points, rows in parallel. */
#include <omp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "emitters.h"
#include "eye_pass.h"
#include "halton.h"
#include "optics.h"

/* Image rows traced together before they join the result (a band of the image). */
#define EYE_CHUNK_ROWS 64

typedef struct {
    const scene_t *scene;
    const tracer_t *tr;
    const emitters_t *em;   /* the area lights the eye sees (em->n 0: none) */
    double *emitted;        /* their radiance, 3 a pixel (NULL when em->n is 0); a row is one
                             * thread's, so each pixel's sum is in path order */
    hitpoints_t *out;
    eye_stats_t st;
    int failed;
} eye_ctx_t;

/* Follow one eye path segment; depth counts segments (the first hit has depth 1). The emitted
 * radiance the segment meets before its surface goes to the pixel, weighted as a hit point there
 * would be. */
static void eye_trace(eye_ctx_t *c, vec3 o, vec3 d, int depth, vec3 throughput, int32_t pixel)
{
    hit_t h;
    depth++;
    c->st.rays++;
    if (depth >= c->scene->max_depth) return;
    const int hit = tracer_intersect(c->tr, o, d, &h);
    vec3 Le;
    if (c->em->n && emitters_seen(c->em, o, d, hit ? h.t : INFINITY, &Le)) {
        double *px = c->emitted + 3 * (size_t)pixel;
        const vec3 e = v3_mul(Le, throughput);
        px[0] += e.x;
        px[1] += e.y;
        px[2] += e.z;
        c->st.emitter_hits++;
    }
    if (!hit) return;
    const material_t *m = &c->scene->materials[h.material];
    vec3 nl = v3_dot(h.n, d) < 0 ? h.n : v3_scale(h.n, -1.0);
    switch (m->kind) {
    case MAT_DIFFUSE:
        /* Store the measurement point; the eye path ends here. */
        if (hitpoints_push(c->out, h.x, h.n, v3_mul(m->colour, throughput), pixel, (uint32_t)h.object)) c->failed = 1;
        return;
    case MAT_MIRROR:
        eye_trace(c, h.x, optics_reflect(d, h.n), depth, v3_mul(m->colour, throughput), pixel);
        return;
    case MAT_GLASS: {
        vec3 lr = optics_reflect(d, h.n);
        refraction_t rf = optics_refract(d, h.n, nl, m->ior);
        if (rf.total_internal) { eye_trace(c, h.x, lr, depth, throughput, pixel); return; }
        vec3 fa = v3_mul(m->colour, throughput);
        c->st.glass_splits++;
        eye_trace(c, h.x, lr, depth, v3_scale(fa, rf.Re), pixel);
        eye_trace(c, h.x, rf.refracted, depth, v3_scale(fa, 1.0 - rf.Re), pixel);
        return;
    }
    }
}

/* The image axes of a w x h image: the reference program's camera fixes x to world +x. */
static void camera_axes(const camera_t *cam, int w, int h, vec3 *dir, vec3 *cx, vec3 *cy)
{
    *dir = v3_norm(cam->dir);
    *cx = cam->has_up ? v3_scale(v3_norm(v3_cross(*dir, cam->up)), w * cam->scale / h)
                      : v3(w * cam->scale / h, 0, 0);
    *cy = v3_scale(v3_norm(v3_cross(*cx, *dir)), cam->scale);
}

/* The tracer (Embree's ray.valid()) takes ray origins with |x| up to 1.8e18 and finite
 * directions; the corner rays bound every eye ray's origin and direction. */
int eye_camera_check(const camera_t *cam, int w, int h, char *err, size_t errlen)
{
    vec3 dir, cx, cy;
    camera_axes(cam, w, h, &dir, &cx, &cy);
    for (int k = 0; k < 4; k++) {
        vec3 d = v3_add(v3_add(v3_scale(cx, (k & 1) - 0.5), v3_scale(cy, (k >> 1) - 0.5)), dir);
        vec3 o = v3_add(cam->origin, v3_scale(d, cam->near)), n = v3_norm(d);
        double m = fmax(fabs(o.x), fmax(fabs(o.y), fabs(o.z)));
        if (!v3_is_finite(n) || !(m <= 1e17)) {
            snprintf(err, errlen, "camera: the eye rays (scale %g, near %g, this image size) %s", cam->scale,
                     cam->near, v3_is_finite(n) ? "start beyond +-1e17, outside the tracer's range"
                                                : "have no direction (is 'dir' along the x axis without 'up'?)");
            return -1;
        }
    }
    return 0;
}

/* The rotation (s, t) of pixel p's jitter pattern: two 32-bit halves of a 64-bit mix of p
 * (splitmix64's finalizer), each over 2^32. */
static void eye_jitter_shift(uint64_t p, double *s, double *t)
{
    uint64_t z = p + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    *s = (double)(uint32_t)z * 0x1p-32;
    *t = (double)(uint32_t)(z >> 32) * 0x1p-32;
}

/* The eye rays of pixel (x, y): through its centre (rays <= 1), or jittered (eye_pass.h). */
static void eye_pixel(eye_ctx_t *c, const camera_t *cam, vec3 dir, vec3 cx, vec3 cy, int w, int h, int rays, int x, int y)
{
    const int32_t pixel = y * w + x;
    if (rays <= 1) {
        vec3 d = v3_add(v3_add(v3_scale(cx, (x + 0.5) / w - 0.5), v3_scale(cy, -(y + 0.5) / h + 0.5)), dir);
        eye_trace(c, v3_add(cam->origin, v3_scale(d, cam->near)), v3_norm(d), 0, v3(1, 1, 1), pixel);
        return;
    }
    double s, t;
    eye_jitter_shift((uint64_t)pixel, &s, &t);
    const double wgt = 1.0 / rays;
    for (int k = 0; k < rays; k++) {
        double u = halton(0, k) + s, v = halton(1, k) + t;
        u -= u >= 1;
        v -= v >= 1;
        vec3 d = v3_add(v3_add(v3_scale(cx, (x + u) / w - 0.5), v3_scale(cy, -(y + v) / h + 0.5)), dir);
        eye_trace(c, v3_add(cam->origin, v3_scale(d, cam->near)), v3_norm(d), 0, v3(wgt, wgt, wgt), pixel);
    }
}

int eye_pass(const scene_t *scene, const tracer_t *tr, const eye_pass_opts_t *eo, hitpoints_t *out,
             double **emitted_out, eye_stats_t *stats, const stop_flag_t *stop, char *err, size_t errlen)
{
    const camera_t *cam = &scene->camera;
    const int w = eo->width, h = eo->height;
    vec3 dir, cx, cy;
    camera_axes(cam, w, h, &dir, &cx, &cy);
    if (eye_camera_check(cam, w, h, err, errlen)) return -1;
    const size_t npix = (size_t)w * (size_t)h;
    const int s = eo->stride;
    emitters_t em = {NULL, 0, 0};
    double *emitted = NULL;
    *emitted_out = NULL;
    if (eo->see_lights && emitters_init(&em, scene)) { snprintf(err, errlen, "out of memory"); return -1; }
    if (em.n && !(emitted = calloc(npix * 3, sizeof *emitted))) {
        emitters_free(&em);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    /* Rows are traced in parallel into row buffers and appended in row order, EYE_CHUNK_ROWS at a
     * time, so that the buffers never hold more than a band of the image beside the result. */
    hitpoints_t *rows = calloc(EYE_CHUNK_ROWS, sizeof *rows);
    if (!rows) { emitters_free(&em); free(emitted); snprintf(err, errlen, "out of memory"); return -1; }
    eye_stats_t total = {0, 0, 0};
    int failed = 0, stopped = 0;
    for (int y0 = 0; y0 < h && !failed && !stopped; y0 += EYE_CHUNK_ROWS) {
        const int y1 = y0 + EYE_CHUNK_ROWS < h ? y0 + EYE_CHUNK_ROWS : h;
#pragma omp parallel reduction(+ : failed, stopped)
        {
            eye_ctx_t c = {scene, tr, &em, emitted, NULL, {0, 0, 0}, 0};
#pragma omp for schedule(dynamic, 1)
            for (int y = y0; y < y1; y++) {
                if (stopped || stop_requested(stop)) { stopped = 1; continue; }
                c.out = &rows[y - y0];
                c.out->with_object = out->with_object;
                if (s > 1 && y % s != s / 2) continue;
                for (int x = s > 1 ? s / 2 : 0; x < w; x += s > 1 ? s : 1) eye_pixel(&c, cam, dir, cx, cy, w, h, eo->rays, x, y);
            }
#pragma omp critical
            {
                total.rays += c.st.rays;
                total.glass_splits += c.st.glass_splits;
                total.emitter_hits += c.st.emitter_hits;
            }
            failed += c.failed;
        }
        for (int y = y0; y < y1; y++) {
            if (!failed && !stopped && hitpoints_append(out, &rows[y - y0])) failed = 1;
            hitpoints_free(&rows[y - y0]);
        }
    }
    free(rows);
    emitters_free(&em);
    if (!failed && !stopped && hitpoints_trim(out)) failed = 1;
    if (failed || stopped) {
        free(emitted);
        snprintf(err, errlen, "%s", failed ? "out of memory in the eye pass" : STOP_MESSAGE);
        return -1;
    }
    if (total.emitter_hits) *emitted_out = emitted;
    else free(emitted);
    *stats = total;
    return 0;
}
