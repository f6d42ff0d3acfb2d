/* mesh_load.c: the scene file's "mesh" directive (model files through Assimp). */
#include <stdio.h>
#include "mesh_load.h"

int mesh_load_directive(scene_t *scene, const char *scene_file, char **tok, int ntok, char *err, size_t errlen)
{
    (void)scene; (void)scene_file; (void)ntok;
    snprintf(err, errlen, "mesh '%s': model files are not supported by this build", tok[0]);
    return -1;
}
