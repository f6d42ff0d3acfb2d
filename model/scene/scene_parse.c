// SPDX-License-Identifier: Apache-2.0
/* scene_parse.c: the text scene format (docs/scene_format.md): one directive per line,
 * '#' starts a comment. Every error names FILE:LINE and what was wrong. */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene.h"
#include "mesh_load.h"
#include "scene_pbrt.h"
#include "mesh_light.h"
#include "file_in.h"
#include "text_escape.h"

#define MAX_TOKENS 64
#define SCENE_LINE_MAX (1 << 20)   /* bytes in one line, comments included */

typedef struct {
    const char *file;
    int line;
    char *err;
    size_t errlen;
    int camera_line, depth_line, epsilon_line;   /* where each singleton was given, or 0 */
} parse_ctx_t;

static int fail(parse_ctx_t *pc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    text_error_at(pc->err, pc->errlen, pc->file, pc->line, fmt, ap);   /* line 0: the whole file */
    va_end(ap);
    return -1;
}

static int once(parse_ctx_t *pc, int *seen, const char *what)
{
    if (*seen) return fail(pc, "%s is given twice (first on line %d)", what, *seen);
    *seen = pc->line;
    return 0;
}

/* Fail when a directive has values after its last one. */
static int no_more(parse_ctx_t *pc, char **tok, int ntok, int n, const char *what)
{
    if (ntok > n) return fail(pc, "%s: unexpected '%s'", what, tok[n]);
    return 0;
}

/* A number, or a sum "A+B" / "A-B" of two numbers evaluated in double (so that the
 * reference program's "-1e5+81.6" keeps its exact rounding). Rejects NaN and infinity. */
static int parse_number(parse_ctx_t *pc, const char *tok, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(tok, &end);
    if (end == tok) return fail(pc, "expected a number, found '%s'", tok);
    if (*end == '+' || *end == '-') {
        const char *rest = end;
        double w = strtod(rest, &end);
        if (end == rest) return fail(pc, "malformed number '%s'", tok);
        v = v + w;
    }
    if (*end != '\0') return fail(pc, "malformed number '%s'", tok);
    if (!isfinite(v)) return fail(pc, "number '%s' is not finite", tok);
    *out = v;
    return 0;
}

/* A number of magnitude at most SCENE_COORD_MAX: a coordinate, radius or distance. */
static int parse_coord(parse_ctx_t *pc, const char *tok, double *out)
{
    if (parse_number(pc, tok, out)) return -1;
    if (fabs(*out) > SCENE_COORD_MAX)
        return fail(pc, "value '%s' lies beyond +-%g, the range the tracer and binary32 hold", tok, SCENE_COORD_MAX);
    return 0;
}

/* Three numbers; bounded by SCENE_COORD_MAX unless raw (light power: docs/scene_format.md). */
static int parse_vec3(parse_ctx_t *pc, char **tok, int raw, vec3 *out)
{
    double v[3];
    for (int k = 0; k < 3; k++)
        if (raw ? parse_number(pc, tok[k], &v[k]) : parse_coord(pc, tok[k], &v[k])) return -1;
    *out = v3(v[0], v[1], v[2]);
    return 0;
}

static int parse_vec(parse_ctx_t *pc, char **tok, vec3 *out) { return parse_vec3(pc, tok, 0, out); }

/* Light power R G B: not negative, and finite after scale (intensity * 4 pi). */
static int parse_power(parse_ctx_t *pc, char **tok, double scale, vec3 *out)
{
    vec3 v;
    if (parse_vec3(pc, tok, 1, &v)) return -1;
    if (v.x < 0 || v.y < 0 || v.z < 0) return fail(pc, "light power must not be negative");
    *out = v3_scale(v, scale);
    if (!v3_is_finite(*out)) return fail(pc, "light power %s %s %s overflows double", tok[0], tok[1], tok[2]);
    return 0;
}

static int need(parse_ctx_t *pc, int ntok, int n, const char *usage)
{
    if (ntok < n) return fail(pc, "too few values; expected: %s", usage);
    return 0;
}

