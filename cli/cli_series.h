// SPDX-License-Identifier: Apache-2.0
/* cli_series.h: `pree render`'s convergence series: --write-every N and --write-at LIST name
 * photon counts at which the render writes its images and statistics (each output NAME.EXT as
 * NAME-COUNT.EXT) on the way to its full count, each with the bits of a render of that count
 * (render_options_t's write_at). */
#ifndef PREE_CLI_SERIES_H
#define PREE_CLI_SERIES_H

#include <stddef.h>
#include <stdint.h>
#include "cli_options.h"

#define CLI_SERIES_MAX 1000   /* points at most */

typedef struct {
    uint64_t every;                  /* --write-every (0: none) */
    uint64_t at[CLI_SERIES_MAX];     /* --write-at, as given */
    int nat;
    uint64_t points[CLI_SERIES_MAX]; /* cli_series_points: ascending, distinct */
    int npoints;
} cli_series_t;

/* The current option's value: --write-every N (every != 0) or --write-at N,N,... Counts are whole
 * numbers of thousands, written plainly or with k (1000) or M (1000000): 100k, 1.5M. 0, or 2
 * with the error printed. */
int cli_series_option(cli_args_t *a, int every, cli_series_t *ser);
/* The points up to the render's photon count `photons` (already whole thousands): 0, or 2 with
 * the error printed (a point beyond it, too many points). */
int cli_series_points(cli_series_t *ser, uint64_t photons);
/* path with "-COUNT" before its extension (out[len]; 0, or -1 when it does not fit). */
int cli_series_name(const char *path, uint64_t photons, char *out, size_t len);
/* The series' options as checkpoint note lines (cli_resume.h) into note[len]. */
void cli_series_note(const cli_series_t *ser, char *note, size_t len);

#endif
