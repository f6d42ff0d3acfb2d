// SPDX-License-Identifier: Apache-2.0
/* render_radiance.h: the convergence series' images (render_radiance.c; the session's radiance
 * phase itself, render_radiance, is in render.h). */
#ifndef PREE_RENDER_RADIANCE_H
#define PREE_RENDER_RADIANCE_H

#include "render_session.h"

/* A convergence series' point (render_run.c): the image and statistics of the photons done
 * handed to opt.snapshot, the session left as it was. 0, or -1 with err. */
int render_radiance_snapshot(render_session_t *s, char *err, size_t errlen);

#endif
