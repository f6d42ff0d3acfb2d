// SPDX-License-Identifier: Apache-2.0
/* render_radiance.h: the session's radiance phase (render_radiance.c). */
#ifndef PREE_RENDER_RADIANCE_H
#define PREE_RENDER_RADIANCE_H

#include "render_session.h"

/* The end of the photon pass (render_close, after the photon pass's buffers are freed): its
 * counters into the statistics, the hit points back in address order, their radiance into
 * res->rgb, the hashes. 0, or -1 with err. */
int render_radiance_pass(render_session_t *s, char *err, size_t errlen);

/* A convergence series' point (render_run.c): the image and statistics of the photons done
 * handed to opt.snapshot, the session left as it was. 0, or -1 with err. */
int render_radiance_snapshot(render_session_t *s, char *err, size_t errlen);

#endif
