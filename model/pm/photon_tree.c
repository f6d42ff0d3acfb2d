// SPDX-License-Identifier: Apache-2.0
/* photon_tree.c: the kd-tree and its structure-of-arrays copies (see photon_tree.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "photon_tree.h"

int photon_tree_build(photon_tree_t *t, const photon_map_t *map)
{
    memset(t, 0, sizeof *t);
    static const double origin[3] = {0, 0, 0};
    if (kdtree_build(&t->kd, map->n ? map->p[0].x : origin, sizeof *map->p / sizeof(double), map->n)) return -1;
    const size_t m = map->n ? map->n : 1;
    float **arrays[6] = {&t->fx, &t->fy, &t->fz, &t->nx, &t->ny, &t->nz};
    for (int a = 0; a < 6; a++)
        if (!(*arrays[a] = malloc(m * sizeof(float)))) { photon_tree_free(t); return -1; }
    if (!(t->flux = malloc(3 * m * sizeof *t->flux))) { photon_tree_free(t); return -1; }
    for (size_t i = 0; i < map->n; i++) {
        const pm_photon_t *p = &map->p[t->kd.index[i]];
        t->fx[i] = (float)t->kd.x[i]; t->fy[i] = (float)t->kd.y[i]; t->fz[i] = (float)t->kd.z[i];
        t->nx[i] = p->n[0]; t->ny[i] = p->n[1]; t->nz[i] = p->n[2];
        memcpy(t->flux + 3 * i, p->flux, sizeof p->flux);
        for (int a = 0; a < 3; a++) t->extent = fmax(t->extent, fabs(p->x[a]));
    }
    return 0;
}

void photon_tree_free(photon_tree_t *t)
{
    kdtree_free(&t->kd);
    free(t->fx); free(t->fy); free(t->fz); free(t->nx); free(t->ny); free(t->nz); free(t->flux);
    memset(t, 0, sizeof *t);
}
