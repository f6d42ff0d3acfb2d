// SPDX-License-Identifier: Apache-2.0
/* pm_render.h: classic two-pass photon mapping (Jensen) with the engine's emission and
 * tracing: the eye pass's hit points as shading points, a photon map of every diffuse photon
 * hit, and at each hit point the radiance estimate from its k nearest photons that pass the
 * PPM update's normal test:
 *     L = weight * (sum of their flux / pi) / (pi r^2 N_emitted),
 * r the distance to the k-th (fewer than k found: the search bound, r0 for the naive search,
 * b_i for the clustered one; docs/photon_map.md). Returns as render_run. */
#ifndef PREE_PM_RENDER_H
#define PREE_PM_RENDER_H

#include "render.h"

int pm_render(const scene_t *scene, const render_options_t *opt, render_result_t *res, char *err, size_t errlen);

#endif
