// SPDX-License-Identifier: Apache-2.0
/* stop.h: a cooperative stop request. A signal handler sets the flag; the long phases (BVH
 * build, eye pass, grid build, photon tracing) poll it and give up with STOP_MESSAGE in err,
 * so that SIGINT or SIGTERM is honoured within a fraction of a second in every phase. */
#ifndef PREE_STOP_H
#define PREE_STOP_H

#include <signal.h>

typedef volatile sig_atomic_t stop_flag_t;

#define STOP_MESSAGE "interrupted"

/* 1 when a stop was asked for (flag may be NULL: never). */
static inline int stop_requested(const stop_flag_t *flag) { return flag && *flag; }

#endif
