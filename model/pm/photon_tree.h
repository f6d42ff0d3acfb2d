// SPDX-License-Identifier: Apache-2.0
/* photon_tree.h: the photon map as the fast searches read it, built once per render: the
 * balanced kd-tree (kdtree.h) over the photons' positions, and beside it, in the same tree
 * order, structure-of-arrays copies of what a distance-and-normal test reads: the positions
 * rounded to float (the vector prefilter's), the normals (float, as the map stores them) and
 * the flux.
 * The tree's double positions stay the exact ones every result is decided on. */
#ifndef PREE_PHOTON_TREE_H
#define PREE_PHOTON_TREE_H

#include "kdtree.h"
#include "photon_map.h"

typedef struct {
    kdtree_t kd;                 /* double positions in tree order, tree order -> photon index */
    float *fx, *fy, *fz;         /* positions rounded to float, tree order */
    float *nx, *ny, *nz;         /* normals, tree order */
    double *flux;                /* flux, 3 a photon, tree order (the estimate's reads stay local) */
    double extent;               /* largest |coordinate| of any photon (the float error bound's scale) */
} photon_tree_t;

/* 0, or -1 when out of memory. */
int photon_tree_build(photon_tree_t *t, const photon_map_t *map);
void photon_tree_free(photon_tree_t *t);

#endif
