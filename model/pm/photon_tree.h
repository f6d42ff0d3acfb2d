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

/* The exact test every search decides on, in the oracle's expression order (nanoflann's L2
 * metric, then the normal test): photon i's squared distance to q, and whether its normal faces n. */
static inline double photon_d2(const photon_tree_t *t, size_t i, const double q[3])
{
    const double dx = q[0] - t->kd.x[i], dy = q[1] - t->kd.y[i], dz = q[2] - t->kd.z[i];
    return dx * dx + dy * dy + dz * dz;
}
static inline int photon_facing(const photon_tree_t *t, size_t i, const double n[3], double cos_min)
{
    return n[0] * t->nx[i] + n[1] * t->ny[i] + n[2] * t->nz[i] > cos_min;
}

/* 0, or -1 when out of memory. */
int photon_tree_build(photon_tree_t *t, const photon_map_t *map);
void photon_tree_free(photon_tree_t *t);

#endif
