// SPDX-License-Identifier: Apache-2.0
/* image.h: RGB images in memory, smallppm's tone map, and reading/writing PPM, PNG and EXR files.
 *
 * API
 *   pree_image_t               float RGB image: row-major, top row first, 3 floats per pixel
 *   pree_image_alloc/free      allocate (zeroed) / release the pixels of an image
 *   pree_accum_t               double RGB accumulation image, same layout, with alloc/free
 *   pree_tonemap8              smallppm's toInt: linear radiance to an 8-bit value
 *   pree_image_write           write double RGB pixels; format chosen by the file extension
 *   pree_image_write_meta      the same, with name/value metadata in EXR headers
 *   pree_image_write_scaled    the same, 8-bit outputs scaled (an exposure) before the tone curve
 *   pree_image_write_u8        write 8-bit RGB values as they are (.png or .ppm)
 *   pree_image_read            read a .png, .ppm/.pnm or .exr file into a pree_image_t
 *
 * Every function that can fail returns 0 on success and -1 on failure, and then writes one
 * line (no newline) naming the file into the caller's buffer err[errlen] (err may be NULL).
 * Writes are atomic: the pixels go to a temporary file in the destination directory that is
 * renamed over the destination only when complete, so a failed write leaves the destination
 * as it was (absent or the old file) and no temporary behind. */
#ifndef PREE_IMAGE_H
#define PREE_IMAGE_H

#include <stddef.h>

/* Where a read image's values came from: integer samples keep their integer values
 * (an 8-bit PNG reads as 0..255), float samples keep their linear values. */
enum { PREE_SAMPLES_FLOAT = 0, PREE_SAMPLES_U8 = 8, PREE_SAMPLES_U16 = 16 };

typedef struct {
    int width, height;
    float *rgb;       /* width*height*3 floats, pixel (x, y) at rgb[3*(y*width + x)] */
    int samples;      /* PREE_SAMPLES_*: filled by pree_image_read, 0 after alloc */
} pree_image_t;

typedef struct {
    int width, height;
    double *rgb;      /* width*height*3 doubles, same layout as pree_image_t */
} pree_accum_t;

/* Allocate a zeroed w x h image. On error (w or h < 1 or too large, out of memory)
 * returns -1 and leaves *img with rgb = NULL and zero sizes. */
int pree_image_alloc(pree_image_t *img, int w, int h, char *err, size_t errlen);
void pree_image_free(pree_image_t *img);
int pree_accum_alloc(pree_accum_t *acc, int w, int h, char *err, size_t errlen);
void pree_accum_free(pree_accum_t *acc);

/* smallppm's toInt, computed in double in exactly this order: int(pow(1 - exp(-L), 1/2.2)*255 + .5).
 * For L >= 0 (including +inf) the result is 0..255. L < 0 or NaN, which smallppm never
 * produces, gives 0 (the original's behaviour there is undefined). */
int pree_tonemap8(double L);

/* Write w x h pixels of linear radiance, 3 doubles per pixel, row-major, top row first.
 * The extension (case-insensitive) picks the format:
 *   .ppm  smallppm's ASCII output byte for byte: "P3\nW H\n255\n", then "r g b " per pixel
 *         (pree_tonemap8 per channel), no newlines between rows or at the end;
 *   .png  the same tone-mapped 8-bit values, RGB, through OpenImageIO;
 *   .exr  linear radiance as 32-bit float RGB (each double rounded to nearest float),
 *         through OpenImageIO with its default (zip) compression.
 * Any other extension, w or h < 1, or an I/O failure: -1 and the destination is unchanged. */
int pree_image_write(const char *path, int w, int h, const double *rgb, char *err, size_t errlen);

/* pree_image_write, and for .exr the string attributes meta (name/value pairs ending with a
 * NULL name; NULL for none) in the file's header; .png and .ppm files get none. */
int pree_image_write_meta(const char *path, int w, int h, const double *rgb, const char *const *meta,
                          char *err, size_t errlen);

/* pree_image_write_meta, where .png and .ppm files take pree_tonemap8(ldr_scale * L) (an
 * exposure: ldr_scale = 2^EV; 1 gives the same bytes as pree_image_write_meta); .exr files keep
 * the linear radiance as it is. */
int pree_image_write_scaled(const char *path, int w, int h, const double *rgb, const char *const *meta,
                            double ldr_scale, char *err, size_t errlen);

/* Write 8-bit RGB values unchanged (3 bytes per pixel, row-major, top row first) to a .png,
 * or to a .ppm in the same ASCII layout as above. Atomic like pree_image_write. */
int pree_image_write_u8(const char *path, int w, int h, const unsigned char *rgb,
                        char *err, size_t errlen);

/* Read an image into *img (which must not hold pixels; free it first). 8- and 16-bit integer
 * files read as their integer values (0..255, 0..65535) and set img->samples to
 * PREE_SAMPLES_U8/U16; half and float files read as linear values (PREE_SAMPLES_FLOAT).
 * One channel is replicated to RGB; channels beyond the third (alpha) are ignored.
 * On error returns -1 and leaves *img empty (rgb = NULL). */
int pree_image_read(const char *path, pree_image_t *img, char *err, size_t errlen);

#endif
