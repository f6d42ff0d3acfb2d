// SPDX-License-Identifier: Apache-2.0
/* knn_kernel.h: the clustered search's vector kernel: one shading point against runs of photons
 * in tree order (structure of arrays, photon_tree.h), vectorised across the photons: 16 float
 * lanes with AVX-512, 8 with AVX2, one at a time in the scalar path.
 *
 * Two tests a photon. The float prefilter: its float distance to the point, within a bound
 * widened past the float rounding (so no photon the exact test takes is dropped); a step of
 * photons none of which passes reads nothing more. The exact test, on the photons that pass it:
 * the double distance and the normal product in the oracle's expression order (photon_tree.h's
 * photon_d2 and photon_facing: d2 = (dx dx + dy dy) + dz dz, dot = (n0 nx + n1 ny) + n2 nz,
 * 8 double lanes with AVX-512, 4 with AVX2, separate multiplies and adds, no fused
 * multiply-add), so every path passes the same photons with the same d2, the oracle's bits. The
 * positions and d2 that pass both are compressed into the output as the kernel runs.
 *
 * The path is chosen at run time (cpu_features.h: cpu_simd_supported): the widest the processor
 * has, or the one asked for (--knn-kernel). */
#ifndef PREE_KNN_KERNEL_H
#define PREE_KNN_KERNEL_H

#include <stddef.h>
#include <stdint.h>
#include "kdtree.h"
#include "photon_tree.h"

typedef enum { KNN_KERNEL_AUTO = 0, KNN_KERNEL_SCALAR, KNN_KERNEL_AVX2, KNN_KERNEL_AVX512 } knn_kernel_id_t;

/* One shading point's tests. */
typedef struct {
    double q[3], n[3];     /* the point and its normal */
    double b2, cos_min;    /* the exact test: d2 <= b2 and dot > cos_min */
    float qf[3], b2f;      /* the prefilter: the point in float, the widened squared bound */
} knn_probe_t;

/* The kernel's output, as arrays (each with room for the runs' total length plus 16): tree
 * positions and their squared distances. */
typedef struct {
    uint32_t *pos;
    double *d2;
} knn_hits_t;

/* The positions i in runs r[0..nr) that pass both tests, in increasing order, into out;
 * *prefiltered += the photons that passed the prefilter (the exact tests computed). Returns their
 * count. */
typedef size_t (*knn_kernel_fn)(const photon_tree_t *t, const kd_range_t *r, size_t nr, const knn_probe_t *p,
                                knn_hits_t *out, unsigned long long *prefiltered);

/* The kernel for id, KNN_KERNEL_AUTO the widest this processor runs; *taken the path it is.
 * NULL when the processor lacks the one asked for. */
knn_kernel_fn knn_kernel_get(knn_kernel_id_t id, knn_kernel_id_t *taken);
/* The kernel calls so far by path (indexed by knn_kernel_id_t), counted by the kernels
 * themselves: the path that ran, whatever was reported. */
void knn_kernel_calls(unsigned long long out[4]);
/* "scalar", "avx2", "avx512" (or "auto"). */
const char *knn_kernel_name(knn_kernel_id_t id);

#endif
