// SPDX-License-Identifier: Apache-2.0
/* cpu_features.h: which vector instruction set the engine's kernels use, chosen once per process.
 *
 * The kernels that have vector versions (the update's screening and its prefilter, the sphere
 * group's intersection) ask cpu_simd_level() and take the widest path at or below it; each
 * path gives the same bits. The level is the widest the processor supports (GCC's
 * __builtin_cpu_supports), lowered to scalar by PREE_NO_AVX2 in the environment, or the one a
 * caller forced (`pree render --simd`), which must be supported. */
#ifndef PREE_CPU_FEATURES_H
#define PREE_CPU_FEATURES_H

typedef enum { SIMD_SCALAR = 0, SIMD_AVX2 = 1, SIMD_AVX512 = 2 } simd_level_t;
#define SIMD_AUTO (-1)

/* Whether the processor runs level's instructions (AVX-512: AVX-512F; SIMD_SCALAR: always). */
int cpu_simd_supported(simd_level_t level);

/* The widest level the processor supports. */
simd_level_t cpu_simd_best(void);

/* The level the kernels use: the forced one, else cpu_simd_best() (scalar under PREE_NO_AVX2). */
simd_level_t cpu_simd_level(void);

/* Force the level (SIMD_AUTO: back to the default). 0, or -1 when the processor lacks it. */
int cpu_simd_force(int level);

/* "scalar", "avx2", "avx512"; and back (-1 for an unknown name, SIMD_AUTO for "auto"). */
const char *cpu_simd_name(simd_level_t level);
int cpu_simd_parse(const char *name, int *level);

#endif
