// SPDX-License-Identifier: Apache-2.0
/* cli_outputs.h: every output path is checked before any work starts, so that a bad one
 * costs nothing and never leaves some outputs written and others not: its directory exists
 * and is writable, its name fits the file system (the temporary's too), it is absent or a
 * regular file (model/util/atomic_out.h), and it is neither an input nor another output
 * (compared by device and inode, so links and other spellings of a path are caught). */
#ifndef PREE_CLI_OUTPUTS_H
#define PREE_CLI_OUTPUTS_H

typedef struct {
    const char *what;   /* for messages: "--out", "--stats", "the scene", "IMAGE_A" */
    const char *path;
} cli_file_t;

/* 0 when every output may be written; else 1 with "pree CMD: PATH: why" printed. */
int cli_outputs_check(const char *cmd, const cli_file_t *in, int nin, const cli_file_t *out, int nout);

#endif
