// SPDX-License-Identifier: Apache-2.0
/* render_setup.h: the eye pass's steps, in the order render_eye_pass (render.h, also in
 * render_setup.c) takes them. Each sets *phase to the name of the step under way (an interrupt's message
 * says where it stopped) and returns 0, or -1 with err. */
#ifndef PREE_RENDER_SETUP_H
#define PREE_RENDER_SETUP_H

#include "render_session.h"

/* The BVH build and the eye pass: the hit points, their figures, the memory check with their
 * true count (and the checkpoint fingerprint, with a checkpoint or a resume). */
int render_setup_eye(render_session_t *s, const char **phase, char *err, size_t errlen);

/* The grid: the initial radius, the spatial order of the hit points, their state, the owners
 * (under MPI the ranks' partition, render_round_open) and the grid. */
int render_setup_grid(render_session_t *s, const char **phase, char *err, size_t errlen);

#endif
