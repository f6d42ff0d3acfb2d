// SPDX-License-Identifier: Apache-2.0
/* mesh.c: triangle storage for scenes: the inline-triangle mesh and mesh release. */
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include "mesh_load.h"

void mesh_free(mesh_t *m)
{
    free(m->vertices);
    free(m->normals);
    free(m->indices);
    free(m->tri_material);
    memset(m, 0, sizeof *m);
}

/* The inline mesh is the scene's first mesh whose source is "inline"; created on demand. */
static mesh_t *inline_mesh(scene_t *s)
{
    for (int i = 0; i < s->num_meshes; i++)
        if (!strcmp(s->meshes[i].source, "inline")) return &s->meshes[i];
    mesh_t *arr = realloc(s->meshes, (size_t)(s->num_meshes + 1) * sizeof *arr);
    if (!arr) return NULL;
    s->meshes = arr;
    mesh_t *m = &arr[s->num_meshes++];
    memset(m, 0, sizeof *m);
    strcpy(m->source, "inline");
    return m;
}

int mesh_append_triangle(scene_t *s, const vec3 p[3], int material, char *err, size_t errlen)
{
    mesh_t *m = inline_mesh(s);
    if (!m) { snprintf(err, errlen, "out of memory"); return -1; }
    float *v = realloc(m->vertices, (m->num_vertices + 3) * 3 * sizeof *v);
    if (v) m->vertices = v;
    uint32_t *ix = realloc(m->indices, (m->num_triangles + 1) * 3 * sizeof *ix);
    if (ix) m->indices = ix;
    int *tm = realloc(m->tri_material, (m->num_triangles + 1) * sizeof *tm);
    if (tm) m->tri_material = tm;
    if (!v || !ix || !tm) { snprintf(err, errlen, "out of memory"); return -1; }
    for (int k = 0; k < 3; k++) {
        float *dst = m->vertices + 3 * (m->num_vertices + k);
        dst[0] = (float)p[k].x; dst[1] = (float)p[k].y; dst[2] = (float)p[k].z;
        m->indices[3 * m->num_triangles + k] = (uint32_t)(m->num_vertices + k);
    }
    m->tri_material[m->num_triangles] = material;
    m->num_vertices += 3;
    m->num_triangles += 1;
    return 0;
}
