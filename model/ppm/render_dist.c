// SPDX-License-Identifier: Apache-2.0
/* render_dist.c: the MPI transport of a distributed render (render_dist.h). Without PREE_MPI
 * the program is one rank, and the exchanges are never called. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "render_dist.h"

size_t render_dist_lo(size_t n, int r, int nranks)
{
    return (size_t)((unsigned __int128)n * (unsigned)r / (unsigned)nranks);
}

#ifdef PREE_MPI
#include <mpi.h>

static int ready(void)
{
    int on = 0, off = 0;
    MPI_Initialized(&on);
    MPI_Finalized(&off);
    return on && !off;
}

int render_dist_size(void)
{
    int n = 1;
    if (ready()) MPI_Comm_size(MPI_COMM_WORLD, &n);
    return n;
}

int render_dist_rank(void)
{
    int r = 0;
    if (ready()) MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

int render_dist_max(int v)
{
    int m = v;
    MPI_Allreduce(&v, &m, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return m;
}

/* Bytes travel as MPI_BYTE counts in int: a block's hits are far below 2 GiB. */
int render_dist_allgather(const void *send, size_t bytes, void **recv, size_t *cap, size_t *counts)
{
    const int n = render_dist_size();
    unsigned long long mine = bytes, *all = malloc((size_t)n * sizeof *all);
    int *cnt = malloc((size_t)n * sizeof *cnt), *disp = malloc((size_t)n * sizeof *disp);
    int fail = !all || !cnt || !disp;
    if (!fail) MPI_Allgather(&mine, 1, MPI_UNSIGNED_LONG_LONG, all, 1, MPI_UNSIGNED_LONG_LONG, MPI_COMM_WORLD);
    size_t total = 0;
    for (int r = 0; r < n && !fail; r++) {
        counts[r] = all[r];
        cnt[r] = (int)all[r];
        disp[r] = (int)total;
        total += all[r];
    }
    if (!fail && total > *cap) {
        void *p = realloc(*recv, total);
        if (p) { *recv = p; *cap = total; } else fail = 1;
    }
    fail = render_dist_max(fail);   /* every rank takes part in the exchange, or none */
    if (!fail) MPI_Allgatherv(send, (int)bytes, MPI_BYTE, *recv, cnt, disp, MPI_BYTE, MPI_COMM_WORLD);
    free(all);
    free(cnt);
    free(disp);
    return fail ? -1 : 0;
}

struct render_dist_xchg {
    MPI_Request req;
    int *scnt, *sdisp, *rcnt, *rdisp;   /* alive until the exchange completes */
};

static void xchg_free(render_dist_xchg_t *x)
{
    if (!x) return;
    free(x->scnt);
    free(x->sdisp);
    free(x->rcnt);
    free(x->rdisp);
    free(x);
}

int render_dist_exchange_start(render_dist_xchg_t **out, const void *send, const size_t *sendcounts, void **recv,
                               size_t *cap, size_t *recvcounts)
{
    const int n = render_dist_size();
    render_dist_xchg_t *x = calloc(1, sizeof *x);
    unsigned long long *o = malloc((size_t)n * sizeof *o), *in = malloc((size_t)n * sizeof *in);
    if (x) {
        x->scnt = malloc((size_t)n * sizeof *x->scnt);
        x->sdisp = malloc((size_t)n * sizeof *x->sdisp);
        x->rcnt = malloc((size_t)n * sizeof *x->rcnt);
        x->rdisp = malloc((size_t)n * sizeof *x->rdisp);
    }
    int fail = !x || !o || !in || !x->scnt || !x->sdisp || !x->rcnt || !x->rdisp;
    size_t total = 0, sent = 0;
    for (int d = 0; d < n && !fail; d++) {
        o[d] = sendcounts[d];
        x->scnt[d] = (int)sendcounts[d];
        x->sdisp[d] = (int)sent;
        sent += sendcounts[d];
    }
    fail = render_dist_max(fail || sent > (size_t)INT32_MAX);
    if (!fail) MPI_Alltoall(o, 1, MPI_UNSIGNED_LONG_LONG, in, 1, MPI_UNSIGNED_LONG_LONG, MPI_COMM_WORLD);
    for (int r = 0; r < n && !fail; r++) {
        recvcounts[r] = in[r];
        x->rcnt[r] = (int)in[r];
        x->rdisp[r] = (int)total;
        total += in[r];
    }
    if (!fail && total > *cap) {
        void *p = realloc(*recv, total);
        if (p) { *recv = p; *cap = total; } else fail = 1;
    }
    fail = render_dist_max(fail || total > (size_t)INT32_MAX);   /* every rank takes part, or none */
    if (!fail) MPI_Ialltoallv(send, x->scnt, x->sdisp, MPI_BYTE, *recv, x->rcnt, x->rdisp, MPI_BYTE, MPI_COMM_WORLD, &x->req);
    free(o);
    free(in);
    if (fail) { xchg_free(x); *out = NULL; return -1; }
    *out = x;
    return 0;
}

