// SPDX-License-Identifier: Apache-2.0
/* scene_pbrt.c: pbrt-v4 scene files (docs/pbrt.md): the subset that progressive photon mapping
 * renders, with pbrt's semantics: its left-handed camera (the world is mirrored in x when the
 * camera's frame needs it, which leaves the image as pbrt forms it), fov on the shorter image axis,
 * the transform stack, spheres, triangle meshes, diffuse / smooth conductor / dielectric
 * materials, point lights and diffuse area lights, Include, and sppm's parameters. Directives
 * that do not change a PPM image get one note on stderr; anything else unsupported is an error
 * "FILE:LINE: Directive: what". */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mesh_light.h"
#include "mesh_load.h"
#include "pbrt_lex.h"
#include "pbrt_ply.h"
#include "scene.h"
#include "scene_pbrt.h"

#define STACK_MAX 64

typedef struct { double m[4][4]; } mat4;

typedef struct {
    mat4 ctm;
    int reverse;       /* ReverseOrientation */
    int material;      /* scene material index, -1: pbrt's default (diffuse 0.5) */
    int area;          /* an AreaLightSource is active */
    vec3 area_L;       /* its radiance */
} gstate_t;

typedef struct {
    pbrt_lex_t lx;
    scene_t *s;
    gstate_t g[STACK_MAX];
    int depth, is_attr[STACK_MAX];
    int world, have_camera, reflect, noted[32];
    mat4 camera_from_world;
    double fov;
    int film_w, film_h, maxdepth;
    long long iterations, per_iteration;
    int anon;
} ctx_t;

static mat4 identity(void)
{
    mat4 r = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    return r;
}

static mat4 mul(mat4 a, mat4 b)
{
    mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double v = 0;
            for (int k = 0; k < 4; k++) v += a.m[i][k] * b.m[k][j];
            r.m[i][j] = v;
        }
    return r;
}

/* The inverse by Gauss-Jordan elimination with partial pivoting: 0, or -1 when singular. */
static int inverse(mat4 a, mat4 *out)
{
    mat4 r = identity();
    for (int c = 0; c < 4; c++) {
        int p = c;
        for (int i = c + 1; i < 4; i++)
            if (fabs(a.m[i][c]) > fabs(a.m[p][c])) p = i;
        if (a.m[p][c] == 0) return -1;
        for (int j = 0; j < 4; j++) {
            double t = a.m[c][j]; a.m[c][j] = a.m[p][j]; a.m[p][j] = t;
            t = r.m[c][j]; r.m[c][j] = r.m[p][j]; r.m[p][j] = t;
        }
        const double d = a.m[c][c];
        for (int j = 0; j < 4; j++) { a.m[c][j] /= d; r.m[c][j] /= d; }
        for (int i = 0; i < 4; i++) {
            if (i == c || a.m[i][c] == 0) continue;
            const double f = a.m[i][c];
            for (int j = 0; j < 4; j++) { a.m[i][j] -= f * a.m[c][j]; r.m[i][j] -= f * r.m[c][j]; }
        }
    }
    *out = r;
    return 0;
}

static vec3 apply_point(const mat4 *m, vec3 p)
{
    const double x = m->m[0][0] * p.x + m->m[0][1] * p.y + m->m[0][2] * p.z + m->m[0][3];
    const double y = m->m[1][0] * p.x + m->m[1][1] * p.y + m->m[1][2] * p.z + m->m[1][3];
    const double z = m->m[2][0] * p.x + m->m[2][1] * p.y + m->m[2][2] * p.z + m->m[2][3];
    const double w = m->m[3][0] * p.x + m->m[3][1] * p.y + m->m[3][2] * p.z + m->m[3][3];
    return w == 1 ? v3(x, y, z) : v3(x / w, y / w, z / w);
}

static vec3 apply_vector(const mat4 *m, vec3 v)
{
    return v3(m->m[0][0] * v.x + m->m[0][1] * v.y + m->m[0][2] * v.z, m->m[1][0] * v.x + m->m[1][1] * v.y + m->m[1][2] * v.z,
              m->m[2][0] * v.x + m->m[2][1] * v.y + m->m[2][2] * v.z);
}

static double det3(const mat4 *m)
{
    return m->m[0][0] * (m->m[1][1] * m->m[2][2] - m->m[1][2] * m->m[2][1]) -
           m->m[0][1] * (m->m[1][0] * m->m[2][2] - m->m[1][2] * m->m[2][0]) +
           m->m[0][2] * (m->m[1][0] * m->m[2][1] - m->m[1][1] * m->m[2][0]);
}

/* pbrt's world as PREE's: mirrored in x when the camera's frame needs it (see docs/pbrt.md). */
static vec3 to_scene(const ctx_t *c, vec3 p) { return c->reflect ? v3(-p.x, p.y, p.z) : p; }

/* A note for a directive that does not change the image, once per kind. */
static void note(ctx_t *c, int kind, const pbrt_tok_t *at, const char *what)
{
    if (kind < 0 || kind >= 32 || c->noted[kind]) return;
    c->noted[kind] = 1;
    fprintf(stderr, "pree: note: %s:%d: %s: %s\n", at->file, at->line, at->text, what);
}

