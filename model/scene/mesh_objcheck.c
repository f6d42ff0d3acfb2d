// SPDX-License-Identifier: Apache-2.0
/* mesh_objcheck.c: line-numbered validation of OBJ and MTL text (see mesh_objcheck.h). */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mesh_objcheck.h"

#define MAX_TOK 64

typedef struct { char **v; size_t n, cap; } names_t;

static int names_add(names_t *s, const char *name)
{
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 16;
        char **v = realloc(s->v, cap * sizeof *v);
        if (!v) return -1;
        s->v = v;
        s->cap = cap;
    }
    s->v[s->n] = strdup(name);
    return s->v[s->n++] ? 0 : -1;
}

static int names_has(const names_t *s, const char *name)
{
    for (size_t i = 0; i < s->n; i++)
        if (!strcmp(s->v[i], name)) return 1;
    return 0;
}

static void names_free(names_t *s)
{
    for (size_t i = 0; i < s->n; i++) free(s->v[i]);
    free(s->v);
    memset(s, 0, sizeof *s);
}

static int fail(char *err, size_t errlen, const char *path, size_t line, const char *fmt, ...)
{
    char msg[300];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(err, errlen, "%s:%zu: %s", path, line, msg);
    return -1;
}

/* Split the next line of text (from *pos) into blank-separated tokens, in a copy. */
typedef struct { const mesh_blob_t *b; size_t pos, line; char buf[8192]; char *tok[MAX_TOK]; int ntok; } lines_t;

static int next_line(lines_t *L, int *too_long)
{
    *too_long = 0;
    if (L->pos >= L->b->size) return 0;
    const char *s = L->b->data + L->pos;
    const char *nl = memchr(s, '\n', L->b->size - L->pos);
    size_t len = nl ? (size_t)(nl - s) : L->b->size - L->pos;
    L->pos += len + (nl ? 1 : 0);
    L->line++;
    if (len >= sizeof L->buf) { *too_long = 1; len = sizeof L->buf - 1; }
    memcpy(L->buf, s, len);
    L->buf[len] = '\0';
    char *h = strchr(L->buf, '#');
    if (h) *h = '\0';
    L->ntok = 0;
    for (char *p = L->buf; *p;) {
        while (*p && isspace((unsigned char)*p)) p++;
        if (!*p) break;
        if (L->ntok < MAX_TOK) L->tok[L->ntok++] = p;
        while (*p && !isspace((unsigned char)*p)) p++;
        if (*p) *p++ = '\0';
    }
    return 1;
}

static int number(const char *t, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(t, &end);
    return end != t && *end == '\0';
}

/* 1..3 numbers after the keyword (a colour) or exactly one; finite and not negative. */
static int check_values(lines_t *L, const char *path, int min, int max, char *err, size_t errlen)
{
    int n = L->ntok - 1;
    if (n < min || n > max)
        return fail(err, errlen, path, L->line, "'%s' needs %d%s value%s, found %d", L->tok[0], min,
                    max > min ? " to 3" : "", max > 1 ? "s" : "", n);
    for (int k = 1; k <= n; k++) {
        double v;
        if (!number(L->tok[k], &v)) return fail(err, errlen, path, L->line, "'%s': malformed number '%s'", L->tok[0], L->tok[k]);
        if (!isfinite(v)) return fail(err, errlen, path, L->line, "'%s': value '%s' is not finite", L->tok[0], L->tok[k]);
        if (v < 0) return fail(err, errlen, path, L->line, "'%s': value '%s' is negative", L->tok[0], L->tok[k]);
    }
    return 0;
}

static int mtl_scan(const char *path, const mesh_blob_t *b, names_t *names, char *err, size_t errlen)
{
    lines_t L;
    memset(&L, 0, sizeof L);
    L.b = b;
    int too_long, have = 0, tex = 0, tex_line = 0;
    char tex_key[32] = "";
    static const char *colours[] = {"Ka", "Kd", "Ks", "Ke", "Tf"};
    static const char *textures[] = {"bump", "disp", "decal", "refl", "norm"};
    static const char *scalars[] = {"Ni", "Ns", "d", "Tr"};
    while (next_line(&L, &too_long)) {
        if (too_long) return fail(err, errlen, path, L.line, "line too long");
        if (L.ntok == 0) continue;
        const char *k = L.tok[0];
        if (!strcmp(k, "newmtl")) {
            if (L.ntok < 2) return fail(err, errlen, path, L.line, "'newmtl' needs a name");
            if (names_add(names, L.tok[1])) return fail(err, errlen, path, L.line, "out of memory");
            have = 1;
            continue;
        }
        int is_colour = 0, is_scalar = 0;
        for (size_t i = 0; i < sizeof colours / sizeof *colours; i++) is_colour |= !strcmp(k, colours[i]);
        for (size_t i = 0; i < sizeof scalars / sizeof *scalars; i++) is_scalar |= !strcmp(k, scalars[i]);
        int is_illum = !strcmp(k, "illum"), is_tex = !strncmp(k, "map_", 4);
        for (size_t i = 0; i < sizeof textures / sizeof *textures; i++) is_tex |= !strcmp(k, textures[i]);
        if (is_tex && !tex++) {
            tex_line = L.line;
            snprintf(tex_key, sizeof tex_key, "%s", k);
        }
        if (!is_colour && !is_scalar && !is_illum) continue;
        if (!have) return fail(err, errlen, path, L.line, "'%s' before any 'newmtl'", k);
        if (is_colour) {
            if (L.ntok >= 2 && (!strcmp(L.tok[1], "spectral") || !strcmp(L.tok[1], "xyz")))
                return fail(err, errlen, path, L.line, "'%s %s' colours are not supported", k, L.tok[1]);
            if (check_values(&L, path, 1, 3, err, errlen)) return -1;
        } else if (is_scalar) {
            if (check_values(&L, path, 1, 1, err, errlen)) return -1;
        } else {
            double v;
            if (L.ntok != 2 || !number(L.tok[1], &v) || v != floor(v) || v < 0 || v > 10)
                return fail(err, errlen, path, L.line, "'illum' needs an integer 0..10");
        }
    }
    if (tex)   /* never silent: the image differs from a textured renderer's */
        fprintf(stderr, "pree: warning: %s:%d: '%s': %d texture line%s ignored (PREE uses the constant colours Kd, "
                "Ks, Ke and Tf)\n", path, tex_line, tex_key, tex, tex > 1 ? "s" : "");
    return 0;
}

