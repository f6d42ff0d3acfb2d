// SPDX-License-Identifier: Apache-2.0
/* scene_pbrt.h: a pbrt-v4 scene file read into a scene (scene_pbrt.c, docs/pbrt.md); scene_load
 * calls it for a path ending in .pbrt. */
#ifndef PREE_SCENE_PBRT_H
#define PREE_SCENE_PBRT_H

#include <stddef.h>
#include <stdint.h>
#include "scene.h"

/* Read path into s (zeroed, with its defaults set by the caller): the Film's resolution and sppm's
 * photon count (iterations x photons per iteration) are returned for the render's defaults.
 * 0, or -1 with "FILE:LINE: Directive: what" in err (s then to be freed by the caller). */
int scene_pbrt_load(const char *path, scene_t *s, int *film_w, int *film_h, uint64_t *photons, char *err, size_t errlen);

#endif
