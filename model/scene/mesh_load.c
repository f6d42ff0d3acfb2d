// SPDX-License-Identifier: Apache-2.0
/* mesh_load.c: the scene file's "mesh FILE [options]" directive: model files through
 * Assimp's C API (gzip-compressed files read through zlib), transforms, the MTL material
 * rule or overrides, degenerate-triangle filtering and emissive (area-light) triangles.
 * Options (mesh_options.c) and rules: docs/scene_format.md, "Meshes". */
#include <assimp/cimport.h>
#include <assimp/material.h>
#include <assimp/ObjMaterial.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "mesh_io.h"
#include "mesh_light.h"
#include "mesh_load.h"
#include "mesh_material.h"
#include "mesh_objcheck.h"
#include "mesh_options.h"

static vec3 colour_key(const struct aiMaterial *m, const char *key, unsigned type, unsigned idx, vec3 dflt)
{
    struct aiColor4D c;
    if (aiGetMaterialColor(m, key, type, idx, &c) != aiReturn_SUCCESS) return dflt;
    return v3(c.r, c.g, c.b);
}

static double float_key(const struct aiMaterial *m, const char *key, unsigned type, unsigned idx, double dflt)
{
    ai_real f;
    unsigned one = 1;
    if (aiGetMaterialFloatArray(m, key, type, idx, &f, &one) != aiReturn_SUCCESS || one != 1) return dflt;
    return (double)f;
}

static void mtl_props(const struct aiMaterial *m, mtl_props_t *p)
{
    p->kd = colour_key(m, AI_MATKEY_COLOR_DIFFUSE, v3(0, 0, 0));
    p->ks = colour_key(m, AI_MATKEY_COLOR_SPECULAR, v3(0, 0, 0));
    p->ke = colour_key(m, AI_MATKEY_COLOR_EMISSIVE, v3(0, 0, 0));
    p->tf = colour_key(m, AI_MATKEY_COLOR_TRANSPARENT, v3(1, 1, 1));
    p->ni = float_key(m, AI_MATKEY_REFRACTI, 1.0);
    p->d = float_key(m, AI_MATKEY_OPACITY, 1.0);
    int il;
    unsigned one = 1;
    p->illum = aiGetMaterialIntegerArray(m, AI_MATKEY_OBJ_ILLUM, &il, &one) == aiReturn_SUCCESS ? il : -1;
}

/* The engine material for Assimp material k: an override, or the rule of mesh_material.h
 * as a new scene material named "FILE:MTLNAME" (reused when the same one exists). -2: excluded. */
static int resolve_material(scene_t *s, const mesh_opts_t *o, const struct aiMaterial *am, const char *base,
                            char *err, size_t errlen)
{
    struct aiString name;
    if (aiGetMaterialString(am, AI_MATKEY_NAME, &name) != aiReturn_SUCCESS) { name.length = 0; name.data[0] = '\0'; }
    for (int i = 0; i < o->nmap; i++)
        if (!strcmp(o->map_name[i], name.data)) return o->map_mat[i];
    if (o->material >= 0) return o->material;
    mtl_props_t p;
    mtl_props(am, &p);
    material_t m;
    memset(&m, 0, sizeof m);
    mesh_material_from_mtl(&p, &m);
    char want[64];
    snprintf(want, sizeof want, "%.40s:%.22s", base, name.data);
    for (int k = 1; k < 1000; k++) {
        if (k == 1) snprintf(m.name, sizeof m.name, "%s", want);
        else snprintf(m.name, sizeof m.name, "%.55s#%u", want, (unsigned)k % 1000u);   /* k < 1000 */
        int id = scene_find_material(s, m.name);
        if (id < 0) return scene_add_material(s, &m, err, errlen);
        const material_t *e = &s->materials[id];
        if (e->kind == m.kind && e->colour.x == m.colour.x && e->colour.y == m.colour.y &&
            e->colour.z == m.colour.z && e->ior == m.ior)
            return id;
    }
    snprintf(err, errlen, "too many materials named '%s'", want);
    return -1;
}

static int ends_with(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && !strcasecmp(s + a - b, suffix);
}

/* Emitting triangles' corners, per Assimp material. */
typedef struct { vec3 *c; size_t n, cap; } corners_t;

static int corners_push(corners_t *e, const vec3 c[3])
{
    if (e->n + 3 > e->cap) {
        size_t cap = e->cap ? 2 * e->cap : 96;
        vec3 *a = realloc(e->c, cap * sizeof *a);
        if (!a) return -1;
        e->c = a;
        e->cap = cap;
    }
    for (int k = 0; k < 3; k++) e->c[e->n++] = c[k];
    return 0;
}

