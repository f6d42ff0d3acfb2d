// SPDX-License-Identifier: Apache-2.0
/* cosim_args.h: the command line of pree cosim beyond the render options it shares with pree
 * render (cli/cli_options.h), scanned with the project's strict value checks. */
#ifndef PREE_COSIM_ARGS_H
#define PREE_COSIM_ARGS_H

#include <stdint.h>
#include "render.h"

/* The command line of pree cosim beyond the render options. */
typedef struct {
    const char *scene, *stats, *out, *trace;
    int reference, reorder, schedule, window, model_only, axi, pipefast;
    int pixel_layout;                  /* --layout pixel */
    int refilter;                      /* --refilter: radii read back at the engine's re-filter points */
    uint64_t win_from, win_to;         /* --trace-window */
    double gap;
} cosim_args_t;

/* Scans the command line into opt and c: -1 to go on, else the exit status (0 after --help, 2 on
 * a usage error, with its message printed). axi_program: 1 in the program that drives pree_axi
 * (build/pree-cosim-axi-*), which needs --axi; the others refuse it. */
int cosim_parse_args(int argc, char **argv, int axi_program, render_options_t *opt, cosim_args_t *c);

#endif
