// SPDX-License-Identifier: Apache-2.0
/* scene_materials.c: the scene's materials by name, with a hash index (open addressing,
 * FNV-1a) so that defining or using a material costs the same with 50,000 of them as with 5.
 * Index entries are checked against the array's names, so entries left by a rollback
 * (mesh_load.c trims num_materials when a mesh fails) are skipped, never returned. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene.h"

static uint32_t name_hash(const char *s)
{
    uint32_t h = 2166136261u;
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

static void index_put(int *index, size_t cap, const char *name, int id)
{
    size_t i = name_hash(name) & (cap - 1);
    while (index[i]) i = (i + 1) & (cap - 1);
    index[i] = id + 1;
}

/* Rebuild the index at a capacity for at least twice the materials; 0, or -1 out of memory. */
static int index_grow(scene_t *s)
{
    size_t cap = 64;
    while (cap < 2 * ((size_t)s->num_materials + 1)) cap *= 2;
    int *index = calloc(cap, sizeof *index);
    if (!index) return -1;
    for (int id = 0; id < s->num_materials; id++) index_put(index, cap, s->materials[id].name, id);
    free(s->mat_index);
    s->mat_index = index;
    s->mat_index_cap = cap;
    s->mat_index_used = (size_t)s->num_materials;
    return 0;
}

int scene_find_material(const scene_t *scene, const char *name)
{
    if (!scene->mat_index) return -1;
    size_t cap = scene->mat_index_cap;
    for (size_t i = name_hash(name) & (cap - 1); scene->mat_index[i]; i = (i + 1) & (cap - 1)) {
        int id = scene->mat_index[i] - 1;
        if (id < scene->num_materials && !strcmp(scene->materials[id].name, name)) return id;
    }
    return -1;
}

int scene_add_material(scene_t *scene, const material_t *m, char *err, size_t errlen)
{
    if (scene_find_material(scene, m->name) >= 0) {
        snprintf(err, errlen, "material '%s' is defined twice", m->name);
        return -1;
    }
    if (scene->num_materials == scene->materials_cap) {
        int cap = scene->materials_cap ? 2 * scene->materials_cap : 16;
        material_t *mats = realloc(scene->materials, (size_t)cap * sizeof *mats);
        if (!mats) { snprintf(err, errlen, "out of memory"); return -1; }
        scene->materials = mats;
        scene->materials_cap = cap;
    }
    if (2 * (scene->mat_index_used + 1) > scene->mat_index_cap && index_grow(scene)) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    int id = scene->num_materials++;
    scene->materials[id] = *m;
    index_put(scene->mat_index, scene->mat_index_cap, m->name, id);
    scene->mat_index_used++;
    return id;
}

void scene_materials_free(scene_t *scene)
{
    free(scene->materials);
    free(scene->mat_index);
    scene->materials = NULL;
    scene->mat_index = NULL;
    scene->num_materials = scene->materials_cap = 0;
    scene->mat_index_cap = scene->mat_index_used = 0;
}