static void base_name(const char *path, char *out, size_t n)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    size_t len = strlen(b);
    if (len >= n) len = n - 1;
    memcpy(out, b, len);
    out[len] = '\0';
    char *gz = strstr(out, ".gz");
    if (gz && gz[3] == '\0') *gz = '\0';
}

static void one_line(char *s)
{
    for (; *s; s++)
        if (*s == '\n' || *s == '\r') *s = ' ';
}

/* Counts the triangle meshes' vertices and faces (faces of other meshes add to *non_tri) and
 * allocates m's arrays for them (normals only when the model has some and o wants them).
 * Returns 0 or -1 (err filled). */
static int mesh_alloc(const mesh_opts_t *o, const struct aiScene *as, const char *path, mesh_t *m,
                      size_t *non_tri, char *err, size_t errlen)
{
    size_t nv = 0, nt = 0;
    int any_normals = 0;
    for (unsigned i = 0; i < as->mNumMeshes; i++) {
        const struct aiMesh *am = as->mMeshes[i];
        if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) { *non_tri += am->mNumFaces; continue; }
        nv += am->mNumVertices;
        nt += am->mNumFaces;
        any_normals |= am->mNormals != NULL;
    }
    if (nv > UINT32_MAX) { snprintf(err, errlen, "%s: more than 2^32 vertices", path); return -1; }
    int normals = any_normals && o->normals != NORMALS_FLAT;
    m->vertices = malloc((nv ? nv : 1) * 3 * sizeof *m->vertices);
    m->indices = malloc((nt ? nt : 1) * 3 * sizeof *m->indices);
    m->tri_material = malloc((nt ? nt : 1) * sizeof *m->tri_material);
    if (normals) m->normals = calloc((nv ? nv : 1) * 3, sizeof *m->normals);
    if (!m->vertices || !m->indices || !m->tri_material || (normals && !m->normals)) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    return 0;
}

/* Transforms mesh am's vertices (and normals, by the cofactor matrix cof) into m from vertex v0.
 * Returns 0, or -1 (err filled) for a vertex that is not finite or lies beyond the range. */
static int copy_vertices(const struct aiMesh *am, const mesh_opts_t *o, const double cof[3][3],
                         mesh_t *m, size_t v0, const char *path, char *err, size_t errlen)
{
    const double (*a)[3] = o->m;
    for (unsigned k = 0; k < am->mNumVertices; k++) {
        vec3 p = v3(am->mVertices[k].x, am->mVertices[k].y, am->mVertices[k].z);
        vec3 q = v3(a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + o->t.x,
                    a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + o->t.y,
                    a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + o->t.z);
        float *dst = m->vertices + 3 * (v0 + k);
        dst[0] = (float)q.x; dst[1] = (float)q.y; dst[2] = (float)q.z;
        if (!v3_is_finite(p) || !isfinite(dst[0]) || !isfinite(dst[1]) || !isfinite(dst[2])) {
            snprintf(err, errlen, "%s: vertex %zu is not finite%s", path, v0 + k + 1,
                     v3_is_finite(p) ? " after the transform (or beyond float range)" : "");
            return -1;
        }
        if (fmax(fabs(q.x), fmax(fabs(q.y), fabs(q.z))) > SCENE_COORD_MAX) {
            snprintf(err, errlen, "%s: vertex %zu lies beyond +-%g (the range the tracer and binary32 hold)%s",
                     path, v0 + k + 1, SCENE_COORD_MAX, " after the transform");
            return -1;
        }
        if (m->normals && am->mNormals) {
            vec3 n = v3(am->mNormals[k].x, am->mNormals[k].y, am->mNormals[k].z);
            vec3 r = v3(cof[0][0] * n.x + cof[0][1] * n.y + cof[0][2] * n.z,
                        cof[1][0] * n.x + cof[1][1] * n.y + cof[1][2] * n.z,
                        cof[2][0] * n.x + cof[2][1] * n.y + cof[2][2] * n.z);
            double l2 = v3_dot(r, r);
            if (l2 > 0 && isfinite(l2)) {   /* else left 0: that corner falls back to flat */
                r = v3_norm(r);
                float *nd = m->normals + 3 * (v0 + k);
                nd[0] = (float)r.x; nd[1] = (float)r.y; nd[2] = (float)r.z;
            }
        }
    }
    return 0;
}

/* Appends mesh am's triangles (vertices from v0) to m with material mat (-2: excluded), their
 * corners to emit when it is not NULL; faces that are not triangles and triangles of area 0 are
 * counted, not kept. Returns 0 or -1 (err filled). */
