// SPDX-License-Identifier: Apache-2.0
/* render_test_hook.h: the render's fault injection for the regression (tests/checks/
 * engine_interrupt.sh, engine_checkpoint.sh): with the environment variable
 * PREE_TEST_INTERRUPT=PHASE, raise SIGINT, through the program's handler, as PHASE (bvh, eye,
 * grid, or blockK: this run's K-th photon block) begins; with PREE_TEST_KILL=PHASE, raise
 * SIGKILL there instead (a crash: what survives is the last checkpoint). */
#ifndef PREE_RENDER_TEST_HOOK_H
#define PREE_RENDER_TEST_HOOK_H

void render_test_interrupt(const char *phase);

#endif