void render_dist_exchange_poll(render_dist_xchg_t *x)
{
    int done = 0;
    if (x) MPI_Test(&x->req, &done, MPI_STATUS_IGNORE);
}

void render_dist_exchange_wait(render_dist_xchg_t *x)
{
    if (!x) return;
    MPI_Wait(&x->req, MPI_STATUS_IGNORE);
    xchg_free(x);
}

/* In pieces of at most 1 GiB a rank, so that each count fits an int. */
void render_dist_share_ranges(void *base, size_t elem, const size_t *lo)
{
    const int n = render_dist_size();
    const size_t piece = ((size_t)1 << 30) / elem;
    size_t most = 0;
    for (int r = 0; r < n; r++) if (lo[r + 1] - lo[r] > most) most = lo[r + 1] - lo[r];
    for (size_t off = 0; off < most; off += piece)
        for (int r = 0; r < n; r++) {
            const size_t a = lo[r] + off < lo[r + 1] ? lo[r] + off : lo[r + 1];
            const size_t b = lo[r + 1] < a + piece ? lo[r + 1] : a + piece;
            MPI_Bcast((char *)base + a * elem, (int)((b - a) * elem), MPI_BYTE, r, MPI_COMM_WORLD);
        }
}

void render_dist_sum(unsigned long long *v, int n)
{
    MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
}

/* In pieces of at most 1 GiB a rank, so that each count fits an int. */
void render_dist_gather_ranges(void *base, size_t elem, const size_t *lo)
{
    const int n = render_dist_size(), me = render_dist_rank();
    const size_t piece = ((size_t)1 << 30) / elem;
    size_t most = 0;
    for (int r = 0; r < n; r++) if (lo[r + 1] - lo[r] > most) most = lo[r + 1] - lo[r];
    for (size_t off = 0; off < most; off += piece) {
        for (int r = 1; r < n; r++) {
            const size_t a = lo[r] + off, b = lo[r + 1] < a + piece ? lo[r + 1] : a + piece;
            if (a >= b) continue;
            char *p = (char *)base + a * elem;
            if (me == r) MPI_Send(p, (int)((b - a) * elem), MPI_BYTE, 0, 0, MPI_COMM_WORLD);
            else if (me == 0) MPI_Recv(p, (int)((b - a) * elem), MPI_BYTE, r, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        }
    }
}
#else
int render_dist_size(void) { return 1; }
int render_dist_rank(void) { return 0; }
int render_dist_max(int v) { return v; }
int render_dist_allgather(const void *send, size_t bytes, void **recv, size_t *cap, size_t *counts)
{
    if (bytes > *cap) {
        void *p = realloc(*recv, bytes);
        if (!p) return -1;
        *recv = p;
        *cap = bytes;
    }
    if (bytes) memcpy(*recv, send, bytes);
    counts[0] = bytes;
    return 0;
}
struct render_dist_xchg { int unused; };
static struct render_dist_xchg one_rank_xchg;
int render_dist_exchange_start(render_dist_xchg_t **out, const void *send, const size_t *sendcounts, void **recv,
                               size_t *cap, size_t *recvcounts)
{
    if (sendcounts[0] > *cap) {
        void *p = realloc(*recv, sendcounts[0]);
        if (!p) return -1;
        *recv = p;
        *cap = sendcounts[0];
    }
    if (sendcounts[0]) memcpy(*recv, send, sendcounts[0]);
    recvcounts[0] = sendcounts[0];
    *out = &one_rank_xchg;
    return 0;
}
void render_dist_exchange_poll(render_dist_xchg_t *x) { (void)x; }
void render_dist_exchange_wait(render_dist_xchg_t *x) { (void)x; }
void render_dist_share_ranges(void *base, size_t elem, const size_t *lo) { (void)base; (void)elem; (void)lo; }
void render_dist_sum(unsigned long long *v, int n) { (void)v; (void)n; }
void render_dist_gather_ranges(void *base, size_t elem, const size_t *lo) { (void)base; (void)elem; (void)lo; }
#endif