static int copy_faces(const struct aiMesh *am, mesh_t *m, size_t v0, int mat, corners_t *emit,
                      size_t *dropped, size_t *excluded, size_t *non_tri, const char *path,
                      char *err, size_t errlen)
{
    for (unsigned f = 0; f < am->mNumFaces; f++) {
        const struct aiFace *fc = &am->mFaces[f];
        if (fc->mNumIndices != 3) { (*non_tri)++; continue; }
        if (mat == -2) { (*excluded)++; continue; }
        vec3 c[3];
        for (int k = 0; k < 3; k++) {
            const float *pv = m->vertices + 3 * (v0 + fc->mIndices[k]);
            c[k] = v3(pv[0], pv[1], pv[2]);
        }
        vec3 x = v3_cross(v3_sub(c[1], c[0]), v3_sub(c[2], c[0]));
        double l2 = v3_dot(x, x);
        if (!(l2 > 0) || !isfinite(l2)) { (*dropped)++; continue; }
        size_t t = m->num_triangles++;
        for (int k = 0; k < 3; k++) m->indices[3 * t + k] = (uint32_t)(v0 + fc->mIndices[k]);
        m->tri_material[t] = mat;
        if (emit && corners_push(emit, c)) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    }
    return 0;
}

/* Copy the imported triangles into m (transformed), resolving materials and collecting
 * emitters. Returns 0 or -1 (err filled). */
static int convert(scene_t *s, const mesh_opts_t *o, const struct aiScene *as, const char *path,
                   mesh_t *m, corners_t *emit, size_t *dropped, size_t *excluded, size_t *non_tri,
                   char *err, size_t errlen)
{
    char base[128];
    base_name(path, base, sizeof base);
    if (mesh_alloc(o, as, path, m, non_tri, err, errlen)) return -1;
    int *mat_of = malloc((as->mNumMaterials ? as->mNumMaterials : 1) * sizeof *mat_of);
    if (!mat_of) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    for (unsigned k = 0; k < as->mNumMaterials; k++) mat_of[k] = -3;   /* not resolved yet */
    /* Normal matrix: the cofactors of m (det(m) times its inverse transpose). */
    const double (*a)[3] = o->m;
    double cof[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            cof[i][j] = a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1];
        }
    size_t v0 = 0;
    int rc = 0;
    for (unsigned i = 0; i < as->mNumMeshes && rc == 0; i++) {
        const struct aiMesh *am = as->mMeshes[i];
        if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        rc = copy_vertices(am, o, (const double (*)[3])cof, m, v0, path, err, errlen);
        unsigned mi = am->mMaterialIndex < as->mNumMaterials ? am->mMaterialIndex : 0;
        if (rc == 0 && as->mNumMaterials > 0 && mat_of[mi] == -3) {
            mat_of[mi] = resolve_material(s, o, as->mMaterials[mi], base, err, errlen);
            if (mat_of[mi] == -1) rc = -1;
        }
        int mat = as->mNumMaterials > 0 ? mat_of[mi] : o->material;
        if (rc == 0 && mat == -1) { snprintf(err, errlen, "%s: no material (give 'material NAME')", path); rc = -1; }
        int emits = 0;
        if (rc == 0 && mat != -2 && o->emission > 0 && as->mNumMaterials > 0) {
            mtl_props_t p;
            mtl_props(as->mMaterials[mi], &p);
            emits = mesh_material_is_emissive(&p);
        }
        if (rc == 0)
            rc = copy_faces(am, m, v0, mat, emits ? &emit[mi] : NULL, dropped, excluded, non_tri, path,
                            err, errlen);
        v0 += am->mNumVertices;
    }
    m->num_vertices = v0;
    free(mat_of);
    return rc;
}

/* Reads the model that o->path names and imports it through Assimp (a ".gz" file decompressed in
 * memory; an OBJ file checked first by mesh_obj_check). Returns the imported scene, whose bytes
 * stay in *blob, or NULL with err set. */