static void *grow(void *p, int count, size_t elem)
{
    return realloc(p, (size_t)(count + 1) * elem);
}

static int material_ref(parse_ctx_t *pc, const scene_t *s, const char *name, int *out)
{
    int id = scene_find_material(s, name);
    if (id < 0) return fail(pc, "unknown material '%s' (define it with 'material' first)", name);
    *out = id;
    return 0;
}

/* camera origin X Y Z dir X Y Z scale S near D [up X Y Z]
 * camera position X Y Z lookat X Y Z up X Y Z fov DEGREES [near D] */
static int parse_camera(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    camera_t c = {0};
    if (once(pc, &pc->camera_line, "camera")) return -1;
    int have_origin = 0, have_dir = 0, have_scale = 0;
    for (int i = 1; i < ntok;) {
        const char *key = tok[i];
        if ((!strcmp(key, "origin") || !strcmp(key, "position")) && i + 3 < ntok) {
            if (parse_vec(pc, tok + i + 1, &c.origin)) return -1;
            have_origin = 1; i += 4;
        } else if (!strcmp(key, "dir") && i + 3 < ntok) {
            if (parse_vec(pc, tok + i + 1, &c.dir)) return -1;
            have_dir = 1; i += 4;
        } else if (!strcmp(key, "lookat") && i + 3 < ntok) {
            vec3 target;
            if (parse_vec(pc, tok + i + 1, &target)) return -1;
            c.dir = v3_sub(target, c.origin);
            if (!have_origin) return fail(pc, "camera: give 'position' before 'lookat'");
            have_dir = 1; i += 4;
        } else if (!strcmp(key, "up") && i + 3 < ntok) {
            if (parse_vec(pc, tok + i + 1, &c.up)) return -1;
            c.has_up = 1; i += 4;
        } else if (!strcmp(key, "scale") && i + 1 < ntok) {
            if (parse_number(pc, tok[i + 1], &c.scale)) return -1;
            if (!(c.scale > 0)) return fail(pc, "camera: scale must be positive");
            have_scale = 1; i += 2;
        } else if (!strcmp(key, "fov") && i + 1 < ntok) {
            double deg;
            if (parse_number(pc, tok[i + 1], &deg)) return -1;
            if (!(deg > 0 && deg < 180)) return fail(pc, "camera: fov %g is not in (0, 180) degrees", deg);
            c.scale = 2.0 * tan(deg * PREE_PI / 360.0);
            have_scale = 1; i += 2;
        } else if (!strcmp(key, "near") && i + 1 < ntok) {
            if (parse_coord(pc, tok[i + 1], &c.near)) return -1;
            i += 2;
        } else {
            return fail(pc, "camera: unexpected '%s'", key);
        }
    }
    if (!have_origin || !have_dir || !have_scale)
        return fail(pc, "camera needs an origin (or position), a dir (or lookat) and a scale (or fov)");
    if (v3_dot(c.dir, c.dir) == 0) return fail(pc, "camera: the view direction is zero");
    if (c.has_up && v3_dot(v3_cross(c.dir, c.up), v3_cross(c.dir, c.up)) == 0)
        return fail(pc, "camera: 'up' is parallel to the view direction");
    if (!(c.scale >= SCENE_SCALE_MIN && c.scale <= SCENE_SCALE_MAX))
        return fail(pc, "camera: scale %g is not in [%g, %g] (a fov gives scale 2 tan(fov/2))", c.scale,
                    SCENE_SCALE_MIN, SCENE_SCALE_MAX);
    if (c.near < 0) return fail(pc, "camera: near must not be negative");
    s->camera = c;
    return 1;
}

