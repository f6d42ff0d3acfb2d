// SPDX-License-Identifier: Apache-2.0
/* render_checkpoint.h: the session's checkpoints (render_checkpoint.c), in the file format of
 * checkpoint.h. */
#ifndef PREE_RENDER_CHECKPOINT_H
#define PREE_RENDER_CHECKPOINT_H

#include "render_session.h"

/* Continue from opt.resume (render_eye_pass, after the grid): the state, the photons done and the
 * pass counters. 0, or -1 with err. */
int render_checkpoint_resume(render_session_t *s, char *err, size_t errlen);

/* Write the state to opt.checkpoint. 0, or -1 with err. */
int render_checkpoint_write(render_session_t *s, char *err, size_t errlen);

#endif
