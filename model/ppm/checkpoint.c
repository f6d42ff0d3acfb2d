// SPDX-License-Identifier: Apache-2.0
/* checkpoint.c: the render state on disk (checkpoint.h): fingerprint, atomic write, checked read.
 *
 * Layout (native byte order; the fingerprint covers the build, so a file is read only by the
 * build that wrote it): magic, fingerprint, hit points n, photons done, the pass counters, the
 * note's length and bytes, then each state array in address order, then the FNV-1a of every
 * byte before it. */
#include <errno.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "checkpoint.h"
#include "fnv1a.h"

static const char MAGIC[8] = {'P', 'R', 'E', 'E', 'C', 'K', 'P', '2'};
static const char MAGIC_OLD[8] = {'P', 'R', 'E', 'E', 'C', 'K', 'P', '1'};   /* no note */
#define FNV_BASIS FNV1A_BASIS
#define HASH(f, x) ((f) = fnv1a((f), &(x), sizeof(x)))
#define HASH_N(f, p, n) ((f) = fnv1a((f), (p), (n) * sizeof *(p)))

static uint64_t scene_hash(uint64_t f, const scene_t *sc)
{
    const camera_t *c = &sc->camera;
    HASH(f, c->origin); HASH(f, c->dir); HASH(f, c->scale); HASH(f, c->near); HASH(f, c->has_up); HASH(f, c->up);
    for (int i = 0; i < sc->num_materials; i++) {
        HASH(f, sc->materials[i].kind); HASH(f, sc->materials[i].colour); HASH(f, sc->materials[i].ior);
    }
    for (int i = 0; i < sc->num_spheres; i++) {
        HASH(f, sc->spheres[i].radius); HASH(f, sc->spheres[i].centre); HASH(f, sc->spheres[i].material);
    }
    for (int i = 0; i < sc->num_meshes; i++) {
        const mesh_t *m = &sc->meshes[i];
        HASH_N(f, m->vertices, 3 * m->num_vertices);
        if (m->normals) HASH_N(f, m->normals, 3 * m->num_vertices);
        HASH_N(f, m->indices, 3 * m->num_triangles);
        HASH_N(f, m->tri_material, m->num_triangles);
    }
    for (int i = 0; i < sc->num_lights; i++) {
        const light_t *l = &sc->lights[i];
        HASH(f, l->kind); HASH(f, l->position); HASH(f, l->flux); HASH(f, l->area);
        if (l->num_tris) HASH_N(f, l->tris, l->num_tris);
    }
    if (sc->light_cdf) HASH_N(f, sc->light_cdf, (size_t)sc->num_lights);
    HASH(f, sc->max_depth);
    HASH(f, sc->epsilon);
    if (sc->max_bounces) HASH(f, sc->max_bounces);
    return f;
}

uint64_t checkpoint_fingerprint(const scene_t *scene, const render_options_t *opt, const hitpoints_t *h)
{
    /* The build: format, state layout, compiler. */
    static const char build[] = "pree checkpoint 2; compiler " __VERSION__;
    const size_t sizes[3] = {sizeof(preu_hp_t), sizeof(preu_shp_t), sizeof(hp_hot_t)};
    uint64_t f = fnv1a(FNV_BASIS, build, sizeof build);
    HASH(f, sizes);
    /* The options that change the bits (not --photons: a resume may extend a render). */
    const double alpha = render_alpha(opt);
    const int o[10] = {opt->width, opt->height, (int)opt->precision, (int)opt->datapath, (int)opt->grid, opt->no_skip,
                       opt->preu ? opt->preu : 4, opt->pipe_fast, (int)opt->layout, opt->prees > 1 ? opt->prees : 1};
    HASH(f, o);
    HASH(f, alpha);
    HASH(f, opt->photon_offset);
    f = scene_hash(f, scene);
    for (size_t i = 0; i < h->n; i++) {
        const hp_hot_t *p = &h->hot[i];
        const double g[6] = {p->px, p->py, p->pz, p->nx, p->ny, p->nz};
        HASH(f, g); HASH(f, h->weight[i]); HASH(f, h->pixel[i]);
    }
    return f;
}

/* One state array: element k of index i at base + i * stride, size bytes. */
typedef struct { void *base; size_t stride, size; } state_array_t;