/* material NAME diffuse|mirror|glass R G B [ior N] */
static int parse_material(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    if (need(pc, ntok, 6, "material NAME diffuse|mirror|glass R G B [ior N]")) return -1;
    material_t m = {0};
    if (strlen(tok[1]) >= sizeof m.name) return fail(pc, "material name '%s' is too long", tok[1]);
    strcpy(m.name, tok[1]);
    if (!strcmp(tok[2], "diffuse")) m.kind = MAT_DIFFUSE;
    else if (!strcmp(tok[2], "mirror")) m.kind = MAT_MIRROR;
    else if (!strcmp(tok[2], "glass")) m.kind = MAT_GLASS;
    else return fail(pc, "material '%s': unknown kind '%s' (diffuse, mirror or glass)", m.name, tok[2]);
    if (parse_vec(pc, tok + 3, &m.colour)) return -1;
    if (m.colour.x < 0 || m.colour.y < 0 || m.colour.z < 0 || m.colour.x > 1 || m.colour.y > 1 || m.colour.z > 1)
        return fail(pc, "material '%s': colour components must lie in [0, 1]", m.name);
    m.ior = 1.5;
    int i = 6;
    if (i < ntok && !strcmp(tok[i], "ior")) {
        if (m.kind != MAT_GLASS) return fail(pc, "material '%s': 'ior' applies to glass only", m.name);
        if (i + 1 >= ntok) return fail(pc, "material '%s': 'ior' needs a value", m.name);
        if (parse_number(pc, tok[i + 1], &m.ior)) return -1;
        if (!(m.ior >= 1.0 && m.ior <= 10.0)) return fail(pc, "material '%s': ior %g is not in [1, 10]", m.name, m.ior);
        i += 2;
    }
    if (i != ntok) return fail(pc, "material '%s': unexpected '%s'", m.name, tok[i]);
    char e[256];
    if (scene_add_material(s, &m, e, sizeof e) < 0) return fail(pc, "%s", e);
    return 1;
}

/* sphere RADIUS X Y Z MATERIAL */
static int parse_sphere(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    if (need(pc, ntok, 6, "sphere RADIUS X Y Z MATERIAL") ) return -1;
    if (no_more(pc, tok, ntok, 6, "sphere")) return -1;
    sphere_t sp;
    if (parse_coord(pc, tok[1], &sp.radius) || parse_vec(pc, tok + 2, &sp.centre)) return -1;
    if (!(sp.radius > 0)) return fail(pc, "sphere radius must be positive");
    if (material_ref(pc, s, tok[5], &sp.material)) return -1;
    sphere_t *arr = grow(s->spheres, s->num_spheres, sizeof *arr);
    if (!arr) return fail(pc, "out of memory");
    s->spheres = arr;
    arr[s->num_spheres++] = sp;
    return 1;
}

/* light triangle X Y Z X Y Z X Y Z radiance|flux R G B: one emitting triangle (front face =
 * counter-clockwise side); it is a light only, not geometry. */
static int parse_light_triangle(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    if (need(pc, ntok, 15, "light triangle X Y Z X Y Z X Y Z radiance|flux R G B")) return -1;
    if (no_more(pc, tok, ntok, 15, "light")) return -1;
    vec3 p[3], v;
    for (int k = 0; k < 3; k++)
        if (parse_vec(pc, tok + 2 + 3 * k, &p[k])) return -1;
    if (parse_power(pc, tok + 12, 1.0, &v)) return -1;
    int is_flux;
    if (!strcmp(tok[11], "radiance")) is_flux = 0;
    else if (!strcmp(tok[11], "flux")) is_flux = 1;
    else return fail(pc, "light: expected 'radiance' or 'flux', found '%s'", tok[11]);
    char e[256];
    if (mesh_light_add(s, p, 1, v, is_flux, e, sizeof e)) return fail(pc, "%s", e);
    return 1;
}

/* light point X Y Z intensity R G B   (flux = intensity * 4 pi)
 * light point X Y Z flux R G B
 * light triangle X Y Z X Y Z X Y Z radiance|flux R G B   (area light, docs: "Lights") */
