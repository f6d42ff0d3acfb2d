// SPDX-License-Identifier: Apache-2.0
/* image.c: RGB image buffers, smallppm's tone map, the ASCII PPM writer, and atomic file writes
 * that choose the format by extension (8-bit PNG through libpng, png_write.c; EXR and every PNG
 * read through image_io.cpp).
 *
 * Loading libOpenImageIO costs every process about 0.3 s of CPU in the dynamic loader (Debian's
 * build pulls in some 260 libraries). Built with -DPREE_OIIO_MODULE='"path/libpree_oiio.so"',
 * image_io.cpp is expected in that shared module instead of in the program, and is loaded on the
 * first EXR write or PNG/EXR read, so renders that write PPM or PNG never pay for it. */
#include "image.h"
#include "image_io.h"
#include "file_in.h"
#include "pree_env.h"
#include "atomic_out.h"
#include "png_write.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#ifdef PREE_OIIO_MODULE
#include <dlfcn.h>
#include <pthread.h>

typedef int (*oiio_write_fn)(const char *, const char *, int, int, int, const void *, const char *const *,
                             char *, size_t);
typedef int (*oiio_read_fn)(const char *, pree_image_t *, char *, size_t);
static oiio_write_fn oiio_write;
static oiio_read_fn oiio_read;
static char oiio_load_error[8192];
static pthread_once_t oiio_once = PTHREAD_ONCE_INIT;

/* Put "<dir><name>" into out[len]; 0 if it fitted. */
static int join_path(char *out, size_t len, const char *dir, const char *name)
{
    int r = snprintf(out, len, "%s%s", dir, name);
    return r < 0 || (size_t)r >= len ? -1 : 0;
}

/* Load the module once, from the first of: $PREE_OIIO_MODULE; libpree_oiio.so beside the
 * program or one directory up (build/pree, build/tests/test_*); the path it was built with. */
static void oiio_load(void)
{
    static char found[4096];
    const char *path = pree_env(PREE_ENV_OIIO_MODULE);   /* an explicit choice is never second-guessed */
    if (!path || !*path) {
        path = PREE_OIIO_MODULE;
        char exe[4096];
        ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
        char *slash = len > 0 ? (exe[len] = 0, strrchr(exe, '/')) : NULL;
        if (slash) {
            slash[1] = 0;
            if (join_path(found, sizeof found, exe, "libpree_oiio.so") == 0 && access(found, R_OK) == 0)
                path = found;
            else if (join_path(found, sizeof found, exe, "../libpree_oiio.so") == 0 && access(found, R_OK) == 0)
                path = found;
        }
    }
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (h) {
        oiio_write = (oiio_write_fn)dlsym(h, "pree_oiio_write");
        oiio_read = (oiio_read_fn)dlsym(h, "pree_oiio_read");
    }
    if (!oiio_write || !oiio_read) {
        const char *why = dlerror();
        snprintf(oiio_load_error, sizeof oiio_load_error, "cannot load the OpenImageIO module %s: %s",
                 path, why ? why : "pree_oiio_read/pree_oiio_write missing");
        oiio_write = NULL;
        oiio_read = NULL;
    }
}

static int oiio_ready(const char *file, char *err, size_t errlen)
{
    pthread_once(&oiio_once, oiio_load);
    if (oiio_write) return 1;
    if (err && errlen) snprintf(err, errlen, "%s: %s", file, oiio_load_error);
    return 0;
}
#define PREE_OIIO_WRITE(file, ...) (oiio_ready(file, err, errlen) ? oiio_write(__VA_ARGS__) : -1)
#define PREE_OIIO_READ(file, ...) (oiio_ready(file, err, errlen) ? oiio_read(__VA_ARGS__) : -1)
#else
#define PREE_OIIO_WRITE(file, ...) pree_oiio_write(__VA_ARGS__)
#define PREE_OIIO_READ(file, ...) pree_oiio_read(__VA_ARGS__)
#endif

/* Largest image accepted anywhere: 2^28 pixels (16384 x 16384). */
#define PREE_IMAGE_MAX_PIXELS ((int64_t)1 << 28)

