// SPDX-License-Identifier: Apache-2.0
/* render_screen.h: the photon pass's screening and grid re-filter, which the one-process batches
 * (render_step.c) and the MPI rounds (render_round.c) share. */
#ifndef PREE_RENDER_SCREEN_H
#define PREE_RENDER_SCREEN_H

#include "render_session.h"

/* Screen the first `blocks` traced blocks (bb) with the session's T threads into their scratch
 * lists (`lists` of them), each kept candidate in list owner[hit point] (list 0 when owner is
 * NULL). 0 or -1 (memory). */
int render_screen_block(render_session_t *s, const uint16_t *owner, int lists, unsigned blocks);

/* Whether the grid is re-filtered, and a point of the re-filter schedule passed: the re-filter
 * now (0 or -1, memory), or, when recording the PREE's operations, render_refilter_due's flag
 * raised for the caller (render_refilter_due and render_refilter_from: render.h). */
int render_refilter_enabled(const render_session_t *s);
int render_refilter_point(render_session_t *s);

#endif
