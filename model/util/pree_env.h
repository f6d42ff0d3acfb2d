// SPDX-License-Identifier: Apache-2.0
/* pree_env.h: every environment variable that the engine (libpree) and the co-simulation host
 * read, named in one place. None changes an image, a state hash or a cycle count.
 *
 * Implementation switches select an equivalent path, for make bench's before/after rows and the
 * regression's equivalence checks (each check compares the bits of both paths):
 *   PREE_NO_AVX2         set: the scalar kernels (screening, prefilter, sphere group) unless
 *                        `pree render --simd` chose (cpu_features.c; engine_scan_order.sh,
 *                        tracer_mixed_scene.sh)
 *   PREE_TRACER_EMBREE   set: Embree for an all-sphere scene instead of the sphere group
 *                        (tracer_mixed_scene.sh)
 *   PREE_GRID_HASHED     set: the cells grid's hash table instead of its dense cell map
 *                        (engine_scan_order.sh)
 *   PREE_NO_REFILTER     set: no grid re-filter as the radii shrink (scripts/bench-scale.sh)
 *   PREE_SCREEN_BLOCKS   K, 1 .. 4: screen K photon blocks a batch whatever the memory; another
 *                        value is a one-line error (engine_screen_batch.sh)
 * Where a file is:
 *   PREE_OIIO_MODULE     the OpenImageIO module (libpree_oiio.so) to load instead of the one
 *                        beside the program (model/image/image.c, docs/compare.md)
 *   PREE_POSTROUTE_RECORD PREFIX: the post-route programs record the UART link in PREFIX.txd,
 *                        PREFIX.rxd and PREFIX.bytes (host/postroute_uart.cpp, docs/fpga_board.md)
 * Test hooks inject a fault at a named point, for the checks of interruption, kill and failure
 * reports:
 *   PREE_TEST_INTERRUPT  PHASE: SIGINT as the render reaches PHASE (render_test_interrupt)
 *   PREE_TEST_KILL       PHASE: SIGKILL there (engine_checkpoint.sh)
 *   PREE_TEST_CORRUPT_HP N: the co-simulation program flips one bit of the model's hit point N
 *                        before it compares (fail_trace.sh and the MPI co-simulation check)
 * docs/engine.md, "Environment variables", lists the same; tests/checks/env_knobs.sh fails when
 * a getenv outside this table appears in model/, host/ or drv/, or the docs miss a name. */
#ifndef PREE_ENV_H
#define PREE_ENV_H

typedef enum {
    PREE_ENV_NO_AVX2,
    PREE_ENV_TRACER_EMBREE,
    PREE_ENV_GRID_HASHED,
    PREE_ENV_NO_REFILTER,
    PREE_ENV_SCREEN_BLOCKS,
    PREE_ENV_OIIO_MODULE,
    PREE_ENV_POSTROUTE_RECORD,
    PREE_ENV_TEST_INTERRUPT,
    PREE_ENV_TEST_KILL,
    PREE_ENV_TEST_CORRUPT_HP,
    PREE_ENV_COUNT
} pree_env_t;

/* The variable's name (PREE_...). */
const char *pree_env_name(pree_env_t v);
/* Its value, or NULL when it is not set. */
const char *pree_env(pree_env_t v);

#endif