static int state_arrays(const hitpoints_t *h, precision_t prec, state_array_t a[3])
{
    if (prec != PRECISION_FP32) {
        a[0] = (state_array_t){h->r2, sizeof *h->r2, sizeof *h->r2};
        a[1] = (state_array_t){&h->acc->flux, sizeof *h->acc, sizeof h->acc->flux};
        a[2] = (state_array_t){&h->acc->count, sizeof *h->acc, sizeof h->acc->count};
        return 3;
    }
    if (h->stable) a[0] = (state_array_t){h->stable, sizeof *h->stable, sizeof *h->stable};
    else a[0] = (state_array_t){h->fp32, sizeof *h->fp32, sizeof *h->fp32};
    a[1] = (state_array_t){h->r2_f32, sizeof *h->r2_f32, sizeof *h->r2_f32};
    return 2;
}

/* The header's words after the magic, in file order. */
#define HEADER_WORDS 10
static void pack(const checkpoint_info_t *in, uint64_t n, uint64_t w[HEADER_WORDS])
{
    const uint64_t v[HEADER_WORDS] = {in->fingerprint, n, in->done_photons, in->photon_hits, in->photon_segments,
                                      in->no_cell, in->upd.candidates, in->upd.skipped_radius, in->upd.normal_passed,
                                      in->upd.accepted};
    memcpy(w, v, sizeof v);
}

static void unpack(const uint64_t w[HEADER_WORDS], checkpoint_info_t *in, uint64_t *n)
{
    *in = (checkpoint_info_t){.fingerprint = w[0], .done_photons = w[2], .photon_hits = w[3], .photon_segments = w[4],
                              .no_cell = w[5], .upd = {w[6], w[7], w[8], w[9]}};
    *n = w[1];
}

/* Address -> photon-pass index. */
static uint32_t *inverse(const uint32_t *perm, size_t n)
{
    uint32_t *inv = malloc((n ? n : 1) * sizeof *inv);
    if (inv) for (size_t i = 0; i < n; i++) inv[perm[i]] = (uint32_t)i;
    return inv;
}

typedef struct { FILE *f; uint64_t hash; int ok; } stream_t;

static void put(stream_t *s, const void *p, size_t n)
{
    s->hash = fnv1a(s->hash, p, n);
    if (s->ok && fwrite(p, 1, n, s->f) != n) s->ok = 0;
}

static void get(stream_t *s, void *p, size_t n)
{
    if (!s->ok) return;
    if (fread(p, 1, n, s->f) != n) { s->ok = 0; return; }
    s->hash = fnv1a(s->hash, p, n);
}

static void temp_name(char *tmp, size_t len, const char *path)
{
    snprintf(tmp, len, "%s.tmp.%ld", path, (long)getpid());
}

int checkpoint_probe(const char *path, char *err, size_t errlen)
{
    char tmp[4200];
    temp_name(tmp, sizeof tmp, path);
    FILE *f = fopen(tmp, "wb");
    if (!f) { snprintf(err, errlen, "%s: cannot write a checkpoint here: %s", path, strerror(errno)); return -1; }
    fclose(f);
    unlink(tmp);
    return 0;
}

int checkpoint_save(const char *path, const checkpoint_info_t *info, const hitpoints_t *h, const uint32_t *perm,
                    precision_t prec, char *err, size_t errlen)
{
    char tmp[4200];
    temp_name(tmp, sizeof tmp, path);
    uint32_t *inv = inverse(perm, h->n);
    if (!inv) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    stream_t s = {fopen(tmp, "wb"), FNV_BASIS, 1};
    if (!s.f) { snprintf(err, errlen, "%s: %s", path, strerror(errno)); free(inv); return -1; }
    uint64_t w[HEADER_WORDS];
    pack(info, h->n, w);
    put(&s, MAGIC, sizeof MAGIC);
    put(&s, w, sizeof w);
    const uint64_t note_len = info->note ? strlen(info->note) : 0;
    put(&s, &note_len, sizeof note_len);
    put(&s, info->note ? info->note : "", note_len);
    state_array_t a[3];
    for (int k = 0, na = state_arrays(h, prec, a); k < na; k++)
        for (size_t i = 0; i < h->n; i++) put(&s, (const char *)a[k].base + inv[i] * a[k].stride, a[k].size);
    free(inv);
    uint64_t sum = s.hash;
    put(&s, &sum, sizeof sum);
    int ok = s.ok && fflush(s.f) == 0 && fsync(fileno(s.f)) == 0;
    int e = errno;
    if (fclose(s.f) != 0 && ok) { ok = 0; e = errno; }
    if (ok && rename(tmp, path) != 0) { ok = 0; e = errno; }
    if (!ok) {
        unlink(tmp);
        snprintf(err, errlen, "%s: cannot write the checkpoint: %s", path, strerror(e ? e : EIO));
        return -1;
    }
    return 0;
}