static int set_err(char *err, size_t errlen, const char *fmt, const char *a, const char *b)
{
    if (err && errlen) snprintf(err, errlen, fmt, a, b);
    return -1;
}

static int check_size(int w, int h, const char *what, char *err, size_t errlen)
{
    if (w < 1 || h < 1 || (int64_t)w * h > PREE_IMAGE_MAX_PIXELS) {
        if (err && errlen)
            snprintf(err, errlen, "%s: bad image size %dx%d (1..16384 each way, at most 2^28 pixels)",
                     what, w, h);
        return -1;
    }
    return 0;
}

int pree_image_alloc(pree_image_t *img, int w, int h, char *err, size_t errlen)
{
    img->width = img->height = 0;
    img->rgb = NULL;
    img->samples = PREE_SAMPLES_FLOAT;
    if (check_size(w, h, "image", err, errlen)) return -1;
    img->rgb = calloc((size_t)w * h * 3, sizeof(float));
    if (!img->rgb) return set_err(err, errlen, "image: %s%s", "out of memory", "");
    img->width = w;
    img->height = h;
    return 0;
}

void pree_image_free(pree_image_t *img)
{
    free(img->rgb);
    img->rgb = NULL;
    img->width = img->height = 0;
}

int pree_accum_alloc(pree_accum_t *acc, int w, int h, char *err, size_t errlen)
{
    acc->width = acc->height = 0;
    acc->rgb = NULL;
    if (check_size(w, h, "image", err, errlen)) return -1;
    acc->rgb = calloc((size_t)w * h * 3, sizeof(double));
    if (!acc->rgb) return set_err(err, errlen, "image: %s%s", "out of memory", "");
    acc->width = w;
    acc->height = h;
    return 0;
}

void pree_accum_free(pree_accum_t *acc)
{
    free(acc->rgb);
    acc->rgb = NULL;
    acc->width = acc->height = 0;
}

int pree_tonemap8(double L)
{
    /* smallppm: int(pow(1-exp(-x),1/2.2)*255+.5); only the undefined cases are guarded. */
    if (!(L >= 0.0)) return 0;
    return (int)(pow(1.0 - exp(-L), 1.0 / 2.2) * 255.0 + 0.5);
}

/* The extension of path's last component (without the dot), or "" when it has none. */
static const char *extension(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    return dot ? dot + 1 : "";
}

/* Write smallppm's ASCII P3 from 8-bit values to the open descriptor fd (which it closes). */
static int write_ppm_fd(int fd, const char *path, int w, int h, const unsigned char *v,
                        char *err, size_t errlen)
{
    /* At most "255 255 255 " = 12 bytes per pixel, plus the header. */
    size_t n = (size_t)w * h, cap = n * 12 + 64, len = 0;
    char *buf = malloc(cap);
    if (!buf) { close(fd); return set_err(err, errlen, "%s: %s", path, "out of memory"); }
    len = (size_t)snprintf(buf, cap, "P3\n%d %d\n255\n", w, h);
    for (size_t i = 0; i < n * 3; i++) {
        unsigned x = v[i];
        if (x >= 100) buf[len++] = (char)('0' + x / 100);
        if (x >= 10) buf[len++] = (char)('0' + x / 10 % 10);
        buf[len++] = (char)('0' + x % 10);
        buf[len++] = ' ';
    }
    for (size_t off = 0; off < len;) {
        ssize_t k = write(fd, buf + off, len - off);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) {
            int e = k < 0 ? errno : EIO;
            free(buf);
            close(fd);
            return set_err(err, errlen, "%s: write failed: %s", path, strerror(e));
        }
        off += (size_t)k;
    }
    free(buf);
    if (close(fd)) return set_err(err, errlen, "%s: write failed: %s", path, strerror(errno));
    return 0;
}

