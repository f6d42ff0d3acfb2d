// SPDX-License-Identifier: Apache-2.0
/* fuzz_mesh.c: libFuzzer harness for the mesh loader (model/scene/mesh_load.c, mesh_objcheck.c,
 * Assimp behind them): each input is written as an OBJ file that a fixed scene loads with
 * `mesh FILE material m` (both files in the current directory). The seed corpus is tests/fuzz/corpus/mesh. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "fuzz_file.h"
#include "scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char obj[64], scene_path[64];
    if (!obj[0]) {
        fuzz_file_name(obj, sizeof obj, ".obj");
        fuzz_file_name(scene_path, sizeof scene_path, ".scene");
        char text[256];
        int n = snprintf(text, sizeof text, "camera origin 0 0 5 dir 0 0 -1 scale 0.5 near 0\n"
                         "material m diffuse .5 .5 .5\nmesh %s material m\nlight point 0 5 0 intensity 1 1 1\n", obj);
        if (fuzz_write_file(scene_path, (const uint8_t *)text, (size_t)n)) abort();
    }
    if (fuzz_write_file(obj, data, size)) return 0;
    scene_t s;
    char err[1024];
    if (scene_load(scene_path, &s, err, sizeof err) == 0) scene_free(&s);
    return 0;
}