/* Every parameter a directive did not take is an error (it could change the image). */
static int unused(ctx_t *c, const pbrt_tok_t *at, pbrt_params_t *ps)
{
    for (int k = 0; k < ps->n; k++)
        if (!ps->p[k].used)
            return pbrt_fail(&c->lx, at, "%s: parameter \"%s %s\" is not supported", at->text, ps->p[k].type,
                             ps->p[k].name);
    return 0;
}

/* A parameter's numbers: exactly n (n > 0) or a multiple of -n; NULL with err when absent (def
 * NULL) or malformed. */
static const double *nums(ctx_t *c, const pbrt_tok_t *at, pbrt_params_t *ps, const char *name, const char *type,
                          int n, const double *def, int *count, int *bad)
{
    pbrt_param_t *p = pbrt_param(ps, name);
    if (count) *count = 0;
    if (!p) return def;
    if (strcmp(p->type, type) && !(!strcmp(type, "point3") && !strcmp(p->type, "point")) &&
        !(!strcmp(type, "normal") && !strcmp(p->type, "normal3"))) {
        *bad = pbrt_fail(&c->lx, at, "%s: \"%s %s\": expected type %s", at->text, p->type, name, type);
        return NULL;
    }
    if (n > 0 ? p->n != n : (p->n == 0 || p->n % -n)) {
        *bad = pbrt_fail(&c->lx, at, "%s: \"%s %s\" has %d values", at->text, p->type, name, p->n);
        return NULL;
    }
    if (count) *count = p->n;
    return p->num;
}

static int read_numbers(ctx_t *c, const pbrt_tok_t *at, int n, double *v)
{
    pbrt_tok_t t;
    int list = 0;
    if (pbrt_lex_peek(&c->lx, &t)) return -1;
    if (t.kind == PT_LBRACKET) { pbrt_lex_next(&c->lx, &t); list = 1; }
    for (int k = 0; k < n; k++) {
        if (pbrt_lex_next(&c->lx, &t)) return -1;
        if (t.kind != PT_NUMBER) return pbrt_fail(&c->lx, at, "%s: expected %d numbers", at->text, n);
        v[k] = t.num;
    }
    if (list && (pbrt_lex_next(&c->lx, &t) || t.kind != PT_RBRACKET))
        return pbrt_fail(&c->lx, at, "%s: expected ']' after %d numbers", at->text, n);
    return 0;
}

static int read_string(ctx_t *c, const pbrt_tok_t *at, char *out, size_t len)
{
    pbrt_tok_t t;
    if (pbrt_lex_next(&c->lx, &t)) return -1;
    if (t.kind != PT_STRING) return pbrt_fail(&c->lx, at, "%s: expected a quoted name", at->text);
    snprintf(out, len, "%s", t.text);
    return 0;
}

/* The parameter NAME without marking it used, or NULL. */
static const pbrt_param_t *has(const pbrt_params_t *ps, const char *name)
{
    for (int k = 0; k < ps->n; k++)
        if (!strcmp(ps->p[k].name, name)) return &ps->p[k];
    return NULL;
}

static gstate_t *g(ctx_t *c) { return &c->g[c->depth]; }

static void concat(ctx_t *c, mat4 m) { g(c)->ctm = mul(g(c)->ctm, m); }

static int rgb_param(ctx_t *c, const pbrt_tok_t *at, pbrt_params_t *ps, const char *name, vec3 def, vec3 *out)
{
    int bad = 0;
    const pbrt_param_t *p = has(ps, name);
    if (p && strcmp(p->type, "rgb"))
        return pbrt_fail(&c->lx, at, "%s: \"%s %s\" is not supported (give \"rgb %s\")", at->text, p->type, name, name);
    const double *v = nums(c, at, ps, name, "rgb", 3, NULL, NULL, &bad);
    if (bad) return -1;
    *out = v ? v3(v[0], v[1], v[2]) : def;
    if (out->x < 0 || out->y < 0 || out->z < 0) return pbrt_fail(&c->lx, at, "%s: \"rgb %s\" is negative", at->text, name);
    return 0;
}

static int float_param(ctx_t *c, const pbrt_tok_t *at, pbrt_params_t *ps, const char *name, double def, double *out)
{
    int bad = 0;
    const double *v = nums(c, at, ps, name, "float", 1, NULL, NULL, &bad);
    if (bad) return -1;
    *out = v ? v[0] : def;
    return 0;
}

static int int_param(ctx_t *c, const pbrt_tok_t *at, pbrt_params_t *ps, const char *name, long long def, long long *out)
{
    int bad = 0;
    const double *v = nums(c, at, ps, name, "integer", 1, NULL, NULL, &bad);
    if (bad) return -1;
    if (v && (!(fabs(v[0]) <= 9007199254740992.0) || v[0] != floor(v[0])))   /* within 2^53, whole */
        return pbrt_fail(&c->lx, at, "%s: \"integer %s\" %g is not an integer", at->text, name, v[0]);
    *out = v ? (long long)v[0] : def;
    return 0;
}

