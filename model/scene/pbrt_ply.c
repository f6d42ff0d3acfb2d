// SPDX-License-Identifier: Apache-2.0
/* pbrt_ply.c: PLY triangles for pbrt's plymesh (pbrt_ply.h). Every element and property of the
 * header is read (others than vertex and face are skipped), in ASCII or binary. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "file_in.h"
#include "pbrt_ply.h"

#define PLY_PROPS 32
#define PLY_ELEMS 8

typedef struct { char name[64]; int type, list, count_type; } prop_t;
typedef struct { char name[64]; size_t n; prop_t p[PLY_PROPS]; int np; } elem_t;

/* Type by name: its size in bytes (1, 2, 4, 8), with a flag for signed and float; 0 unknown. */
static int type_of(const char *s)
{
    static const struct { const char *name; int code; } t[] = {
        {"char", 0x11}, {"int8", 0x11}, {"uchar", 0x01}, {"uint8", 0x01}, {"short", 0x12}, {"int16", 0x12},
        {"ushort", 0x02}, {"uint16", 0x02}, {"int", 0x14}, {"int32", 0x14}, {"uint", 0x04}, {"uint32", 0x04},
        {"float", 0x24}, {"float32", 0x24}, {"double", 0x28}, {"float64", 0x28}};
    for (size_t k = 0; k < sizeof t / sizeof *t; k++)
        if (!strcmp(s, t[k].name)) return t[k].code;
    return 0;
}

typedef struct { const unsigned char *p, *end; int ascii, swap; } rd_t;

/* One value of type code: 0, or -1 at the end of the data or on bad text. */
static int value(rd_t *r, int code, double *out)
{
    if (r->ascii) {
        while (r->p < r->end && (*r->p == ' ' || *r->p == '\n' || *r->p == '\r' || *r->p == '\t')) r->p++;
        if (r->p == r->end) return -1;
        char buf[64];
        size_t n = 0;
        while (r->p < r->end && n < sizeof buf - 1 && !strchr(" \n\r\t", *r->p)) buf[n++] = (char)*r->p++;
        buf[n] = 0;
        char *e;
        *out = strtod(buf, &e);
        return *e ? -1 : 0;
    }
    const int size = code & 0xf;
    if (r->end - r->p < size) return -1;
    unsigned char b[8];
    for (int k = 0; k < size; k++) b[k] = r->p[r->swap ? size - 1 - k : k];
    r->p += size;
    if (code & 0x20) {
        if (size == 4) { float f; memcpy(&f, b, 4); *out = f; }
        else { double d; memcpy(&d, b, 8); *out = d; }
        return 0;
    }
    uint64_t u = 0;
    memcpy(&u, b, (size_t)size);   /* little-endian host */
    if ((code & 0x10) && size < 8 && (u >> (8 * size - 1)) & 1) u |= ~0ull << (8 * size);
    *out = (code & 0x10) ? (double)(int64_t)u : (double)u;
    return 0;
}

