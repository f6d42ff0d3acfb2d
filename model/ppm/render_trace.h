// SPDX-License-Identifier: Apache-2.0
/* render_trace.h: the photon pass's tracing, which the one-process batches (render_step.c) and
 * the MPI rounds (render_round.c) share: trace the photons of sequence indices [first, first +
 * count) into the block buffers' slot for block `slot` of a batch, dropping hits that reach no
 * hit point's cell when skipping (0, -1 out of memory, or 1: stopped, the block abandoned); and
 * the progress on stderr (a failed write only stops the printing). */
#ifndef PREE_RENDER_TRACE_H
#define PREE_RENDER_TRACE_H

#include "render_session.h"

int render_trace_block(render_session_t *s, uint64_t first, uint64_t count, unsigned slot);
void render_progress(render_session_t *s);

#endif