/* A material from its type and parameters into *m (name set by the caller): 0, or -1. */
static int make_material(ctx_t *c, const pbrt_tok_t *at, const char *type, pbrt_params_t *ps, material_t *m)
{
    double rough = 0, ur = 0, vr = 0, eta = 1.5;
    if (!strcmp(type, "diffuse")) {
        m->kind = MAT_DIFFUSE;
        if (rgb_param(c, at, ps, "reflectance", v3(0.5, 0.5, 0.5), &m->colour)) return -1;
    } else if (!strcmp(type, "conductor") || !strcmp(type, "dielectric")) {
        if (float_param(c, at, ps, "roughness", 0, &rough) || float_param(c, at, ps, "uroughness", rough, &ur) ||
            float_param(c, at, ps, "vroughness", rough, &vr))
            return -1;
        pbrt_param(ps, "remaproughness");
        if (ur != 0 || vr != 0)
            return pbrt_fail(&c->lx, at, "%s: a rough %s (roughness %g) is not supported: smooth only", at->text, type,
                             ur != 0 ? ur : vr);
        if (!strcmp(type, "dielectric")) {
            m->kind = MAT_GLASS;
            m->colour = v3(1, 1, 1);
            const pbrt_param_t *pe = has(ps, "eta");
            if (pe && strcmp(pe->type, "float"))
                return pbrt_fail(&c->lx, at, "%s: \"%s eta\" is not supported (give \"float eta\")", at->text, pe->type);
            if (float_param(c, at, ps, "eta", 1.5, &eta)) return -1;
            if (!(eta > 1 && eta <= 10)) return pbrt_fail(&c->lx, at, "%s: eta %g is not in (1, 10]", at->text, eta);
            m->ior = eta;
        } else {
            m->kind = MAT_MIRROR;
            vec3 e, k;
            if (has(ps, "reflectance")) {
                if (rgb_param(c, at, ps, "reflectance", v3(1, 1, 1), &m->colour)) return -1;
            } else if (has(ps, "eta") && has(ps, "k")) {
                if (rgb_param(c, at, ps, "eta", v3(1, 1, 1), &e) || rgb_param(c, at, ps, "k", v3(0, 0, 0), &k)) return -1;
                /* The reflectance at normal incidence, per channel. */
                const double n3[3] = {e.x, e.y, e.z}, k3[3] = {k.x, k.y, k.z};
                double f[3];
                for (int i = 0; i < 3; i++)
                    f[i] = ((n3[i] - 1) * (n3[i] - 1) + k3[i] * k3[i]) / ((n3[i] + 1) * (n3[i] + 1) + k3[i] * k3[i]);
                m->colour = v3(f[0], f[1], f[2]);
            } else {
                return pbrt_fail(&c->lx, at, "%s: a conductor needs \"rgb reflectance\" or \"rgb eta\" and \"rgb k\" "
                                 "(named spectra are not supported)", at->text);
            }
        }
    } else {
        return pbrt_fail(&c->lx, at, "%s: material type \"%s\" is not supported (diffuse, conductor, dielectric)",
                         at->text, type);
    }
    if (m->colour.x > 1 || m->colour.y > 1 || m->colour.z > 1)
        return pbrt_fail(&c->lx, at, "%s: a reflectance above 1", at->text);
    return unused(c, at, ps);
}

static int add_material(ctx_t *c, const pbrt_tok_t *at, material_t *m)
{
    char e[256];
    const int id = scene_add_material(c->s, m, e, sizeof e);
    if (id < 0) return pbrt_fail(&c->lx, at, "%s: %s", at->text, e);
    return id;
}

static int material_of(ctx_t *c, const pbrt_tok_t *at)
{
    if (g(c)->material >= 0) return g(c)->material;
    int id = scene_find_material(c->s, "pbrt:default");
    if (id >= 0) return id;
    material_t m = {.name = "pbrt:default", .kind = MAT_DIFFUSE, .colour = {0.5, 0.5, 0.5}, .ior = 1.5};
    return add_material(c, at, &m);
}

static int do_material(ctx_t *c, const pbrt_tok_t *at, int named)
{
    char type[256] = "", name[256];
    pbrt_params_t ps;
    if (read_string(c, at, named ? name : type, sizeof type) || pbrt_params_read(&c->lx, &ps)) return -1;
    int rc = -1;
    material_t m = {.ior = 1.5};
    if (named) {
        pbrt_param_t *t = pbrt_param(&ps, "type");
        if (!t || !t->is_str || t->n != 1) { rc = pbrt_fail(&c->lx, at, "%s: needs \"string type\"", at->text); goto out; }
        snprintf(type, sizeof type, "%s", t->str[0]);
        snprintf(m.name, sizeof m.name, "pbrt:%.58s", name);
    } else {
        snprintf(m.name, sizeof m.name, "pbrt:%d:%d", c->lx.depth, ++c->anon);
    }
    if (make_material(c, at, type, &ps, &m)) goto out;
    const int id = add_material(c, at, &m);
    if (id < 0) goto out;
    if (!named) g(c)->material = id;
    rc = 0;
out:
    pbrt_params_free(&ps);
    return rc;
}

static int do_named_material(ctx_t *c, const pbrt_tok_t *at)
{
    char name[256], full[80];
    if (read_string(c, at, name, sizeof name)) return -1;
    snprintf(full, sizeof full, "pbrt:%.58s", name);
    const int id = scene_find_material(c->s, full);
    if (id < 0) return pbrt_fail(&c->lx, at, "%s: no material \"%s\" (MakeNamedMaterial before)", at->text, name);
    g(c)->material = id;
    return 0;
}

