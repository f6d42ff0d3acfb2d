// SPDX-License-Identifier: Apache-2.0
/* pbrt_ply.h: the triangles of a PLY file for pbrt's "plymesh" (pbrt_ply.c): ASCII or binary
 * (either byte order); vertex x y z (and nx ny nz), faces as lists of 3 or 4 vertex indices
 * (a quad gives two triangles). */
#ifndef PREE_PBRT_PLY_H
#define PREE_PBRT_PLY_H

#include <stddef.h>

typedef struct {
    double *points;     /* 3 per vertex */
    double *normals;    /* 3 per vertex, or NULL */
    double *indices;    /* 3 per triangle */
    size_t num_points, num_triangles;
} pbrt_ply_t;

/* 0, or -1 with "PATH: what" in err. */
int pbrt_ply_read(const char *path, pbrt_ply_t *out, char *err, size_t errlen);
void pbrt_ply_free(pbrt_ply_t *p);

#endif
