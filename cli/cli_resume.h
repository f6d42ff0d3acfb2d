// SPDX-License-Identifier: Apache-2.0
/* cli_resume.h: a checkpoint carries the options of its render, so that `pree render --resume
 * FILE` alone continues it as it was. The checkpoint's note (model/ppm/checkpoint.h) is the
 * render's command line in a canonical form, one option a line ("--width 320"; a flag alone;
 * "scene PATH" first; paths absolute). On a resume the options given on the command line that
 * change the bits (the fingerprint's: size, precision, datapath, alpha, grid, skips, PREUs,
 * PipeFast, layout, PREEs, photon offset, light sampling, max bounces) must equal the note's,
 * or the resume is refused naming the option and both values; the others replace the note's:
 * more photons, other outputs (any --out replaces the note's images, --stats its statistics),
 * other checkpoint settings. */
#ifndef PREE_CLI_RESUME_H
#define PREE_CLI_RESUME_H

#include <stddef.h>
#include "render.h"

/* What a render writes besides its options, as the note records it. */
typedef struct {
    const char *scene, *stats;
    const char *const *outs;
    int nout;
    const char *series;     /* the convergence series' options as note lines ("" or NULL: none) */
} cli_resume_job_t;

/* The note of a render: 0, or 2 with the error printed ("pree render: ..."). */
int cli_resume_note(const render_options_t *opt, const cli_resume_job_t *job, char *note, size_t len);

/* The command line of the resumed render: argv (argv[0] the subcommand) with, before its own
 * options, those of the checkpoint's note (rec) that argv does not give (given: the options on
 * argv, by name; has_scene: argv names the scene), and --checkpoint CKPT unless given. Options
 * of argv that change the bits are compared with rec (cmd: argv's own note). 0 with *out_argv
 * allocated (free with cli_resume_free), 1 for a conflict or 2 otherwise, with the error printed. */
int cli_resume_args(const char *ckpt, const char *rec, const char *cmd, const char *const *given, int ngiven,
                    int has_scene, int argc, char **argv, int *out_argc, char ***out_argv);
void cli_resume_free(int argc, char **argv);

#endif