int mesh_mtl_check(const char *path, const mesh_blob_t *mtl, char *err, size_t errlen)
{
    names_t names = {0};
    int rc = mtl_scan(path, mtl, &names, err, errlen);
    names_free(&names);
    return rc;
}

/* One face reference "v", "v/t", "v//n" or "v/t/n"; indices 1-based or negative (relative). */
static int face_ref(const char *t, const size_t count[3], const char **what, long *bad)
{
    static const char *kinds[3] = {"vertex", "texture coordinate", "normal"};
    const char *p = t;
    for (int k = 0; k < 3; k++) {
        if (k > 0) {
            if (*p == '\0') return 0;
            if (*p != '/') { *what = "malformed"; return -1; }
            p++;
            if (*p == '/' || *p == '\0') continue;   /* empty texture (or trailing) index */
        }
        char *end;
        errno = 0;
        long v = strtol(p, &end, 10);
        if (end == p || errno) { *what = "malformed"; return -1; }
        p = end;
        long n = (long)count[k];
        long idx = v < 0 ? n + v + 1 : v;
        if (v == 0 || idx < 1 || idx > n) { *what = kinds[k]; *bad = v; return -1; }
    }
    return *p == '\0' ? 0 : (*what = "malformed", -1);
}

static void dir_of(const char *path, char *dir, size_t n)
{
    const char *s = strrchr(path, '/');
    if (!s) snprintf(dir, n, ".");
    else snprintf(dir, n, "%.*s", (int)(s - path), path);
}

int mesh_obj_check(const char *path, const mesh_blob_t *obj, int need_mtl, mesh_obj_counts_t *counts,
                   char *err, size_t errlen)
{
    lines_t L;
    memset(&L, 0, sizeof L);
    L.b = obj;
    names_t mats = {0};
    size_t count[3] = {0, 0, 0};   /* v, vt, vn */
    size_t faces = 0;
    char dir[4096];
    dir_of(path, dir, sizeof dir);
    int too_long, rc = 0;
    if (obj->size && memchr(obj->data, '\0', obj->size))
        return fail(err, errlen, path, 1, "binary data where OBJ text was expected");
    while (rc == 0 && next_line(&L, &too_long)) {
        if (too_long) { rc = fail(err, errlen, path, L.line, "line too long"); break; }
        if (L.ntok == 0) continue;
        const char *k = L.tok[0];
        if (!strcmp(k, "v") || !strcmp(k, "vn")) {
            if (L.ntok < 4) { rc = fail(err, errlen, path, L.line, "'%s' needs 3 coordinates", k); break; }
            for (int i = 1; i < 4 && rc == 0; i++) {
                double v;
                if (!number(L.tok[i], &v)) rc = fail(err, errlen, path, L.line, "malformed number '%s'", L.tok[i]);
                else if (!isfinite(v)) rc = fail(err, errlen, path, L.line, "coordinate '%s' is not finite", L.tok[i]);
            }
            count[k[1] == 'n' ? 2 : 0]++;
        } else if (!strcmp(k, "vt")) {
            count[1]++;
        } else if (!strcmp(k, "f")) {
            if (L.ntok < 4) { rc = fail(err, errlen, path, L.line, "a face needs at least 3 vertices"); break; }
            for (int i = 1; i < L.ntok && rc == 0; i++) {
                const char *what = NULL;
                long bad = 0;
                if (face_ref(L.tok[i], count, &what, &bad)) {
                    if (!strcmp(what, "malformed")) rc = fail(err, errlen, path, L.line, "malformed face reference '%s'", L.tok[i]);
                    else rc = fail(err, errlen, path, L.line, "face refers to %s %ld, but %zu are defined", what, bad,
                                   count[!strcmp(what, "vertex") ? 0 : !strcmp(what, "normal") ? 2 : 1]);
                }
            }
            faces++;
        } else if (!strcmp(k, "mtllib") && need_mtl) {
            for (int i = 1; i < L.ntok && rc == 0; i++) {
                char mp[8192];
                if (strchr(path, '/')) snprintf(mp, sizeof mp, "%s/%s", dir, L.tok[i]);
                else snprintf(mp, sizeof mp, "%s", L.tok[i]);
                mesh_blob_t m;
                char e[512];
                if (mesh_read_file(mp, &m, e, sizeof e)) { rc = fail(err, errlen, path, L.line, "material library: %s", e); break; }
                rc = mtl_scan(mp, &m, &mats, err, errlen);
                mesh_blob_free(&m);
            }
        } else if (!strcmp(k, "usemtl") && need_mtl) {
            if (L.ntok < 2) rc = fail(err, errlen, path, L.line, "'usemtl' needs a name");
            else if (!names_has(&mats, L.tok[1]))
                rc = fail(err, errlen, path, L.line, "material '%s' is not defined by a preceding mtllib", L.tok[1]);
        }
    }
    names_free(&mats);
    if (rc) return -1;
    if (counts) { counts->vertices = count[0]; counts->faces = faces; counts->normals = count[2]; }
    return 0;
}
