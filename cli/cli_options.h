/* cli_options.h: strict option parsing shared by the subcommands: every bad value is a
 * one-line error "pree CMD: ..." and exit status 2. */
#ifndef PREE_CLI_OPTIONS_H
#define PREE_CLI_OPTIONS_H

#include "render.h"

typedef struct {
    int argc;
    char **argv;
    int i;              /* next argument */
    const char *cmd;    /* subcommand name for messages */
} cli_args_t;

/* Print "pree CMD: message" and return 2. */
int cli_error(cli_args_t *a, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The value after option opt, or NULL (error printed) when missing. */
const char *cli_value(cli_args_t *a, const char *opt);
/* An integer value in [lo, hi]; 0, or 2 with the error printed. */
int cli_int(cli_args_t *a, const char *opt, long long lo, long long hi, long long *out);
/* A size in bytes: a number, or one with K, M, G or T (powers of 1024), in [1M, 1024T];
 * 0, or 2 with the error printed. */
int cli_size(cli_args_t *a, const char *opt, uint64_t *out);
/* A real value in (lo, hi] (lo_open) or [lo, hi]; 0, or 2 with the error printed. */
int cli_real(cli_args_t *a, const char *opt, double lo, int lo_open, double hi, double *out);
/* The render options that `pree render` and `pree cosim` share: --width/--height (at least
 * min_size), --photons, --preu, --grid, --no-skip, --quiet, --datapath paper|stable, --alpha A.
 * Returns 1 when arg is not one of them, 0 when it was taken, 2 on an error (printed). */
int cli_render_option(cli_args_t *a, const char *arg, render_options_t *opt, int min_size);
/* 0 when path ends in .png, .ppm or .exr; else 2 with the error printed. */
int cli_image_ext(cli_args_t *a, const char *path);

#endif
