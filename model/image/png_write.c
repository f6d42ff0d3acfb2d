// SPDX-License-Identifier: Apache-2.0
/* png_write.c: 8-bit RGB PNG output through libpng, so that a render writing a PNG does not load
 * OpenImageIO's module (about 0.3 s of start-up for its 260 libraries; image.c). */
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "png_write.h"

/* libpng reports errors through a long jump; the message is kept for the caller's line. */
typedef struct {
    char why[256];
} png_err_t;

static void on_error(png_structp png, png_const_charp msg)
{
    png_err_t *e = png_get_error_ptr(png);
    snprintf(e->why, sizeof e->why, "%s", msg);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;   /* nothing a writer of plain 8-bit RGB can be warned of that matters here */
}

int png_write_rgb8(int fd, const char *path, int w, int h, const unsigned char *rgb, char *err, size_t errlen)
{
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
        close(fd);
        return -1;
    }
    png_err_t e = {""};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &e, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        fclose(f);
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    /* volatile: read after the long jump */
    volatile int failed = 0;
    if (setjmp(png_jmpbuf(png))) {
        failed = 1;
    } else {
        png_init_io(png, f);
        png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        for (int y = 0; y < h; y++) png_write_row(png, rgb + (size_t)y * (size_t)w * 3);
        png_write_end(png, NULL);
    }
    png_destroy_write_struct(&png, &info);
    const int io = ferror(f) ? errno : 0;
    if (fclose(f) != 0 && !failed && !io) {
        snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
        return -1;
    }
    if (failed || io) {
        snprintf(err, errlen, "%s: write failed: %s", path, failed ? e.why : strerror(io));
        return -1;
    }
    return 0;
}
