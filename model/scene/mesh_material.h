// SPDX-License-Identifier: Apache-2.0
/* mesh_material.h: the rule that maps a model file's (MTL) material to an engine material
 * (docs/scene_format.md, "Meshes"), first match wins:
 *   1. emissive (max Ke > 0): diffuse Kd (the surface of an area light);
 *   2. glass: illum 4, 6, 7 or 9, or dissolve d < 1: glass tinted Tf / max(Tf) (white when
 *      Tf is zero or absent), ior Ni when Ni > 1, else 1.5;
 *   3. mirror: illum 3, 5 or 8, or max(Ks) > max(Kd): mirror tinted Ks (white if Ks is 0);
 *   4. diffuse Kd.
 * Colours are clamped to [0, 1]. */
#ifndef PREE_MESH_MATERIAL_H
#define PREE_MESH_MATERIAL_H

#include "scene.h"

typedef struct {
    vec3 kd, ks, ke, tf;   /* absent colours are 0 (tf: 1 1 1) */
    double ni;             /* absent: 1 */
    double d;              /* dissolve (opacity); absent: 1 */
    int illum;             /* absent: -1 */
} mtl_props_t;

void mesh_material_from_mtl(const mtl_props_t *p, material_t *out);
int mesh_material_is_emissive(const mtl_props_t *p);

#endif
