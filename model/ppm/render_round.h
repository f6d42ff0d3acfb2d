// SPDX-License-Identifier: Apache-2.0
/* render_round.h: the photon pass across more than one MPI rank (render_round.c,
 * docs/scale_out.md). */
#ifndef PREE_RENDER_ROUND_H
#define PREE_RENDER_ROUND_H

#include "render_session.h"

/* The ranks and the partition of the hit points among them (0, or -1 with err); a round of
 * photon blocks (1, 0 when ended, -1 with err); every rank's state and counters to rank 0; the
 * rounds' buffers released (with an exchange in flight: after it ends). */
int render_round_open(render_session_t *s, char *err, size_t errlen);
int render_round_step(render_session_t *s, char *err, size_t errlen);
void render_round_close(render_session_t *s);
void render_round_free(render_session_t *s);

#endif
