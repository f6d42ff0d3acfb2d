// SPDX-License-Identifier: Apache-2.0
/* render_dist.h: the transport of a render over MPI ranks (docs/scale_out.md): built on MPI
 * when make finds mpicc (PREE_MPI), otherwise one rank. Only the distributed photon rounds
 * (render_round.c, and render_trace.c's poll of their exchange) exchange through it, and only when
 * render_dist_size() > 1 (the program was started by an MPI launcher with more than one rank and
 * cli/cli_mpi.c initialised MPI). */
#ifndef PREE_RENDER_DIST_H
#define PREE_RENDER_DIST_H

#include <stddef.h>

/* The ranks of MPI_COMM_WORLD (1 when MPI is not built in or not initialised) and this one's. */
int render_dist_size(void);
int render_dist_rank(void);

/* The partition (docs/scale_out.md): rank r of nranks owns the hit points [lo(r), lo(r + 1)) of
 * the n hit points in the spatial order of the photon pass (hp_order.c), contiguous runs of
 * nearby hit points; lo(nranks) = n. */
size_t render_dist_lo(size_t n, int r, int nranks);

/* Every rank's v: the maximum (the ranks agree on stopping or failing). */
int render_dist_max(int v);

/* Every rank's bytes [send, send + bytes) to every rank, in rank order, into *recv (grown;
 * *cap its size); counts[r]: rank r's bytes. 0 or -1 (memory). */
int render_dist_allgather(const void *send, size_t bytes, void **recv, size_t *cap, size_t *counts);

/* An exchange in flight: every rank's send[...] in pieces to every rank, sendcounts[d] bytes
 * (consecutive, in rank order) to rank d, into *recv (grown; *cap its size) in rank order,
 * recvcounts[r] bytes from rank r. Start (the counts travel at once; 0, or -1 on memory on any
 * rank, with no exchange), poll (lets it progress; call it from the thread that started MPI),
 * wait (until *recv holds everything; then send and recv may be reused). */
typedef struct render_dist_xchg render_dist_xchg_t;
int render_dist_exchange_start(render_dist_xchg_t **x, const void *send, const size_t *sendcounts, void **recv,
                               size_t *cap, size_t *recvcounts);
void render_dist_exchange_poll(render_dist_xchg_t *x);
void render_dist_exchange_wait(render_dist_xchg_t *x);

/* Each rank's elements [lo[r], lo[r + 1]) of base (elem bytes each) to every rank. */
void render_dist_share_ranges(void *base, size_t elem, const size_t *lo);

/* Sum v[0..n) over the ranks, on every rank. */
void render_dist_sum(unsigned long long *v, int n);

/* The elements [lo[r], lo[r + 1]) of base (elem bytes each), owned by rank r, to rank 0's base. */
void render_dist_gather_ranges(void *base, size_t elem, const size_t *lo);

#endif