static int add_sphere(ctx_t *c, const pbrt_tok_t *at, pbrt_params_t *ps)
{
    double r, zmin, zmax, phimax;
    if (float_param(c, at, ps, "radius", 1, &r) || float_param(c, at, ps, "zmin", -r, &zmin) ||
        float_param(c, at, ps, "zmax", r, &zmax) || float_param(c, at, ps, "phimax", 360, &phimax))
        return -1;
    if (!(r > 0)) return pbrt_fail(&c->lx, at, "Shape: sphere radius %g is not positive", r);
    if (zmin > -r || zmax < r || phimax < 360)
        return pbrt_fail(&c->lx, at, "Shape: a partial sphere (zmin %g, zmax %g, phimax %g) is not supported", zmin, zmax,
                         phimax);
    if (g(c)->area) return pbrt_fail(&c->lx, at, "Shape: an area light on a sphere is not supported (triangles only)");
    const mat4 *m = &g(c)->ctm;
    double len[3];
    for (int k = 0; k < 3; k++) len[k] = sqrt(v3_dot(apply_vector(m, v3(k == 0, k == 1, k == 2)), apply_vector(m, v3(k == 0, k == 1, k == 2))));
    if (fabs(len[0] - len[1]) > 1e-9 * len[0] || fabs(len[0] - len[2]) > 1e-9 * len[0])
        return pbrt_fail(&c->lx, at, "Shape: a sphere under a non-uniform scale (%g, %g, %g) is not supported", len[0], len[1],
                         len[2]);
    const int mat = material_of(c, at);
    if (mat < 0) return -1;
    sphere_t *arr = realloc(c->s->spheres, (size_t)(c->s->num_spheres + 1) * sizeof *arr);
    if (!arr) return pbrt_fail(&c->lx, at, "out of memory");
    c->s->spheres = arr;
    arr[c->s->num_spheres++] = (sphere_t){.radius = r * len[0], .centre = to_scene(c, apply_point(m, v3(0, 0, 0))),
                                          .material = mat};
    return unused(c, at, ps);
}

/* Triangles from corners P (np points) and indices idx (ni, a multiple of 3), normals N (or
 * NULL): geometry, and an area light when one is active, emitting on pbrt's side. */
static int add_triangles(ctx_t *c, const pbrt_tok_t *at, const double *P, int np, const double *idx, int ni,
                         const double *N)
{
    const gstate_t *gs = g(c);
    const int mat = material_of(c, at);
    if (mat < 0) return -1;
    mat4 inv, nt;   /* normals: the inverse transpose */
    if (inverse(gs->ctm, &inv)) return pbrt_fail(&c->lx, at, "Shape: the transform is singular");
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) nt.m[i][j] = inv.m[j][i];
    const int swaps = det3(&gs->ctm) < 0;
    vec3 *corners = gs->area ? malloc((size_t)ni * sizeof *corners) : NULL;
    if (gs->area && !corners) return pbrt_fail(&c->lx, at, "out of memory");
    int nl = 0;
    char e[256];
    for (int t = 0; t < ni; t += 3) {
        vec3 w[3], q[3], obj_ns = v3(0, 0, 0);
        for (int k = 0; k < 3; k++) {
            const double v = idx ? idx[t + k] : t + k;
            if (v < 0 || v >= np || v != floor(v)) {
                free(corners);
                return pbrt_fail(&c->lx, at, "Shape: index %g is not a vertex (0..%d)", v, np - 1);
            }
            const int i = (int)v;
            w[k] = apply_point(&gs->ctm, v3(P[3 * i], P[3 * i + 1], P[3 * i + 2]));
            if (!v3_is_finite(w[k]) || fabs(w[k].x) > SCENE_COORD_MAX || fabs(w[k].y) > SCENE_COORD_MAX ||
                fabs(w[k].z) > SCENE_COORD_MAX) {
                free(corners);
                return pbrt_fail(&c->lx, at, "Shape: vertex %d is beyond +-%g after the transform", i, SCENE_COORD_MAX);
            }
            if (N) obj_ns = v3_add(obj_ns, v3(N[3 * i], N[3 * i + 1], N[3 * i + 2]));
            q[k] = to_scene(c, w[k]);
        }
        vec3 n = v3_cross(v3_sub(q[1], q[0]), v3_sub(q[2], q[0]));
        if (v3_dot(n, n) == 0) continue;   /* degenerate: it cannot be hit */
        if (mesh_append_triangle(c->s, q, mat, e, sizeof e)) { free(corners); return pbrt_fail(&c->lx, at, "Shape: %s", e); }
        if (!corners) continue;
        /* pbrt's emitting side: the geometric normal of the world corners, flipped by
         * ReverseOrientation and by a transform that swaps handedness; with normals, their side. */
        vec3 d = v3_cross(v3_sub(w[1], w[0]), v3_sub(w[2], w[0]));
        if (gs->reverse ^ swaps) d = v3_scale(d, -1);
        if (N) {
            vec3 ns = apply_vector(&nt, obj_ns);
            if (gs->reverse) ns = v3_scale(ns, -1);
            if (v3_dot(d, ns) < 0) d = v3_scale(d, -1);
        }
        d = to_scene(c, d);
        if (v3_dot(n, d) < 0) { vec3 tmp = q[1]; q[1] = q[2]; q[2] = tmp; }
        for (int k = 0; k < 3; k++) corners[3 * nl + k] = q[k];
        nl++;
    }
    int rc = 0;
    if (corners && nl && mesh_light_add(c->s, corners, (size_t)nl, gs->area_L, 0, e, sizeof e))
        rc = pbrt_fail(&c->lx, at, "AreaLightSource: %s", e);
    free(corners);
    return rc;
}