int pbrt_ply_read(const char *path, pbrt_ply_t *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    FILE *f = file_in_open(path, 1LL << 32, err, errlen);
    if (!f) return -1;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *data = len > 0 ? malloc((size_t)len + 1) : NULL;
    if (!data || fread(data, 1, (size_t)len, f) != (size_t)len) {
        fclose(f);
        free(data);
        snprintf(err, errlen, "%s: %s", path, len <= 0 ? "empty" : "cannot read it");
        return -1;
    }
    fclose(f);
    data[len] = 0;
    elem_t el[PLY_ELEMS];
    int ne = 0, ascii = 0, swap = 0;
    const char *why = NULL;
    char *line = (char *)data, *next;
    unsigned char *body = NULL;
    for (int first = 1; line && line < (char *)data + len; line = next, first = 0) {
        next = strchr(line, '\n');
        if (next) *next++ = 0;
        char w[4][64] = {{0}};
        const int nw = sscanf(line, "%63s %63s %63s %63s", w[0], w[1], w[2], w[3]);
        if (first && strcmp(w[0], "ply")) { why = "not a PLY file"; break; }
        if (nw <= 0 || first || !strcmp(w[0], "comment") || !strcmp(w[0], "obj_info")) continue;
        if (!strcmp(w[0], "format")) {
            ascii = !strcmp(w[1], "ascii");
            swap = !strcmp(w[1], "binary_big_endian");
            if (!ascii && !swap && strcmp(w[1], "binary_little_endian")) { why = "an unknown format"; break; }
        } else if (!strcmp(w[0], "element")) {
            if (ne == PLY_ELEMS) { why = "too many elements"; break; }
            elem_t *e = &el[ne++];
            memset(e, 0, sizeof *e);
            snprintf(e->name, sizeof e->name, "%s", w[1]);
            e->n = strtoull(w[2], NULL, 10);
        } else if (!strcmp(w[0], "property")) {
            if (!ne || el[ne - 1].np == PLY_PROPS) { why = "a property outside an element"; break; }
            prop_t *p = &el[ne - 1].p[el[ne - 1].np++];
            p->list = !strcmp(w[1], "list");
            p->count_type = p->list ? type_of(w[2]) : 0;
            p->type = type_of(p->list ? w[3] : w[1]);
            char name[64] = "";
            sscanf(line, p->list ? "%*s %*s %*s %*s %63s" : "%*s %*s %63s", name);
            snprintf(p->name, sizeof p->name, "%s", name);
            if (!p->type || (p->list && !p->count_type)) { why = "a property of an unknown type"; break; }
        } else if (!strcmp(w[0], "end_header")) {
            body = (unsigned char *)next;
            break;
        } else {
            why = "an unknown header line";
            break;
        }
    }
    if (!why && !body) why = "no end_header";
    rd_t r = {body, data + len, ascii, swap};
    for (int k = 0; !why && k < ne; k++) {
        elem_t *e = &el[k];
        const int vert = !strcmp(e->name, "vertex"), face = !strcmp(e->name, "face");
        if (vert) {
            out->num_points = e->n;
            out->points = calloc(3 * e->n + 3, sizeof *out->points);
            for (int i = 0; i < e->np; i++)
                if (!strcmp(e->p[i].name, "nx")) out->normals = calloc(3 * e->n + 3, sizeof *out->normals);
            if (!out->points || e->n > 1u << 28) { why = "too many vertices"; break; }
        }
        if (face && !(out->indices = malloc((2 * e->n + 1) * 3 * sizeof *out->indices))) { why = "out of memory"; break; }
        for (size_t i = 0; !why && i < e->n; i++) {
            for (int j = 0; !why && j < e->np; j++) {
                const prop_t *p = &e->p[j];
                double v, cnt = 1, idx[4];
                if (p->list && value(&r, p->count_type, &cnt)) { why = "the data ends early"; break; }
                const int is_idx = face && (!strcmp(p->name, "vertex_indices") || !strcmp(p->name, "vertex_index"));
                if (is_idx && cnt != 3 && cnt != 4) { why = "a face of other than 3 or 4 vertices"; break; }
                for (int q = 0; q < (int)cnt; q++) {
                    if (value(&r, p->type, &v)) { why = "the data ends early or holds a bad number"; break; }
                    if (is_idx) idx[q] = v;
                    if (vert) {
                        static const char *const names[6] = {"x", "y", "z", "nx", "ny", "nz"};
                        for (int a = 0; a < 6; a++)
                            if (!strcmp(p->name, names[a])) (a < 3 ? out->points : out->normals)[3 * i + a % 3] = v;
                    }
                }
                if (is_idx && !why) {
                    double *t = out->indices + 3 * out->num_triangles;
                    t[0] = idx[0]; t[1] = idx[1]; t[2] = idx[2];
                    out->num_triangles++;
                    if (cnt == 4) { t[3] = idx[0]; t[4] = idx[2]; t[5] = idx[3]; out->num_triangles++; }
                }
            }
        }
    }
    free(data);
    if (!why && (!out->points || !out->num_triangles)) why = "no vertices or no faces";
    if (why) {
        snprintf(err, errlen, "%s: %s", path, why);
        pbrt_ply_free(out);
        return -1;
    }
    return 0;
}

void pbrt_ply_free(pbrt_ply_t *p)
{
    free(p->points);
    free(p->normals);
    free(p->indices);
    memset(p, 0, sizeof *p);
}
