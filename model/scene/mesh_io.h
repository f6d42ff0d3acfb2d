// SPDX-License-Identifier: Apache-2.0
/* mesh_io.h: reading model files into memory for the mesh loader.
 *
 * mesh_read_file() reads a whole file, gunzipping it if it is gzip-compressed (zlib reads
 * plain files unchanged); when PATH does not exist but PATH.gz does, it reads that. Returns
 * 0 or -1 with "PATH: reason" in err. mesh_io_assimp() fills an Assimp file system whose
 * opens go through mesh_read_file(), serving 'cached' (the model file already read) without
 * reading it again; it must outlive the import. */
#ifndef PREE_MESH_IO_H
#define PREE_MESH_IO_H

#include <stddef.h>
#include <assimp/cfileio.h>

typedef struct { char *data; size_t size; } mesh_blob_t;

#define MESH_MAX_FILE_BYTES ((size_t)1 << 30)

int mesh_read_file(const char *path, mesh_blob_t *out, char *err, size_t errlen);
void mesh_blob_free(mesh_blob_t *b);

typedef struct {
    struct aiFileIO io;
    const char *cached_path;
    const mesh_blob_t *cached;
} mesh_io_t;

void mesh_io_assimp(mesh_io_t *io, const char *cached_path, const mesh_blob_t *cached);

#endif
