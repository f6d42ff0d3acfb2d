// SPDX-License-Identifier: Apache-2.0
/* top_bench_abank.h: the top bench's abank scenario (tb/cosim/top_bench.c): a photon stream whose
 * index entries are misplaced on purpose (0..2P-1 entries of random padding between photons
 * instead of the driver's placement), streamed into the RTL by its own host loop, so that an
 * offer spanning two photons reads one index bank twice (stage-A bank conflicts). */
#ifndef TOP_BENCH_ABANK_H
#define TOP_BENCH_ABANK_H

#include <stddef.h>
#include <stdint.h>
#include "cosim_drv.h"

/* The abank scenario's photon stream: index entries in write order, each with the count of
 * photons that must be done (photons_done_o) before it overwrites their entries, and photons
 * with the end of their entries in that order. */
typedef struct {
    uint32_t *e_addr, *e_hp, *e_need;
    size_t ne;
    preu_photon_t *ph;
    uint32_t *p_addr, *p_n;
    size_t *p_eend;
    uint64_t *p_start;          /* absolute index-table position of each photon's first entry */
    size_t nph, oldest;
    uint64_t alloc_end;
} mis_stream_t;

/* Allocates room for photons photons of up to max_cand candidates each. Returns 0 or -1. */
int mis_init(mis_stream_t *m, size_t photons, size_t max_cand);
void mis_free(mis_stream_t *m);
/* Place one photon at a random padding of 0..2P-1 entries (drawn from *rng) after the previous one. */
void mis_add(mis_stream_t *m, int preu, const preu_photon_t *ph, const uint32_t *cand, size_t n, uint64_t *rng);
/* Stream it into the RTL (docs/pree_top.md, "Host protocol"): each cycle up to P entries in
 * order, in distinct banks, once their photons_done condition holds; the head photon once its
 * entries are written, except in random gaps (probability gap, drawn from *rng). Leaves the
 * photon input idle afterwards. Returns 0, or -1 when the stream does not drain. */
int misplaced_stream(cosim_rtl_t *rtl, const mis_stream_t *m, int preu, double gap, uint64_t *rng);

#endif
