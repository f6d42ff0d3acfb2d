// SPDX-License-Identifier: Apache-2.0
/* mesh_objcheck.h: a strict line-by-line check of Wavefront OBJ text and the MTL files it
 * names, before Assimp (which is lenient and reports no line numbers) reads them.
 *
 * Checked: vertex and normal lines hold 3 finite numbers; face lines hold at least 3
 * references, each to a vertex (texture coordinate, normal) already defined; material
 * libraries exist (when need_mtl) and their colour, Ni, Ns, d, Tr and illum values are
 * well-formed, finite and not negative; every usemtl names a material of those libraries
 * (when need_mtl). Other lines are ignored. Returns 0, or -1 with "FILE:LINE: what" in err. */
#ifndef PREE_MESH_OBJCHECK_H
#define PREE_MESH_OBJCHECK_H

#include <stddef.h>
#include "mesh_io.h"

typedef struct { size_t vertices, faces, normals; } mesh_obj_counts_t;

int mesh_obj_check(const char *path, const mesh_blob_t *obj, int need_mtl, mesh_obj_counts_t *counts,
                   char *err, size_t errlen);

/* The same check for MTL text alone (names collected are freed before returning). */
int mesh_mtl_check(const char *path, const mesh_blob_t *mtl, char *err, size_t errlen);

#endif
