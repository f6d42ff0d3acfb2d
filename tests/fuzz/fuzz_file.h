// SPDX-License-Identifier: Apache-2.0
/* fuzz_file.h: the harnesses' helpers: a per-process file name in the current directory,
 * removed at exit, and writing a fuzz input to it (the loaders read files by name). */
#ifndef PREE_FUZZ_FILE_H
#define PREE_FUZZ_FILE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static char fuzz_files[2][64];
static void fuzz_files_remove(void)
{
    for (int i = 0; i < 2; i++)
        if (fuzz_files[i][0]) unlink(fuzz_files[i]);
}

/* "pree-fuzz-PID" + suffix into name; the file is removed at exit (at most two). */
static inline void fuzz_file_name(char *name, size_t len, const char *suffix)
{
    static int n;
    snprintf(name, len, "pree-fuzz-%ld%s", (long)getpid(), suffix);
    if (n == 0) atexit(fuzz_files_remove);
    if (n < 2) snprintf(fuzz_files[n++], sizeof fuzz_files[0], "%s", name);
}

/* Write a fuzz input to path: 0, or -1 when it cannot be written (the input is skipped). */
static inline int fuzz_write_file(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    size_t put = fwrite(data, 1, size, f);
    return (fclose(f) != 0 || put != size) ? -1 : 0;
}

#endif
