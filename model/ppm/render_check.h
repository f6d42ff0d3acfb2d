// SPDX-License-Identifier: Apache-2.0
/* render_check.h: the render's result checks (model/ppm/render_check.c). */
#ifndef PREE_RENDER_CHECK_H
#define PREE_RENDER_CHECK_H

#include <stddef.h>
#include <stdint.h>
#include "photon_pass.h"
#include "render.h"

/* res->stats.image_hash and state_hash, for determinism checks. */
void render_hash_results(render_result_t *res, precision_t prec);

/* fp32 mode: every photon hit crosses into the PREE as binary32; a flux or position beyond
 * binary32's range is an error naming the photon (-1 with err), else 0. */
int render_fp32_check_hits(const photon_hits_t *chunk, unsigned nchunks, char *err, size_t errlen);

/* fp32 mode: count the stable datapath's saturated hit points; -1 with err when the image
 * holds an infinite or NaN pixel, else 0. */
int render_fp32_result_check(render_result_t *res, char *err, size_t errlen);

#endif
