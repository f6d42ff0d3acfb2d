// SPDX-License-Identifier: Apache-2.0
/* stats_json.h: the render statistics as a JSON file (jansson; written atomically: a temporary
 * file renamed into place). Returns 0, or -1 with a one-line message naming the file in err. */
#ifndef PREE_STATS_JSON_H
#define PREE_STATS_JSON_H

#include <jansson.h>
#include "render.h"

int stats_json_write(const char *path, const char *scene, const render_options_t *opt,
                     const render_stats_t *st, int interrupted, char *err, size_t errlen);
/* The names the statistics (and the EXR metadata) give: "cells", "smallppm", "brute"; "paper",
 * "stable", or "none" for the double mode. */
const char *stats_grid_name(grid_kind_t g);
const char *stats_datapath_name(const render_options_t *opt);
/* The statistics as a JSON object (NULL when out of memory); the caller releases it. */
json_t *stats_json(const char *scene, const render_options_t *opt, const render_stats_t *st, int interrupted);

#endif
