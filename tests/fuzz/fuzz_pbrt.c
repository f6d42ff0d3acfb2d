// SPDX-License-Identifier: Apache-2.0
/* fuzz_pbrt.c: libFuzzer harness for the pbrt-v4 reader (model/scene/scene_pbrt.c, pbrt_lex.c):
 * fuzz_scene.c with the input written to a .pbrt file. Seed corpus: tests/fuzz/corpus/pbrt. */
#define FUZZ_SCENE_SUFFIX ".pbrt"
#include "fuzz_scene.c"
