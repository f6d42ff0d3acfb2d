// SPDX-License-Identifier: Apache-2.0
/* mesh_options.h: the options of the scene file's "mesh FILE [options]" directive
 * (docs/scene_format.md, "Meshes"): the model's path, material and its maps, the transform
 * composed in the order written, the normals and the emission scale.
 * mesh_parse_options() reads the tokens after the word "mesh" (scene_file: the including file,
 * for a relative path); returns 0, or -1 with a one-line message in err. */
#ifndef PREE_MESH_OPTIONS_H
#define PREE_MESH_OPTIONS_H

#include <stddef.h>
#include "scene.h"

#define MAX_MAPS 64

typedef enum { NORMALS_FILE = 0, NORMALS_FLAT = 1, NORMALS_SMOOTH = 2 } normals_mode_t;

typedef struct {
    char path[4096];             /* resolved against the scene file's folder */
    int material;                /* -1: from the file */
    int nmap;
    char map_name[MAX_MAPS][64]; /* "map MTLNAME MATERIAL" and "exclude MTLNAME" (material -2) */
    int map_mat[MAX_MAPS];
    double m[3][3];              /* p' = m p + t, composed in the order written */
    vec3 t;
    normals_mode_t normals;
    double emission;             /* multiplies Ke */
} mesh_opts_t;

int mesh_parse_options(const scene_t *s, const char *scene_file, char **tok, int ntok, mesh_opts_t *o,
                       char *err, size_t errlen);

#endif
