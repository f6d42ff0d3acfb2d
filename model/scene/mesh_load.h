// SPDX-License-Identifier: Apache-2.0
/* mesh_load.h: triangle meshes in a scene: inline triangles and model files.
 * mesh_append_triangle() adds one triangle to the scene's inline mesh.
 * mesh_load_directive() handles the scene file's "mesh FILE [options]" line (tokens after
 * the word "mesh"; scene_file is the including file, for relative paths). Both return 0,
 * or -1 with a one-line message in err and the scene unchanged. */
#ifndef PREE_MESH_LOAD_H
#define PREE_MESH_LOAD_H

#include <stddef.h>
#include "scene.h"

int mesh_append_triangle(scene_t *scene, const vec3 p[3], int material, char *err, size_t errlen);
int mesh_load_directive(scene_t *scene, const char *scene_file, char **tok, int ntok, char *err, size_t errlen);
void mesh_free(mesh_t *mesh);

#endif
