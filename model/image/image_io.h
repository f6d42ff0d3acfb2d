// SPDX-License-Identifier: Apache-2.0
/* image_io.h: OpenImageIO behind a C API: write 8-bit or float RGB pixels, read any image as RGB.
 *
 * API (used by image.c, which adds the format choice and atomic temporary-file handling)
 *   pree_oiio_write   write w x h RGB pixels (uint8 or float) to a file in a named format
 *   pree_oiio_read    read the first subimage of a file into a pree_image_t
 *
 * Both return 0 on success, -1 on failure with one line naming the file in err[errlen]. */
#ifndef PREE_IMAGE_IO_H
#define PREE_IMAGE_IO_H

#include <stddef.h>
#include "image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Write pixels (3 values per pixel, row-major, top row first) to `path` in the format named by
 * `format` ("png", "exr": an OpenImageIO format or extension name; the name of `path` does not
 * matter). is_float = 0: pixels are unsigned char; 1: pixels are float, stored as 32-bit float.
 * meta: NULL, or name/value string pairs ending with a NULL name, stored as string attributes
 * (EXR header attributes).
 * On failure the file at `path` may be partly written: the caller owns its removal. */
int pree_oiio_write(const char *path, const char *format, int w, int h, int is_float,
                    const void *pixels, const char *const *meta, char *err, size_t errlen);

/* Read `path` into *img, as described for pree_image_read in image.h. */
int pree_oiio_read(const char *path, pree_image_t *img, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