static int add_trianglemesh(ctx_t *c, const pbrt_tok_t *at, pbrt_params_t *ps)
{
    int bad = 0, np = 0, ni = 0, nn = 0;
    const double *P = nums(c, at, ps, "P", "point3", -3, NULL, &np, &bad);
    const double *idx = nums(c, at, ps, "indices", "integer", -3, NULL, &ni, &bad);
    const double *N = nums(c, at, ps, "N", "normal", -3, NULL, &nn, &bad);
    if (bad) return -1;
    if (!P) return pbrt_fail(&c->lx, at, "Shape: trianglemesh needs \"point3 P\"");
    np /= 3;
    if (!idx && np != 3) return pbrt_fail(&c->lx, at, "Shape: trianglemesh needs \"integer indices\" (%d points)", np);
    if (N && nn / 3 != np) return pbrt_fail(&c->lx, at, "Shape: \"normal N\" has %d normals for %d points", nn / 3, np);
    for (const char *const *o = (const char *const[]){"uv", "S", "faceIndices", NULL}; *o; o++)
        if (pbrt_param(ps, *o)) note(c, 20, at, "texture coordinates, tangents and face indices are not used");
    if (N) note(c, 21, at, "shading normals (\"normal N\") are not used: triangles are flat-shaded; N sets an area light's side");
    if (unused(c, at, ps)) return -1;
    return add_triangles(c, at, P, np, idx, idx ? ni : 3, N);
}

static int add_plymesh(ctx_t *c, const pbrt_tok_t *at, pbrt_params_t *ps)
{
    pbrt_param_t *f = pbrt_param(ps, "filename");
    if (!f || !f->is_str || f->n != 1) return pbrt_fail(&c->lx, at, "Shape: plymesh needs \"string filename\"");
    for (const char *const *o = (const char *const[]){"displacement", "edgelength", NULL}; *o; o++)
        if (has(ps, *o)) return pbrt_fail(&c->lx, at, "Shape: plymesh: \"%s\" (displacement) is not supported", *o);
    if (unused(c, at, ps)) return -1;
    char path[4200], e[4400];
    const char *slash = strrchr(at->file, '/');
    if (f->str[0][0] == '/' || !slash) snprintf(path, sizeof path, "%s", f->str[0]);
    else snprintf(path, sizeof path, "%.*s/%s", (int)(slash - at->file), at->file, f->str[0]);
    pbrt_ply_t ply;
    if (pbrt_ply_read(path, &ply, e, sizeof e)) return pbrt_fail(&c->lx, at, "Shape: plymesh: %s", e);
    if (ply.normals) note(c, 21, at, "shading normals are not used: triangles are flat-shaded; they set an area light's side");
    const int rc = add_triangles(c, at, ply.points, (int)ply.num_points, ply.indices, (int)(3 * ply.num_triangles),
                                 ply.normals);
    pbrt_ply_free(&ply);
    return rc;
}

static int do_shape(ctx_t *c, const pbrt_tok_t *at, const char *type, pbrt_params_t *ps)
{
    if (!c->world) return pbrt_fail(&c->lx, at, "Shape before WorldBegin");
    if (!strcmp(type, "sphere")) return add_sphere(c, at, ps);
    if (!strcmp(type, "trianglemesh")) return add_trianglemesh(c, at, ps);
    if (!strcmp(type, "plymesh")) return add_plymesh(c, at, ps);
    return pbrt_fail(&c->lx, at, "Shape: \"%s\" is not supported (sphere, trianglemesh, plymesh)", type);
}

static int do_light(ctx_t *c, const pbrt_tok_t *at, const char *type, pbrt_params_t *ps)
{
    const int area = at->text[0] == 'A';   /* AreaLightSource */
    int bad = 0;
    double scale;
    vec3 L;
    if (!c->world) return pbrt_fail(&c->lx, at, "%s before WorldBegin", at->text);
    if (strcmp(type, area ? "diffuse" : "point"))
        return pbrt_fail(&c->lx, at, "%s: \"%s\" is not supported (%s)", at->text, type, area ? "diffuse" : "point");
    if (has(ps, "power"))
        return pbrt_fail(&c->lx, at, "%s: \"power\" is not supported (give the %s and \"scale\")", at->text,
                         area ? "radiance L" : "intensity I");
    if (float_param(c, at, ps, "scale", 1, &scale) || rgb_param(c, at, ps, area ? "L" : "I", v3(1, 1, 1), &L)) return -1;
    if (!(scale >= 0)) return pbrt_fail(&c->lx, at, "%s: scale %g is negative", at->text, scale);
    L = v3_scale(L, scale);
    if (area) {
        const double *two = nums(c, at, ps, "twosided", "bool", 1, NULL, NULL, &bad);
        if (bad) return -1;
        if (two && two[0]) return pbrt_fail(&c->lx, at, "%s: a two-sided area light is not supported", at->text);
        if (unused(c, at, ps)) return -1;
        g(c)->area = 1;
        g(c)->area_L = L;
    } else {
        const double zero[3] = {0, 0, 0}, *from = nums(c, at, ps, "from", "point3", 3, zero, NULL, &bad);
        if (bad || unused(c, at, ps)) return -1;
        light_t l = {.kind = LIGHT_POINT, .position = to_scene(c, apply_point(&g(c)->ctm, v3(from[0], from[1], from[2]))),
                     .flux = v3_scale(L, PREE_PI * 4.0)};
        light_t *arr = realloc(c->s->lights, (size_t)(c->s->num_lights + 1) * sizeof *arr);
        if (!arr) return pbrt_fail(&c->lx, at, "out of memory");
        c->s->lights = arr;
        arr[c->s->num_lights++] = l;
    }
    return 0;
}