static int parse_light(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    if (ntok >= 2 && !strcmp(tok[1], "triangle")) return parse_light_triangle(pc, s, tok, ntok);
    const char *usage = "light point X Y Z intensity|flux R G B";
    if (need(pc, ntok, 9, usage)) return -1;
    if (strcmp(tok[1], "point")) return fail(pc, "unknown light kind '%s' (point or triangle)", tok[1]);
    if (no_more(pc, tok, ntok, 9, "light")) return -1;
    light_t l;
    memset(&l, 0, sizeof l);
    l.kind = LIGHT_POINT;
    int is_flux = !strcmp(tok[5], "flux");
    if (!is_flux && strcmp(tok[5], "intensity"))
        return fail(pc, "light: expected 'intensity' or 'flux', found '%s'", tok[5]);
    if (parse_vec(pc, tok + 2, &l.position) || parse_power(pc, tok + 6, is_flux ? 1.0 : PREE_PI * 4.0, &l.flux))
        return -1;
    light_t *arr = grow(s->lights, s->num_lights, sizeof *arr);
    if (!arr) return fail(pc, "out of memory");
    s->lights = arr;
    arr[s->num_lights++] = l;
    return 1;
}

/* triangle X Y Z X Y Z X Y Z MATERIAL: one inline triangle (collected into one mesh). */
static int parse_triangle(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    if (need(pc, ntok, 11, "triangle X Y Z X Y Z X Y Z MATERIAL")) return -1;
    if (no_more(pc, tok, ntok, 11, "triangle")) return -1;
    vec3 p[3];
    int mat = -1;
    for (int k = 0; k < 3; k++)
        if (parse_vec(pc, tok + 1 + 3 * k, &p[k])) return -1;
    if (material_ref(pc, s, tok[10], &mat)) return -1;
    vec3 n = v3_cross(v3_sub(p[1], p[0]), v3_sub(p[2], p[0]));
    if (v3_dot(n, n) == 0) return fail(pc, "triangle is degenerate (zero area)");
    char e[256];
    if (mesh_append_triangle(s, p, mat, e, sizeof e)) return fail(pc, "%s", e);
    return 1;
}

static int parse_depth(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    double d;
    if (need(pc, ntok, 2, "depth N") || no_more(pc, tok, ntok, 2, "depth") || once(pc, &pc->depth_line, "depth"))
        return -1;
    if (parse_number(pc, tok[1], &d)) return -1;
    if (d != floor(d) || d < 1 || d > 20)
        return fail(pc, "depth %s is not an integer in 1..20 (the Halton dimensions end at 61)", tok[1]);
    s->max_depth = (int)d;
    return 1;
}

static int parse_epsilon(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    double e;
    if (need(pc, ntok, 2, "epsilon E") || no_more(pc, tok, ntok, 2, "epsilon") ||
        once(pc, &pc->epsilon_line, "epsilon"))
        return -1;
    if (parse_number(pc, tok[1], &e)) return -1;
    if (!(e > 0 && e <= 1e30)) return fail(pc, "epsilon %s is not a positive distance up to 1e30", tok[1]);
    s->epsilon = e;
    return 1;
}

static int parse_mesh(parse_ctx_t *pc, scene_t *s, char **tok, int ntok)
{
    char e[512];
    if (need(pc, ntok, 2, "mesh FILE [options]")) return -1;
    if (mesh_load_directive(s, pc->file, tok + 1, ntok - 1, e, sizeof e)) return fail(pc, "%s", e);
    return 1;
}

typedef int (*directive_fn)(parse_ctx_t *, scene_t *, char **, int);
static const struct { const char *name; directive_fn fn; } directives[] = {
    {"camera", parse_camera},     {"material", parse_material}, {"sphere", parse_sphere},
    {"light", parse_light},       {"triangle", parse_triangle}, {"mesh", parse_mesh},
    {"depth", parse_depth},       {"epsilon", parse_epsilon},
};

