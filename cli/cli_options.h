// SPDX-License-Identifier: Apache-2.0
/* cli_options.h: the command line of every subcommand: getopt_long scans the options, and
 * strict value checks sit on top of it. Every bad value is a one-line error "pree CMD: ..."
 * and exit status 2.
 *
 * A command lists its long options (struct option, each with an id in .val), starting with
 * CLI_RENDER_LONGOPTS where it takes the shared render options, and scans them with
 * cli_next(); the operands (the scene, the images) are what remains in argv afterwards. */
#ifndef PREE_CLI_OPTIONS_H
#define PREE_CLI_OPTIONS_H

#include <getopt.h>
#include "render.h"

/* Option ids: the shared ones, then each command's own from CLI_OWN. */
enum {
    CLI_HELP = 'h',
    CLI_WIDTH = 0x100, CLI_HEIGHT, CLI_PHOTONS, CLI_PREU, CLI_GRID, CLI_NO_SKIP, CLI_QUIET,
    CLI_DATAPATH, CLI_ALPHA, CLI_THREADS, CLI_PIPE_FAST, CLI_LAYOUT, CLI_HIDE_LIGHTS, CLI_EYE_RAYS,
    CLI_EXPOSURE, CLI_RADIUS,
    CLI_OWN = 0x200
};

/* The options `pree render` and `pree cosim` share (see cli_render_option) and --help. */
#define CLI_RENDER_LONGOPTS                                                           \
    {"help", no_argument, NULL, CLI_HELP},                                            \
    {"width", required_argument, NULL, CLI_WIDTH},                                    \
    {"height", required_argument, NULL, CLI_HEIGHT},                                  \
    {"photons", required_argument, NULL, CLI_PHOTONS},                                \
    {"preu", required_argument, NULL, CLI_PREU},                                      \
    {"grid", required_argument, NULL, CLI_GRID},                                      \
    {"no-skip", no_argument, NULL, CLI_NO_SKIP},                                      \
    {"quiet", no_argument, NULL, CLI_QUIET},                                          \
    {"datapath", required_argument, NULL, CLI_DATAPATH},                              \
    {"alpha", required_argument, NULL, CLI_ALPHA},                                    \
    {"threads", required_argument, NULL, CLI_THREADS},                                \
    {"pipe-fast", no_argument, NULL, CLI_PIPE_FAST},                                  \
    {"layout", required_argument, NULL, CLI_LAYOUT},                                  \
    {"hide-lights", no_argument, NULL, CLI_HIDE_LIGHTS},                              \
    {"eye-rays", required_argument, NULL, CLI_EYE_RAYS},                              \
    {"exposure", required_argument, NULL, CLI_EXPOSURE},                              \
    {"radius", required_argument, NULL, CLI_RADIUS}

typedef struct {
    int argc;
    char **argv;
    const char *cmd;                /* subcommand name for messages */
    const struct option *longopts;  /* terminated by a zero entry */
    const char *val;                /* the current option's value (NULL for a flag) */
    char name[64];                  /* the current option as "--name", for messages */
    render_options_t *render;       /* where cli_next applies CLI_RENDER_LONGOPTS, or NULL */
    int min_size;                   /* the smallest --width/--height there */
} cli_args_t;

/* Start scanning argv (argv[0] is the subcommand's name). With render set, cli_next applies
 * the shared render options to it itself (cli_render_option, images at least min_size). */
void cli_begin(cli_args_t *a, int argc, char **argv, const char *cmd, const struct option *longopts,
               render_options_t *render, int min_size);
/* The next option's id (one the command handles itself); 0 when the options are done (the
 * operands are cli_operands()); -1 on an unknown option, a missing, unexpected or bad value
 * (error printed, the caller returns 2). */
int cli_next(cli_args_t *a);
/* The operands left after the options, and their count. */
char **cli_operands(const cli_args_t *a, int *n);
/* The one operand a command that takes a scene expects: the scene's path, or NULL with the
 * error printed (none, or more than one). */
const char *cli_scene(cli_args_t *a);

/* Print "pree CMD: message" and return 2. */
int cli_error(cli_args_t *a, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The current option's value as an integer in [lo, hi]; 0, or 2 with the error printed. */
int cli_int(cli_args_t *a, long long lo, long long hi, long long *out);
/* The current option's value as a size in bytes: a number, or one with K, M, G or T (powers of
 * 1024), in [1M, 1024T]; 0, or 2 with the error printed. */
int cli_size(cli_args_t *a, uint64_t *out);
/* The current option's value as a real in (lo, hi] (lo_open) or [lo, hi]; 0, or 2. */
int cli_real(cli_args_t *a, double lo, int lo_open, double hi, double *out);
/* The current option's value as one of names[0..n): its index, or -1 (error printed). */
int cli_keyword(cli_args_t *a, const char *const *names, int n);
/* Apply one of CLI_RENDER_LONGOPTS (not --help): --width/--height (at least min_size),
 * --photons, --preu, --grid, --no-skip, --quiet, --datapath paper|stable, --alpha A,
 * --threads T, --pipe-fast, --layout spatial|pixel, --hide-lights, --eye-rays N (1..EYE_RAYS_MAX),
 * --exposure EV (-30..30), --radius R (the initial radius, in (0, 1e30]).
 * Returns 1 when id is not one of them, 0 when it was taken, 2 on an error (printed). */
int cli_render_option(cli_args_t *a, int id, render_options_t *opt, int min_size);
/* 0 when path ends in .png, .ppm or .exr; else 2 with the error printed. */
int cli_image_ext(cli_args_t *a, const char *path);

#endif
