// SPDX-License-Identifier: Apache-2.0
/* file_in.h: inputs are read only from regular files of bounded size, so that a directory,
 * a device (/dev/zero), a FIFO or a socket given as a scene or an image is a clear one-line
 * error instead of a hang or an endless read. */
#ifndef PREE_FILE_IN_H
#define PREE_FILE_IN_H

#include <stdio.h>

#define PREE_INPUT_MAX_BYTES (1LL << 30)   /* 1 GiB: scenes and images */

/* Open path for reading ("rb" semantics) when it is a regular file of at most max_bytes.
 * Never blocks on a FIFO. Returns the stream, or NULL with "PATH: why" in err. */
FILE *file_in_open(const char *path, long long max_bytes, char *err, size_t errlen);

#endif