static int do_camera(ctx_t *c, const pbrt_tok_t *at, const char *type, pbrt_params_t *ps)
{
    double lens;
    if (c->world) return pbrt_fail(&c->lx, at, "Camera after WorldBegin");
    if (strcmp(type, "perspective")) return pbrt_fail(&c->lx, at, "Camera: \"%s\" is not supported (perspective)", type);
    if (float_param(c, at, ps, "fov", 90, &c->fov) || float_param(c, at, ps, "lensradius", 0, &lens)) return -1;
    if (!(c->fov > 0 && c->fov < 180)) return pbrt_fail(&c->lx, at, "Camera: fov %g is not in (0, 180)", c->fov);
    if (lens != 0) return pbrt_fail(&c->lx, at, "Camera: a lens (lensradius %g) is not supported: a pinhole only", lens);
    if (pbrt_param(ps, "focaldistance")) note(c, 22, at, "focaldistance has no effect on a pinhole");
    if (unused(c, at, ps)) return -1;
    c->camera_from_world = g(c)->ctm;
    c->have_camera = 1;
    return 0;
}

static int do_film(ctx_t *c, const pbrt_tok_t *at, const char *type, pbrt_params_t *ps)
{
    (void)type;   /* any film: its resolution is what a PPM image takes */
    long long w, h;
    if (int_param(c, at, ps, "xresolution", 1280, &w) || int_param(c, at, ps, "yresolution", 720, &h)) return -1;
    if (w < 1 || h < 1 || w > 16384 || h > 16384) return pbrt_fail(&c->lx, at, "Film: %lldx%lld is not in 1..16384", w, h);
    c->film_w = (int)w;
    c->film_h = (int)h;
    for (int k = 0; k < ps->n; k++) ps->p[k].used = 1;   /* the file name, sensor, ...: PREE writes --out as is */
    note(c, 1, at, "the resolution is taken; the file name and the sensor's parameters are not (pree render --out)");
    return 0;
}

static int do_integrator(ctx_t *c, const pbrt_tok_t *at, const char *type, pbrt_params_t *ps)
{
    long long depth, it, per;
    double radius;
    if (strcmp(type, "sppm")) {
        for (int k = 0; k < ps->n; k++) ps->p[k].used = 1;
        note(c, 2, at, "PREE renders by progressive photon mapping whatever the integrator; its parameters are not used");
        return 0;
    }
    const int has_radius = has(ps, "radius") != NULL;
    if (float_param(c, at, ps, "radius", 0, &radius)) return -1;
    if (has_radius && !(radius > 0 && radius <= 1e30))
        return pbrt_fail(&c->lx, at, "Integrator: sppm's radius %g is not in (0, 1e30]", radius);
    if (int_param(c, at, ps, "maxdepth", 5, &depth) || int_param(c, at, ps, "iterations", 64, &it) ||
        int_param(c, at, ps, "numiterations", it, &it) || int_param(c, at, ps, "photonsperiteration", -1, &per))
        return -1;
    if (pbrt_param(ps, "seed")) note(c, 3, at, "the seed is not used: PREE's photons follow the Halton sequence");
    if (depth < 1 || depth > 19) return pbrt_fail(&c->lx, at, "Integrator: maxdepth %lld is not in 1..19", depth);
    if (it < 1 || it > 4294967295LL || per == 0 || per < -1 || per > 4294967295LL) return pbrt_fail(&c->lx, at, "Integrator: %lld iterations of %lld photons", it, per);
    if (unused(c, at, ps)) return -1;
    c->maxdepth = (int)depth;
    c->s->film_radius = radius;   /* 0 when not given */
    c->iterations = it;
    c->per_iteration = per;
    return 0;
}

/* A directive that takes a type and parameters and does not change a PPM image: one note. */
static int do_noted(ctx_t *c, const pbrt_tok_t *at, int kind, const char *what, const char *only_type)
{
    char type[256] = "";
    pbrt_params_t ps;
    pbrt_tok_t t;
    if (pbrt_lex_peek(&c->lx, &t)) return -1;
    if (t.kind == PT_STRING && read_string(c, at, type, sizeof type)) return -1;
    if (pbrt_params_read(&c->lx, &ps)) return -1;
    pbrt_params_free(&ps);
    if (only_type && strcmp(type, only_type))
        return pbrt_fail(&c->lx, at, "%s: \"%s\" is not supported (%s only: PREE traces one ray through each pixel's centre)",
                         at->text, type, only_type);
    note(c, kind, at, what);
    return 0;
}

