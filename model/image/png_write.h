// SPDX-License-Identifier: Apache-2.0
/* png_write.h: 8-bit RGB PNG output (libpng), for image.c's writer. */
#ifndef PREE_PNG_WRITE_H
#define PREE_PNG_WRITE_H

#include <stddef.h>

/* Write w x h RGB bytes (rows top to bottom) as a PNG to the open descriptor fd, which it
 * closes. 0, or -1 with "PATH: ..." in err. */
int png_write_rgb8(int fd, const char *path, int w, int h, const unsigned char *rgb, char *err, size_t errlen);

#endif