static const struct aiScene *import_model(const mesh_opts_t *o, mesh_blob_t *blob, char *err, size_t errlen)
{
    if (mesh_read_file(o->path, blob, err, errlen)) return NULL;
    /* The name Assimp sees: without ".gz", so that it picks the importer by extension. */
    char vpath[4096];
    snprintf(vpath, sizeof vpath, "%s", o->path);
    if (ends_with(vpath, ".gz")) vpath[strlen(vpath) - 3] = '\0';
    const int is_obj = ends_with(vpath, ".obj");
    mesh_obj_counts_t counts;
    if (is_obj && mesh_obj_check(o->path, blob, o->material < 0, &counts, err, errlen)) return NULL;
    if (is_obj && counts.faces == 0) {
        snprintf(err, errlen, "%s: no faces (an empty mesh)", o->path);
        return NULL;
    }

    unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                     aiProcess_SortByPType | aiProcess_ValidateDataStructure;
    if (o->normals == NORMALS_FLAT) flags |= aiProcess_DropNormals;
    if (o->normals == NORMALS_SMOOTH) flags |= aiProcess_GenSmoothNormals | aiProcess_ForceGenNormals;
    struct aiPropertyStore *props = aiCreatePropertyStore();
    aiSetImportPropertyFloat(props, AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 80.0f);
    mesh_io_t io;
    mesh_io_assimp(&io, vpath, blob);
    const struct aiScene *as = aiImportFileExWithProperties(vpath, flags, &io.io, props);
    aiReleasePropertyStore(props);
    if (!as) {
        char msg[400];
        snprintf(msg, sizeof msg, "%s", aiGetErrorString());
        one_line(msg);
        snprintf(err, errlen, "%s: %s", o->path, msg[0] ? msg : "cannot read the model");
    }
    return as;
}

/* Adds an imported model to the scene: its triangles as one mesh and each emissive material's
 * triangles as a light; warns of what it dropped. On an error the caller removes the lights it
 * may have added. */
static int add_model(scene_t *scene, const mesh_opts_t *o, const struct aiScene *as, char *err, size_t errlen)
{
    mesh_t m;
    memset(&m, 0, sizeof m);
    snprintf(m.source, sizeof m.source, "%.255s", o->path);
    corners_t *emit = calloc(as->mNumMaterials ? as->mNumMaterials : 1, sizeof *emit);
    size_t dropped = 0, excluded = 0, non_tri = 0;
    int rc = emit ? 0 : -1;
    if (!emit) snprintf(err, errlen, "%s: out of memory", o->path);
    if (rc == 0) rc = convert(scene, o, as, o->path, &m, emit, &dropped, &excluded, &non_tri, err, errlen);
    if (rc == 0 && m.num_triangles == 0) {
        snprintf(err, errlen, "%s: no triangles (%zu degenerate dropped, %zu excluded)", o->path, dropped, excluded);
        rc = -1;
    }
    for (unsigned k = 0; rc == 0 && k < as->mNumMaterials; k++) {
        if (emit[k].n == 0) continue;
        mtl_props_t p;
        mtl_props(as->mMaterials[k], &p);
        char e[256];
        if (mesh_light_add(scene, emit[k].c, emit[k].n / 3, v3_scale(p.ke, o->emission), 0, e, sizeof e)) {
            snprintf(err, errlen, "%s: %s", o->path, e);
            rc = -1;
        }
    }
    if (rc == 0) {
        mesh_t *arr = realloc(scene->meshes, (size_t)(scene->num_meshes + 1) * sizeof *arr);
        if (!arr) { snprintf(err, errlen, "out of memory"); rc = -1; }
        else { scene->meshes = arr; arr[scene->num_meshes++] = m; }
    }
    if (rc == 0 && dropped)
        fprintf(stderr, "pree: warning: %s: dropped %zu degenerate (zero-area) triangle%s\n", o->path, dropped,
                dropped == 1 ? "" : "s");
    if (rc == 0 && non_tri)
        fprintf(stderr, "pree: warning: %s: ignored %zu point and line primitive%s\n", o->path, non_tri,
                non_tri == 1 ? "" : "s");
    for (unsigned k = 0; emit && k < as->mNumMaterials; k++) free(emit[k].c);
    free(emit);
    if (rc) mesh_free(&m);
    return rc;
}

int mesh_load_directive(scene_t *scene, const char *scene_file, char **tok, int ntok, char *err, size_t errlen)
{
    mesh_opts_t o;
    if (mesh_parse_options(scene, scene_file, tok, ntok, &o, err, errlen)) return -1;
    const int mats_before = scene->num_materials, lights_before = scene->num_lights;
    mesh_blob_t blob = {0};
    const struct aiScene *as = import_model(&o, &blob, err, errlen);
    int rc = as ? add_model(scene, &o, as, err, errlen) : -1;
    if (as) aiReleaseImport(as);
    mesh_blob_free(&blob);
    if (rc) {
        /* Leave the scene as it was. */
        for (int i = lights_before; i < scene->num_lights; i++) free(scene->lights[i].tris);
        scene->num_lights = lights_before;
        scene->num_materials = mats_before;
        return -1;
    }
    return 0;
}