static int do_transform(ctx_t *c, const pbrt_tok_t *at)
{
    const char *d = at->text;
    double v[16];
    if (!strcmp(d, "Identity")) { g(c)->ctm = identity(); return 0; }
    if (!strcmp(d, "Translate") || !strcmp(d, "Scale")) {
        if (read_numbers(c, at, 3, v)) return -1;
        mat4 m = identity();
        for (int k = 0; k < 3; k++) {
            if (d[0] == 'T') m.m[k][3] = v[k];
            else m.m[k][k] = v[k];
        }
        concat(c, m);
        return 0;
    }
    if (!strcmp(d, "Rotate")) {
        if (read_numbers(c, at, 4, v)) return -1;
        double len = sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
        if (len == 0) return pbrt_fail(&c->lx, at, "Rotate: the axis is zero");
        const double x = v[1] / len, y = v[2] / len, z = v[3] / len, a = v[0] * (PREE_PI / 180.0);
        const double s = sin(a), co = cos(a);
        mat4 m = identity();
        m.m[0][0] = x * x + (1 - x * x) * co; m.m[0][1] = x * y * (1 - co) - z * s; m.m[0][2] = x * z * (1 - co) + y * s;
        m.m[1][0] = x * y * (1 - co) + z * s; m.m[1][1] = y * y + (1 - y * y) * co; m.m[1][2] = y * z * (1 - co) - x * s;
        m.m[2][0] = x * z * (1 - co) - y * s; m.m[2][1] = y * z * (1 - co) + x * s; m.m[2][2] = z * z + (1 - z * z) * co;
        concat(c, m);
        return 0;
    }
    if (!strcmp(d, "LookAt")) {
        if (read_numbers(c, at, 9, v)) return -1;
        const vec3 pos = v3(v[0], v[1], v[2]), dir0 = v3_sub(v3(v[3], v[4], v[5]), pos), up = v3(v[6], v[7], v[8]);
        const vec3 right0 = v3_cross(v3_norm(up), v3_norm(dir0));
        if (v3_dot(dir0, dir0) == 0 || v3_dot(right0, right0) == 0)
            return pbrt_fail(&c->lx, at, "LookAt: the view direction is zero or parallel to up");
        const vec3 dir = v3_norm(dir0), right = v3_norm(right0), nup = v3_cross(dir, right);
        mat4 wfc = identity();   /* world from camera: columns right, up, dir, pos */
        const vec3 col[4] = {right, nup, dir, pos};
        for (int k = 0; k < 4; k++) { wfc.m[0][k] = col[k].x; wfc.m[1][k] = col[k].y; wfc.m[2][k] = col[k].z; }
        mat4 cfw;
        if (inverse(wfc, &cfw)) return pbrt_fail(&c->lx, at, "LookAt: a singular frame");
        concat(c, cfw);
        return 0;
    }
    /* Transform / ConcatTransform: 16 numbers, column by column. */
    if (read_numbers(c, at, 16, v)) return -1;
    mat4 m;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) m.m[i][j] = v[4 * j + i];
    if (d[0] == 'T') g(c)->ctm = m;
    else concat(c, m);
    return 0;
}

static int push_state(ctx_t *c, const pbrt_tok_t *at, int attr)
{
    if (c->depth + 1 == STACK_MAX) return pbrt_fail(&c->lx, at, "%s: nested more than %d deep", at->text, STACK_MAX - 1);
    c->g[c->depth + 1] = c->g[c->depth];
    c->is_attr[++c->depth] = attr;
    return 0;
}

static int pop_state(ctx_t *c, const pbrt_tok_t *at, int attr)
{
    if (c->depth == 0) return pbrt_fail(&c->lx, at, "%s without a matching Begin", at->text);
    if (c->is_attr[c->depth] != attr)
        return pbrt_fail(&c->lx, at, "%s closes a %sBegin", at->text, attr ? "Transform" : "Attribute");
    const gstate_t inner = c->g[c->depth];
    c->depth--;
    if (!attr) {   /* TransformEnd restores the transform only */
        const mat4 m = c->g[c->depth].ctm;
        c->g[c->depth] = inner;
        c->g[c->depth].ctm = m;
    }
    return 0;
}

typedef int (*typed_fn)(ctx_t *, const pbrt_tok_t *, const char *, pbrt_params_t *);

/* A directive of the form `Name "type" parameters...`: read them, then fn. */
static int typed(ctx_t *c, const pbrt_tok_t *at, typed_fn fn)
{
    char type[256];
    pbrt_params_t ps;
    if (read_string(c, at, type, sizeof type) || pbrt_params_read(&c->lx, &ps)) return -1;
    const int rc = fn(c, at, type, &ps);
    pbrt_params_free(&ps);
    return rc;
}

