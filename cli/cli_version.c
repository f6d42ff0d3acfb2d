// SPDX-License-Identifier: Apache-2.0
/* cli_version.c: the program's version, `git describe --always --dirty --tags` of the tree it was
 * built from, baked in at build time (build/version.h, rewritten by make when it changes). */
#include "cli.h"
#include "version.h"

const char *pree_version(void)
{
    return PREE_VERSION;
}
