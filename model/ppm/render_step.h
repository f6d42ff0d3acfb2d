// SPDX-License-Identifier: Apache-2.0
/* render_step.h: the photon pass's steps (render_step.c; render_step itself is in render.h). */
#ifndef PREE_RENDER_STEP_H
#define PREE_RENDER_STEP_H

#include "render_session.h"

/* The batch's cap (screen_blocks) from the scan and PREE_SCREEN_BLOCKS: 0, or -1 with err for a
 * value out of range. */
int render_screen_blocks_set(render_session_t *s, char *err, size_t errlen);

/* The photon pass's target and the threads' update counters and candidate lists (render_eye_pass,
 * after the grid): 0, or -1 with err. */
int render_photon_pass_open(render_session_t *s, char *err, size_t errlen);

/* What only the photon pass uses, freed: the grid, the traced hits, the candidate lists (before
 * the radiance pass, so that its peak does not add to theirs; again at the release). */
void render_photon_pass_free(render_session_t *s);

#endif