/* Write 8-bit (is_float = 0) or float (1) RGB pixels to path in format ext, atomically. */
static int write_atomic(const char *path, const char *ext, int w, int h, int is_float,
                        const void *pixels, const char *const *meta, char *err, size_t errlen)
{
    char tmp[4096];
    int fd = atomic_out_begin(path, tmp, sizeof tmp, err, errlen);
    if (fd < 0) return -1;
    int rc;
    if (!strcasecmp(ext, "ppm")) {
        rc = write_ppm_fd(fd, path, w, h, pixels, err, errlen);
    } else if (!strcasecmp(ext, "png") && !is_float) {
        rc = png_write_rgb8(fd, path, w, h, pixels, err, errlen);
    } else {
        close(fd);   /* OpenImageIO opens the file by name and truncates it */
        rc = PREE_OIIO_WRITE(path, tmp, ext, w, h, is_float, pixels, meta, err, errlen);
        if (rc && err && errlen) {   /* name the destination, not the temporary */
            size_t tl = strlen(tmp);
            if (!strncmp(err, tmp, tl)) {
                char why[1024];
                snprintf(why, sizeof why, "%s", err + tl);
                snprintf(err, errlen, "%s%s", path, why);
            }
        }
    }
    if (rc) atomic_out_discard(tmp);
    else rc = atomic_out_commit(tmp, path, err, errlen);
    return rc;
}

int pree_image_write(const char *path, int w, int h, const double *rgb, char *err, size_t errlen)
{
    return pree_image_write_meta(path, w, h, rgb, NULL, err, errlen);
}

int pree_image_write_meta(const char *path, int w, int h, const double *rgb, const char *const *meta,
                          char *err, size_t errlen)
{
    return pree_image_write_scaled(path, w, h, rgb, meta, 1.0, err, errlen);
}

int pree_image_write_scaled(const char *path, int w, int h, const double *rgb, const char *const *meta,
                            double ldr_scale, char *err, size_t errlen)
{
    const char *ext = extension(path);
    int is_exr = !strcasecmp(ext, "exr");
    if (!is_exr && strcasecmp(ext, "png") && strcasecmp(ext, "ppm"))
        return set_err(err, errlen, "%s: unknown image extension '%s' (use .ppm, .png or .exr)", path, ext);
    if (check_size(w, h, path, err, errlen)) return -1;
    size_t n = (size_t)w * h * 3;
    void *pix = malloc(n * (is_exr ? sizeof(float) : 1));
    if (!pix) return set_err(err, errlen, "%s: %s", path, "out of memory");
    if (is_exr) {
        float *f = pix;
        for (size_t i = 0; i < n; i++) f[i] = (float)rgb[i];
    } else {
        unsigned char *u = pix;
        for (size_t i = 0; i < n; i++) u[i] = (unsigned char)pree_tonemap8(ldr_scale * rgb[i]);
    }
    int rc = write_atomic(path, ext, w, h, is_exr, pix, is_exr ? meta : NULL, err, errlen);
    free(pix);
    return rc;
}

int pree_image_write_u8(const char *path, int w, int h, const unsigned char *rgb,
                        char *err, size_t errlen)
{
    const char *ext = extension(path);
    if (strcasecmp(ext, "png") && strcasecmp(ext, "ppm"))
        return set_err(err, errlen, "%s: unknown 8-bit image extension '%s' (use .png or .ppm)", path, ext);
    if (check_size(w, h, path, err, errlen)) return -1;
    return write_atomic(path, ext, w, h, 0, rgb, NULL, err, errlen);
}

/* A PNM file being parsed: the whole file in memory and a cursor. */
typedef struct { const unsigned char *p, *end; } pnm_cursor_t;

/* Skip white space and '#' comments; read an unsigned decimal number into *v (< 2^31). */
static int pnm_number(pnm_cursor_t *c, long *v)
{
    for (;;) {
        while (c->p < c->end && (*c->p == ' ' || (*c->p >= '\t' && *c->p <= '\r'))) c->p++;
        if (c->p < c->end && *c->p == '#') {
            while (c->p < c->end && *c->p != '\n') c->p++;
            continue;
        }
        break;
    }
    if (c->p >= c->end || *c->p < '0' || *c->p > '9') return -1;
    long x = 0;
    while (c->p < c->end && *c->p >= '0' && *c->p <= '9') {
        x = x * 10 + (*c->p++ - '0');
        if (x > 0x7fffffffL) return -1;
    }
    *v = x;
    return 0;
}

