// SPDX-License-Identifier: Apache-2.0
/* halton.h: the radical-inverse (Halton) sequence with reverse digit permutation, as in the
 * reference program: dimension b uses the b-th prime (2, 3, 5, ... 283), index j >= 0. */
#ifndef PREE_HALTON_H
#define PREE_HALTON_H

#define HALTON_DIMENSIONS 61

/* Value in [0, 1) of dimension b (0 <= b < HALTON_DIMENSIONS) at index j. */
double halton(int b, long long j);

#endif