/* Read the magic, the header words and the note (into note[cap] when note is not NULL, else
 * skipped): 0, or -1 with err. */
static int read_head(stream_t *s, const char *path, checkpoint_info_t *in, uint64_t *n, char *note, size_t cap,
                     char *err, size_t errlen)
{
    char magic[sizeof MAGIC];
    uint64_t w[HEADER_WORDS], len = 0;
    get(s, magic, sizeof magic);
    if (s->ok && !memcmp(magic, MAGIC_OLD, sizeof MAGIC_OLD)) {
        snprintf(err, errlen, "%s: a checkpoint of an older format (PREECKP1): resume it with the build that wrote it", path);
        return -1;
    }
    if (!s->ok || memcmp(magic, MAGIC, sizeof MAGIC)) { snprintf(err, errlen, "%s: not a PREE checkpoint", path); return -1; }
    get(s, w, sizeof w);
    get(s, &len, sizeof len);
    if (!s->ok) { snprintf(err, errlen, "%s: truncated checkpoint (in its header)", path); return -1; }
    if (len >= CHECKPOINT_NOTE_MAX) { snprintf(err, errlen, "%s: corrupt checkpoint (its note)", path); return -1; }
    unpack(w, in, n);
    char buf[512];
    for (uint64_t done = 0; done < len && s->ok;) {
        const size_t k = len - done < sizeof buf ? (size_t)(len - done) : sizeof buf;
        get(s, buf, k);
        if (note && done + k < cap) memcpy(note + done, buf, k);
        done += k;
    }
    if (!s->ok) { snprintf(err, errlen, "%s: truncated checkpoint (in its note)", path); return -1; }
    if (note && cap) {
        if (len >= cap || memchr(note, 0, (size_t)len)) { snprintf(err, errlen, "%s: corrupt checkpoint (its note)", path); return -1; }
        note[len] = 0;
    }
    return 0;
}

int checkpoint_read_note(const char *path, char *note, size_t cap, uint64_t *done_photons, char *err, size_t errlen)
{
    stream_t s = {fopen(path, "rb"), FNV_BASIS, 1};
    if (!s.f) { snprintf(err, errlen, "%s: %s", path, strerror(errno)); return -1; }
    checkpoint_info_t in;
    uint64_t n;
    const int rc = read_head(&s, path, &in, &n, note, cap, err, errlen);
    fclose(s.f);
    if (rc == 0) *done_photons = in.done_photons;
    return rc;
}

int checkpoint_load(const char *path, checkpoint_info_t *info, hitpoints_t *h, const uint32_t *perm,
                    precision_t prec, char *err, size_t errlen)
{
    stream_t s = {fopen(path, "rb"), FNV_BASIS, 1};
    if (!s.f) { snprintf(err, errlen, "%s: %s", path, strerror(errno)); return -1; }
    const uint64_t want = info->fingerprint;
    checkpoint_info_t in;
    uint64_t n = 0, sum = 0;
    int rc = -1;
    if (read_head(&s, path, &in, &n, NULL, 0, err, errlen)) goto out;
    if (in.fingerprint != want || n != h->n) {
        snprintf(err, errlen, "%s: the checkpoint is of another scene, options or build (fingerprint %016llx, this "
                 "render's %016llx)", path, (unsigned long long)in.fingerprint, (unsigned long long)want);
        goto out;
    }
    uint32_t *inv = inverse(perm, h->n);
    if (!inv) { snprintf(err, errlen, "%s: out of memory", path); goto out; }
    state_array_t a[3];
    for (int k = 0, na = state_arrays(h, prec, a); k < na; k++)
        for (size_t i = 0; i < h->n; i++) get(&s, (char *)a[k].base + inv[i] * a[k].stride, a[k].size);
    free(inv);
    const uint64_t expect = s.hash;
    get(&s, &sum, sizeof sum);
    if (!s.ok) { snprintf(err, errlen, "%s: truncated checkpoint", path); goto out; }
    if (sum != expect || fgetc(s.f) != EOF) { snprintf(err, errlen, "%s: corrupt checkpoint (checksum)", path); goto out; }
    *info = in;
    rc = 0;
out:
    fclose(s.f);
    return rc;
}
