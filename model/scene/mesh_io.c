// SPDX-License-Identifier: Apache-2.0
/* mesh_io.c: whole-file reads with transparent gzip (zlib), and the Assimp file system. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <zlib.h>
#include "mesh_io.h"

static int read_gz(const char *path, mesh_blob_t *out, char *err, size_t errlen)
{
    struct stat st;
    if (stat(path, &st) != 0) { snprintf(err, errlen, "%s: %s", path, strerror(errno)); return -1; }
    if (!S_ISREG(st.st_mode)) { snprintf(err, errlen, "%s: not a regular file", path); return -1; }
    gzFile f = gzopen(path, "rb");
    if (!f) { snprintf(err, errlen, "%s: %s", path, errno ? strerror(errno) : "cannot open"); return -1; }
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap + 1);
    int rc = 0;
    while (buf) {
        if (n == cap) {
            if (cap >= MESH_MAX_FILE_BYTES) { snprintf(err, errlen, "%s: larger than 1 GiB", path); rc = -1; break; }
            char *b = realloc(buf, 2 * cap + 1);
            if (!b) break;
            buf = b;
            cap *= 2;
        }
        int got = gzread(f, buf + n, (unsigned)(cap - n > (1u << 30) ? (1u << 30) : cap - n));
        if (got < 0) {
            int zerr;
            const char *m = gzerror(f, &zerr);
            snprintf(err, errlen, "%s: %s", path, zerr == Z_ERRNO ? strerror(errno) : m);
            rc = -1;
            break;
        }
        if (got == 0) {
            int zerr;
            const char *m = gzerror(f, &zerr);
            if (zerr != Z_OK && zerr != Z_STREAM_END) {   /* e.g. a truncated gzip stream */
                size_t pl = strlen(path);   /* zlib's message starts with "PATH: " */
                if (m && !strncmp(m, path, pl) && m[pl] == ':') m += pl + 2;
                snprintf(err, errlen, "%s: %s", path, m && *m ? m : "corrupt gzip data");
                rc = -1;
            }
            break;
        }
        n += (size_t)got;
    }
    gzclose(f);
    if (!buf) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    if (rc) { free(buf); return -1; }
    buf[n] = '\0';
    out->data = buf;
    out->size = n;
    return 0;
}

int mesh_read_file(const char *path, mesh_blob_t *out, char *err, size_t errlen)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        char gz[4096];
        if (snprintf(gz, sizeof gz, "%s.gz", path) < (int)sizeof gz && stat(gz, &st) == 0)
            return read_gz(gz, out, err, errlen);
    }
    return read_gz(path, out, err, errlen);
}

void mesh_blob_free(mesh_blob_t *b)
{
    free(b->data);
    b->data = NULL;
    b->size = 0;
}

/* An open file: a blob (owned unless it is the cached one) and a read position. */
typedef struct { mesh_blob_t blob; int owned; size_t pos; } open_file_t;

static size_t f_read(struct aiFile *f, char *buf, size_t size, size_t count)
{
    open_file_t *o = (open_file_t *)f->UserData;
    if (size == 0) return 0;
    size_t avail = (o->blob.size - o->pos) / size;
    if (count > avail) count = avail;
    memcpy(buf, o->blob.data + o->pos, count * size);
    o->pos += count * size;
    return count;
}

static size_t f_write(struct aiFile *f, const char *buf, size_t size, size_t count)
{
    (void)f; (void)buf; (void)size; (void)count;
    return 0;
}

static size_t f_tell(struct aiFile *f) { return ((open_file_t *)f->UserData)->pos; }
static size_t f_size(struct aiFile *f) { return ((open_file_t *)f->UserData)->blob.size; }
static void f_flush(struct aiFile *f) { (void)f; }

static enum aiReturn f_seek(struct aiFile *f, size_t off, enum aiOrigin origin)
{
    open_file_t *o = (open_file_t *)f->UserData;
    size_t base = origin == aiOrigin_SET ? 0 : origin == aiOrigin_CUR ? o->pos : o->blob.size;
    if (off > o->blob.size - base) return aiReturn_FAILURE;
    o->pos = base + off;
    return aiReturn_SUCCESS;
}

static struct aiFile *io_open(struct aiFileIO *io, const char *path, const char *mode)
{
    mesh_io_t *m = (mesh_io_t *)io;
    if (strchr(mode, 'w') || strchr(mode, 'a')) return NULL;
    struct aiFile *f = calloc(1, sizeof *f);
    open_file_t *o = calloc(1, sizeof *o);
    if (!f || !o) { free(f); free(o); return NULL; }
    if (m->cached && !strcmp(path, m->cached_path)) {
        o->blob = *m->cached;
    } else {
        char err[256];
        if (mesh_read_file(path, &o->blob, err, sizeof err)) { free(f); free(o); return NULL; }
        o->owned = 1;
    }
    f->ReadProc = f_read;
    f->WriteProc = f_write;
    f->TellProc = f_tell;
    f->FileSizeProc = f_size;
    f->SeekProc = f_seek;
    f->FlushProc = f_flush;
    f->UserData = (aiUserData)o;
    return f;
}

static void io_close(struct aiFileIO *io, struct aiFile *f)
{
    (void)io;
    if (!f) return;
    open_file_t *o = (open_file_t *)f->UserData;
    if (o->owned) mesh_blob_free(&o->blob);
    free(o);
    free(f);
}

void mesh_io_assimp(mesh_io_t *io, const char *cached_path, const mesh_blob_t *cached)
{
    memset(io, 0, sizeof *io);
    io->io.OpenProc = io_open;
    io->io.CloseProc = io_close;
    io->io.UserData = NULL;
    io->cached_path = cached_path;
    io->cached = cached;
}