static int tokenize(char *line, char **tok)
{
    int n = 0;
    char *p = line;
    while (*p) {
        while (*p && isspace((unsigned char)*p)) p++;
        if (!*p || *p == '#') break;
        if (n == MAX_TOKENS) return -1;
        tok[n++] = p;
        while (*p && !isspace((unsigned char)*p)) p++;
        if (*p) *p++ = '\0';
    }
    return n;
}

static int scene_validate(parse_ctx_t *pc, scene_t *s)
{
    if (s->camera.scale == 0) return fail(pc, "the scene has no camera");
    if (s->num_lights == 0) return fail(pc, "the scene has no light");
    if (s->num_spheres == 0 && s->num_meshes == 0) return fail(pc, "the scene has no geometry");
    for (int i = 0; i < s->num_materials; i++) {
        s->has_mirror |= s->materials[i].kind == MAT_MIRROR;
        s->has_glass |= s->materials[i].kind == MAT_GLASS;
        s->has_diffuse |= s->materials[i].kind == MAT_DIFFUSE;
    }
    return 0;
}

int scene_load(const char *path, scene_t *out, char *err, size_t errlen)
{
    parse_ctx_t pc = {path, 0, err, errlen, 0, 0, 0};
    scene_t s;
    memset(&s, 0, sizeof s);
    snprintf(s.path, sizeof s.path, "%s", path);
    s.max_depth = 20;
    s.epsilon = 1e-4;   /* TRACER_EPSILON: the reference program's */
    const size_t plen = strlen(path);
    if (plen > 5 && !strcmp(path + plen - 5, ".pbrt")) {
        int rc = scene_pbrt_load(path, &s, &s.film_width, &s.film_height, &s.film_photons, err, errlen);
        if (rc == 0) rc = scene_validate(&pc, &s);   /* errors name the file alone (line 0) */
        if (rc) { scene_free(&s); return -1; }
        *out = s;
        return 0;
    }
    FILE *f = file_in_open(path, PREE_INPUT_MAX_BYTES, err, errlen);
    if (!f) return -1;
    char *line = NULL;
    size_t cap = 0;
    ssize_t got;
    char *tok[MAX_TOKENS];
    int rc = 0;
    while ((got = getline(&line, &cap, f)) >= 0) {
        pc.line++;
        /* getline gives the true length, so a NUL byte inside the line is seen (strlen would
         * stop at it and drop the rest of the line). */
        if (got > SCENE_LINE_MAX) { rc = fail(&pc, "line longer than %d bytes", SCENE_LINE_MAX); break; }
        if (strlen(line) != (size_t)got) { rc = fail(&pc, "binary data (a NUL byte)"); break; }
        /* A UTF-8 byte-order mark (as some editors write) before the first line is skipped. */
        size_t bom = pc.line == 1 && !strncmp(line, "\xEF\xBB\xBF", 3) ? 3 : 0;
        int ntok = tokenize(line + bom, tok);
        if (ntok < 0) { rc = fail(&pc, "too many values on one line"); break; }
        if (ntok == 0) continue;
        size_t d;
        for (d = 0; d < sizeof directives / sizeof directives[0]; d++)
            if (!strcmp(tok[0], directives[d].name)) break;
        if (d == sizeof directives / sizeof directives[0]) { rc = fail(&pc, "unknown directive '%s'", tok[0]); break; }
        if (directives[d].fn(&pc, &s, tok, ntok) < 0) { rc = -1; break; }
    }
    if (rc == 0 && ferror(f)) { pc.line = 0; rc = fail(&pc, "read error"); }
    free(line);
    fclose(f);
    if (rc == 0) { pc.line++; rc = scene_validate(&pc, &s); }
    if (rc) { scene_free(&s); return -1; }
    *out = s;
    return 0;
}

void scene_free(scene_t *s)
{
    for (int i = 0; i < s->num_meshes; i++) mesh_free(&s->meshes[i]);
    free(s->meshes);
    scene_materials_free(s);
    free(s->light_cdf);
    free(s->spheres);
    for (int i = 0; i < s->num_lights; i++) free(s->lights[i].tris);
    free(s->lights);
    memset(s, 0, sizeof *s);
}
