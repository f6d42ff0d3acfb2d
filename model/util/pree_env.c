// SPDX-License-Identifier: Apache-2.0
/* pree_env.c: the names of the environment variables of pree_env.h, and their reader. */
#include "pree_env.h"

#include <stdlib.h>

static const char *const NAMES[PREE_ENV_COUNT] = {
    [PREE_ENV_NO_AVX2] = "PREE_NO_AVX2",
    [PREE_ENV_TRACER_EMBREE] = "PREE_TRACER_EMBREE",
    [PREE_ENV_GRID_HASHED] = "PREE_GRID_HASHED",
    [PREE_ENV_NO_REFILTER] = "PREE_NO_REFILTER",
    [PREE_ENV_SCREEN_BLOCKS] = "PREE_SCREEN_BLOCKS",
    [PREE_ENV_OIIO_MODULE] = "PREE_OIIO_MODULE",
    [PREE_ENV_POSTROUTE_RECORD] = "PREE_POSTROUTE_RECORD",
    [PREE_ENV_TEST_INTERRUPT] = "PREE_TEST_INTERRUPT",
    [PREE_ENV_TEST_KILL] = "PREE_TEST_KILL",
    [PREE_ENV_TEST_CORRUPT_HP] = "PREE_TEST_CORRUPT_HP",
};

const char *pree_env_name(pree_env_t v)
{
    return (unsigned)v < PREE_ENV_COUNT ? NAMES[v] : "";
}

const char *pree_env(pree_env_t v)
{
    return (unsigned)v < PREE_ENV_COUNT ? getenv(NAMES[v]) : NULL;
}