/* The directives, each reading its own arguments. */
static int directive(ctx_t *c, const pbrt_tok_t *at)
{
    const char *d = at->text;
    char name[256];
    static const char *const transforms[] = {"Identity", "Translate", "Scale", "Rotate", "LookAt", "Transform",
                                             "ConcatTransform"};
    for (size_t k = 0; k < sizeof transforms / sizeof *transforms; k++)
        if (!strcmp(d, transforms[k])) return do_transform(c, at);
    if (!strcmp(d, "AttributeBegin") || !strcmp(d, "TransformBegin")) return push_state(c, at, d[0] == 'A');
    if (!strcmp(d, "AttributeEnd") || !strcmp(d, "TransformEnd")) return pop_state(c, at, d[0] == 'A');
    if (!strcmp(d, "ReverseOrientation")) { g(c)->reverse ^= 1; return 0; }
    if (!strcmp(d, "WorldBegin")) {
        if (c->world) return pbrt_fail(&c->lx, at, "WorldBegin given twice");
        c->world = 1;
        c->depth = 0;
        c->g[0].ctm = identity();
        /* pbrt's camera frame (right, up, forward) is left-handed where PREE's is right-handed:
         * mirror the world in x when the camera's image x axis is forward x up. */
        mat4 wfc;
        if (inverse(c->camera_from_world, &wfc)) return pbrt_fail(&c->lx, at, "the camera transform is singular");
        const vec3 right = apply_vector(&wfc, v3(1, 0, 0)), up = apply_vector(&wfc, v3(0, 1, 0)),
                   fwd = apply_vector(&wfc, v3(0, 0, 1));
        c->reflect = v3_dot(v3_cross(fwd, up), right) < 0;
        return 0;
    }
    if (!strcmp(d, "WorldEnd")) { note(c, 4, at, "(pbrt-v3) ignored"); return 0; }
    if (!strcmp(d, "Include") || !strcmp(d, "Import")) {
        if (read_string(c, at, name, sizeof name)) return -1;
        return pbrt_lex_include(&c->lx, at, name);
    }
    if (!strcmp(d, "Camera")) return typed(c, at, do_camera);
    if (!strcmp(d, "Film")) return typed(c, at, do_film);
    if (!strcmp(d, "Integrator")) return typed(c, at, do_integrator);
    if (!strcmp(d, "Sampler")) return do_noted(c, at, 5, "PREE's eye rays go through pixel centres and its photons "
                                               "follow the Halton sequence", NULL);
    if (!strcmp(d, "PixelFilter")) return do_noted(c, at, 6, "a box filter over one sample at each pixel's centre", "box");
    if (!strcmp(d, "Option")) return do_noted(c, at, 7, "options are not used", NULL);
    if (!strcmp(d, "ColorSpace")) return do_noted(c, at, 8, "RGB values are used as they are", "srgb");
    if (!strcmp(d, "Accelerator")) return do_noted(c, at, 9, "PREE builds its own (Embree)", NULL);
    if (!strcmp(d, "Material")) return do_material(c, at, 0);
    if (!strcmp(d, "MakeNamedMaterial")) return do_material(c, at, 1);
    if (!strcmp(d, "NamedMaterial")) return do_named_material(c, at);
    if (!strcmp(d, "Shape")) return typed(c, at, do_shape);
    if (!strcmp(d, "LightSource") || !strcmp(d, "AreaLightSource")) return typed(c, at, do_light);
    return pbrt_fail(&c->lx, at, "%s is not supported (docs/pbrt.md lists what is)", d);
}

int scene_pbrt_load(const char *path, scene_t *s, int *film_w, int *film_h, uint64_t *photons, char *err, size_t errlen)
{
    ctx_t *c = calloc(1, sizeof *c);
    if (!c) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    if (pbrt_lex_open(&c->lx, path, err, errlen)) { free(c); return -1; }
    c->s = s;
    c->g[0] = (gstate_t){.ctm = identity(), .material = -1};
    c->camera_from_world = identity();
    c->fov = 90;
    c->film_w = 1280;
    c->film_h = 720;
    c->maxdepth = 5;
    c->iterations = 64;
    c->per_iteration = -1;
    int rc = 0;
    pbrt_tok_t t;
    for (;;) {
        if ((rc = pbrt_lex_next(&c->lx, &t)) != 0 || t.kind == PT_EOF) break;
        if (t.kind != PT_WORD) { rc = pbrt_fail(&c->lx, &t, "expected a directive, found '%s'", t.text[0] ? t.text : "["); break; }
        if ((rc = directive(c, &t)) != 0) break;
    }
    if (rc == 0 && !c->world) rc = pbrt_fail(&c->lx, &t, "no WorldBegin");
    if (rc == 0) {
        mat4 wfc;
        inverse(c->camera_from_world, &wfc);
        camera_t *cam = &s->camera;
        cam->origin = to_scene(c, apply_point(&wfc, v3(0, 0, 0)));
        cam->dir = v3_norm(to_scene(c, apply_vector(&wfc, v3(0, 0, 1))));
        cam->up = to_scene(c, apply_vector(&wfc, v3(0, 1, 0)));
        cam->has_up = 1;
        /* fov spans the shorter image axis; scale is the vertical extent at unit distance. */
        const double t2 = 2.0 * tan(c->fov * PREE_PI / 360.0);
        cam->scale = c->film_w >= c->film_h ? t2 : t2 * c->film_h / c->film_w;
        s->max_depth = c->maxdepth + 1;
        *film_w = c->film_w;
        *film_h = c->film_h;
        *photons = (uint64_t)c->iterations *
                   (uint64_t)(c->per_iteration > 0 ? c->per_iteration : (long long)c->film_w * c->film_h);
    }
    pbrt_lex_close(&c->lx);
    free(c);
    return rc;
}
