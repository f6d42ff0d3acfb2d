// SPDX-License-Identifier: Apache-2.0
/* fuzz_scene.c: libFuzzer harness for the scene parser (model/scene/scene_parse.c): each input
 * is written to a scene file and loaded with scene_load; any crash, hang, leak or sanitizer
 * report is a finding. The seed corpus is tests/fuzz/corpus/scene (make fuzz, docs/engine.md).
 * fuzz_pbrt.c includes it with FUZZ_SCENE_SUFFIX ".pbrt" for the pbrt-v4 reader. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include "fuzz_file.h"
#include "scene.h"

#ifndef FUZZ_SCENE_SUFFIX
#define FUZZ_SCENE_SUFFIX ".scene"
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char path[64];
    if (!path[0]) fuzz_file_name(path, sizeof path, FUZZ_SCENE_SUFFIX);
    if (fuzz_write_file(path, data, size)) return 0;
    scene_t s;
    char err[1024];
    if (scene_load(path, &s, err, sizeof err) == 0) scene_free(&s);
    return 0;
}
