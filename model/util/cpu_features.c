// SPDX-License-Identifier: Apache-2.0
/* cpu_features.c: the vector level the kernels use (cpu_features.h). */
#include <stdlib.h>
#include <string.h>
#include "cpu_features.h"
#include "pree_env.h"

static int forced = SIMD_AUTO;

int cpu_simd_supported(simd_level_t level)
{
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    switch (level) {
    case SIMD_AVX512: return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx2");
    case SIMD_AVX2: return __builtin_cpu_supports("avx2");
    default: return 1;
    }
#else
    return level == SIMD_SCALAR;
#endif
}

simd_level_t cpu_simd_best(void)
{
    return cpu_simd_supported(SIMD_AVX512) ? SIMD_AVX512 : cpu_simd_supported(SIMD_AVX2) ? SIMD_AVX2 : SIMD_SCALAR;
}

simd_level_t cpu_simd_level(void)
{
    if (forced != SIMD_AUTO) return (simd_level_t)forced;
    return pree_env(PREE_ENV_NO_AVX2) ? SIMD_SCALAR : cpu_simd_best();
}

int cpu_simd_force(int level)
{
    if (level != SIMD_AUTO && (level < SIMD_SCALAR || level > SIMD_AVX512 || !cpu_simd_supported((simd_level_t)level)))
        return -1;
    forced = level;
    return 0;
}

static const char *const names[] = {"scalar", "avx2", "avx512"};

const char *cpu_simd_name(simd_level_t level)
{
    return level >= SIMD_SCALAR && level <= SIMD_AVX512 ? names[level] : "?";
}

int cpu_simd_parse(const char *name, int *level)
{
    if (!strcmp(name, "auto")) { *level = SIMD_AUTO; return 0; }
    for (int k = 0; k <= SIMD_AVX512; k++)
        if (!strcmp(name, names[k])) { *level = k; return 0; }
    return -1;
}
