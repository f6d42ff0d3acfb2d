// SPDX-License-Identifier: Apache-2.0
/* checkpoint.h: a long render's state on disk, so that it can stop and resume to the same bits.
 *
 * A checkpoint holds the photons done, the photon pass's counters and every hit point's state
 * (r2, count and flux in double mode; the PREU words and the screening bound in fp32 mode) in
 * hit-point address order, so a resume may use any thread count. Its fingerprint covers the
 * build (format, state layout, compiler), the options that change the bits, the scene, and the
 * eye pass's hit points; a resume with another fingerprint is refused. The file ends with an
 * FNV-1a of its bytes, so a truncated or corrupt one is refused too. Written atomically (a
 * temporary file beside the target, flushed to disk, then renamed over it). After the header the
 * file holds a note, text the engine does not read: the command line's options (cli/cli_resume.c),
 * so that a resume needs no options. */
#ifndef PREE_CHECKPOINT_H
#define PREE_CHECKPOINT_H

#include <stddef.h>
#include <stdint.h>
#include "render.h"

/* The longest note a checkpoint holds (the render's options as text, render_options_t's
 * checkpoint_note). */
#define CHECKPOINT_NOTE_MAX 65536

typedef struct {
    uint64_t fingerprint;
    uint64_t done_photons;
    unsigned long long photon_hits, photon_segments, no_cell;
    update_stats_t upd;
    const char *note;     /* save: the note written (NULL: none); load leaves it NULL */
} checkpoint_info_t;

/* The fingerprint of a render: build, options, scene, and the hit points h (address order,
 * before the photon pass reorders them). */
uint64_t checkpoint_fingerprint(const scene_t *scene, const render_options_t *opt, const hitpoints_t *h);

/* Write info and h's state; h is in the photon pass's order, perm[i] the address of index i.
 * 0, or -1 with "PATH: reason" in err (the target is then untouched). */
int checkpoint_save(const char *path, const checkpoint_info_t *info, const hitpoints_t *h, const uint32_t *perm,
                    precision_t prec, char *err, size_t errlen);

/* Read a checkpoint into info and h (same order convention). info->fingerprint is the
 * expected one on entry. 0, or -1 with "PATH: reason" in err. */
int checkpoint_load(const char *path, checkpoint_info_t *info, hitpoints_t *h, const uint32_t *perm,
                    precision_t prec, char *err, size_t errlen);

/* The note of the checkpoint at path (NUL-terminated, at most CHECKPOINT_NOTE_MAX bytes, into
 * note[cap]) and the photons it holds, read without checking the rest of the file (the resume
 * does). 0, or -1 with "PATH: reason" in err. */
int checkpoint_read_note(const char *path, char *note, size_t cap, uint64_t *done_photons, char *err, size_t errlen);

/* Whether a checkpoint can be written at path: creates and removes its temporary file.
 * 0, or -1 with "PATH: reason" in err. */
int checkpoint_probe(const char *path, char *err, size_t errlen);

#endif
