// SPDX-License-Identifier: Apache-2.0
/* render_test_hook.c: the render's fault injection (see render_test_hook.h). */
#include <signal.h>
#include <string.h>
#include "pree_env.h"
#include "render_test_hook.h"

void render_test_interrupt(const char *phase)
{
    const char *want = pree_env(PREE_ENV_TEST_INTERRUPT), *kill = pree_env(PREE_ENV_TEST_KILL);
    if (want && !strcmp(want, phase)) raise(SIGINT);
    if (kill && !strcmp(kill, phase)) raise(SIGKILL);
}