/* Read a P2/P3 (ASCII) or P5/P6 (binary) file with maxval 255 or 65535 in plain C, so PPM work
 * never needs OpenImageIO. Grey (P2/P5) is replicated to RGB. */
static int read_pnm(const char *path, const unsigned char *buf, size_t len, pree_image_t *img,
                    char *err, size_t errlen)
{
    pnm_cursor_t c = {buf + 2, buf + len};
    const int ascii = buf[1] == '2' || buf[1] == '3', nc = (buf[1] == '3' || buf[1] == '6') ? 3 : 1;
    long w, h, maxval;
    if (pnm_number(&c, &w) || pnm_number(&c, &h) || pnm_number(&c, &maxval))
        return set_err(err, errlen, "%s: %s", path, "malformed PNM header");
    if (maxval != 255 && maxval != 65535)
        return set_err(err, errlen, "%s: %s", path, "unsupported PNM maxval (255 or 65535 only)");
    if (check_size((int)w, (int)h, path, err, errlen)) return -1;
    const size_t n = (size_t)w * h * nc, bytes = maxval > 255 ? 2 : 1;
    if (!ascii) {
        /* Exactly one white-space character separates the header from the samples. */
        if (c.p >= c.end || !(*c.p == ' ' || (*c.p >= '\t' && *c.p <= '\r')) || (size_t)(c.end - c.p - 1) < n * bytes)
            return set_err(err, errlen, "%s: %s", path, "truncated PNM file");
        c.p++;
    }
    float *rgb = malloc((size_t)w * h * 3 * sizeof(float));
    if (!rgb) return set_err(err, errlen, "%s: %s", path, "out of memory");
    for (size_t i = 0; i < n; i++) {
        long v;
        if (ascii) {
            if (pnm_number(&c, &v)) {
                free(rgb);
                return set_err(err, errlen, "%s: %s", path, "truncated or malformed PNM samples");
            }
        } else {
            v = bytes == 1 ? c.p[i] : (long)c.p[2 * i] << 8 | c.p[2 * i + 1];
        }
        if (v > maxval) {
            free(rgb);
            return set_err(err, errlen, "%s: %s", path, "PNM sample above maxval");
        }
        if (nc == 3) rgb[i] = (float)v;
        else rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = (float)v;
    }
    img->width = (int)w;
    img->height = (int)h;
    img->rgb = rgb;
    img->samples = maxval > 255 ? PREE_SAMPLES_U16 : PREE_SAMPLES_U8;
    return 0;
}

int pree_image_read(const char *path, pree_image_t *img, char *err, size_t errlen)
{
    img->width = img->height = 0;
    img->rgb = NULL;
    img->samples = PREE_SAMPLES_FLOAT;

    /* PNM (P2, P3, P5, P6) is read here; everything else by OpenImageIO. */
    FILE *f = file_in_open(path, PREE_INPUT_MAX_BYTES, err, errlen);
    if (!f) return -1;
    unsigned char magic[2] = {0, 0};
    size_t got = fread(magic, 1, 2, f);
    int pnm = got == 2 && magic[0] == 'P' && (magic[1] == '2' || magic[1] == '3' || magic[1] == '5' || magic[1] == '6');
    if (!pnm) {
        fclose(f);
        return PREE_OIIO_READ(path, path, img, err, errlen);
    }
    unsigned char *buf = NULL;
    size_t len = 0, cap = 0;
    int rc = -1;
    if (fseek(f, 0, SEEK_END) == 0) {
        long size = ftell(f);
        if (size > 0 && fseek(f, 0, SEEK_SET) == 0) {
            cap = (size_t)size;
            buf = malloc(cap);
            if (buf) len = fread(buf, 1, cap, f);
        }
    }
    if (!buf || len != cap || ferror(f)) set_err(err, errlen, "%s: %s", path, "cannot read the file");
    else rc = read_pnm(path, buf, len, img, err, errlen);
    free(buf);
    fclose(f);
    return rc;
}
