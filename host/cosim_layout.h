// SPDX-License-Identifier: Apache-2.0
/* cosim_layout.h: where each hit point lies in the PREE's memory, on one PREE or a board of
 * them under mpirun (docs/pree_top.md, "Hit-point layout"; docs/scale_out.md). */
#ifndef PREE_COSIM_LAYOUT_H
#define PREE_COSIM_LAYOUT_H

#include <stddef.h>
#include <stdint.h>
#include "preu_state.h"

/* A hit point's address in another rank's PREE (render_hp_address translated by cosim_part_t). */
#define OTHER_RANK UINT32_MAX

/* Where each hit point lies in the PREE's memory (docs/pree_top.md, "Hit-point layout").
 * Under mpirun with more than one rank (docs/scale_out.md, "Multi-PREE co-simulation"): every
 * rank runs the whole fp32 engine alone (opt.one_rank) and drives one PREE, which holds only
 * the hit points the rank owns, [lo[rank], lo[rank + 1]) of the photon pass's spatial order
 * (render_dist_lo: the distributed render's partition), at the local addresses i - lo[rank];
 * it is sent only the operations on them. Without mpirun (or with one rank): nranks 1, and
 * addr i (--layout spatial, the default: the same spatial order) or the eye pass's order
 * (--layout pixel: the model's own index after render_radiance). */
typedef struct {
    int nranks, rank;
    size_t *lo;                 /* nranks + 1 */
    uint32_t *addr;             /* photon-pass index -> this PREE's address, or OTHER_RANK */
    uint32_t *model;            /* photon-pass index -> the model's index after render_radiance */
    size_t n_local;
    int spatial;                /* addresses in the photon pass's spatial order (else model's) */
} cosim_part_t;

/* The RTL's words of one hit point and its pixel, as gathered from the ranks. */
typedef struct {
    preu_hpw_t w;
    uint32_t px;
} hp_read_t;

/* This rank's partition of n hit points (p->nranks, p->rank and p->spatial set); perm:
 * render_hp_address. 0, or -1 (memory). */
int cosim_part_open(cosim_part_t *p, size_t n, const uint32_t *perm);
void cosim_part_free(cosim_part_t *p);

#endif
