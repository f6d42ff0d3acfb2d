// SPDX-License-Identifier: Apache-2.0
/* mesh_material.c: MTL material -> engine material (the rule is in mesh_material.h). */
#include <string.h>
#include "mesh_material.h"

static double clamp01(double v) { return v > 1 ? 1 : (v > 0 ? v : 0); }
static vec3 clamp3(vec3 c) { return v3(clamp01(c.x), clamp01(c.y), clamp01(c.z)); }

int mesh_material_is_emissive(const mtl_props_t *p) { return v3_max_comp(p->ke) > 0; }

void mesh_material_from_mtl(const mtl_props_t *p, material_t *out)
{
    const int il = p->illum;
    out->ior = 1.5;
    if (mesh_material_is_emissive(p)) {
        out->kind = MAT_DIFFUSE;
        out->colour = clamp3(p->kd);
    } else if (il == 4 || il == 6 || il == 7 || il == 9 || p->d < 1) {
        out->kind = MAT_GLASS;
        double m = v3_max_comp(p->tf);
        out->colour = m > 0 ? clamp3(v3_scale(p->tf, 1.0 / m)) : v3(1, 1, 1);
        out->ior = p->ni > 1 && p->ni <= 10 ? p->ni : 1.5;
    } else if (il == 3 || il == 5 || il == 8 || v3_max_comp(p->ks) > v3_max_comp(p->kd)) {
        out->kind = MAT_MIRROR;
        out->colour = v3_max_comp(p->ks) > 0 ? clamp3(p->ks) : v3(1, 1, 1);
    } else {
        out->kind = MAT_DIFFUSE;
        out->colour = clamp3(p->kd);
    }
}
