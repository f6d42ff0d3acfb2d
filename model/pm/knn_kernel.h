// SPDX-License-Identifier: Apache-2.0
/* knn_kernel.h: the clustered search's vector prefilter: one shading point against runs of
 * photons in tree order (structure of arrays, photon_tree.h), vectorised across the photons:
 * 16 float lanes with AVX-512, 8 with AVX2, one at a time in the scalar path. Each photon's
 * float distance and normal products against the point's, in the same float operations on
 * every path (so every path passes the same photons); the tree positions that pass both loose
 * tests are compressed into the output as the kernel runs. The caller rechecks each in double
 * (the exact test): the prefilter's bounds are widened past the float rounding so no photon
 * the exact test would take is dropped.
 *
 * The path is chosen at run time (cpu_features.h: cpu_simd_supported): the widest the processor has, or
 * the one asked for (--knn-kernel). */
#ifndef PREE_KNN_KERNEL_H
#define PREE_KNN_KERNEL_H

#include <stddef.h>
#include <stdint.h>
#include "kdtree.h"
#include "photon_tree.h"

typedef enum { KNN_KERNEL_AUTO = 0, KNN_KERNEL_SCALAR, KNN_KERNEL_AVX2, KNN_KERNEL_AVX512 } knn_kernel_id_t;

/* The positions i in runs r[0..nr) with |q - p_i|^2 <= b2 and n . n_i > cos_lo in float, in
 * increasing order, into out (room for the runs' total length plus 16). Returns their count. */
typedef size_t (*knn_kernel_fn)(const photon_tree_t *t, const kd_range_t *r, size_t nr, const float q[3],
                                const float n[3], float b2, float cos_lo, uint32_t *out);

/* The kernel for id, KNN_KERNEL_AUTO the widest this processor runs; *taken the path it is.
 * NULL when the processor lacks the one asked for. */
knn_kernel_fn knn_kernel_get(knn_kernel_id_t id, knn_kernel_id_t *taken);
/* The kernel calls so far by path (indexed by knn_kernel_id_t), counted by the kernels
 * themselves: the path that ran, whatever was reported. */
void knn_kernel_calls(unsigned long long out[4]);
/* "scalar", "avx2", "avx512" (or "auto"). */
const char *knn_kernel_name(knn_kernel_id_t id);

#endif
