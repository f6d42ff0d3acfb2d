/* render_session.h: the render session's state, shared by the phases (render.c) and the
 * driver with its stopping rules and checkpoints (render_run.c). Private to model/ppm. */
#ifndef PREE_RENDER_SESSION_H
#define PREE_RENDER_SESSION_H

#include "photon_pass.h"
#include "render.h"
#include "update_batch.h"

#define PHOTON_BLOCK RENDER_PHOTON_BLOCK   /* whole batches of 1000 photons */
#define TRACE_CHUNKS 64u
_Static_assert(TRACE_CHUNKS <= UPDATE_BATCH_MAX_CHUNKS, "update_batch_prepare takes at most UPDATE_BATCH_MAX_CHUNKS chunks");

typedef struct {
    photon_hits_t chunk[TRACE_CHUNKS];
    unsigned long long no_cell;
} block_buffers_t;

struct render_session {
    const scene_t *scene;
    render_options_t opt;
    render_result_t *res;
    double t_start, t_photons;
    int T, skip, photon_major, interrupted, last_decile;
    size_t npix;
    grid_t grid;
    block_buffers_t *bb;
    tracer_t *tr;
    uint32_t *perm;
    uint16_t *owner;
    update_batch_t batch;
    update_scratch_t *scratch;
    update_stats_t *ust;
    update_ops_t ops;
    uint64_t emitted_target, done_photons, last_checkpoint;
    uint64_t blocks;         /* blocks updated: the grid is re-filtered after blocks 1, 2, 4, 8, ... */
    uint64_t fingerprint;    /* checkpoint_fingerprint, with a checkpoint or a resume */
    int failed;              /* a step failed: close only releases */
    /* More than one MPI rank (render_dist.c, docs/scale_out.md): rank `rank` of `nranks` owns the
     * hit points [own_lo[rank], own_lo[rank + 1]) of the spatial order; the others' are routed
     * to part T, which no thread applies. */
    int nranks, rank;
    size_t *own_lo;
    void *sendbuf, *recvbuf;
    size_t send_cap, recv_cap, *counts;
    unsigned long long bytes_sent;   /* this rank's bytes to the other ranks */
    int own_block;                   /* the block being applied is the one this rank traced */
};

/* The update counters summed over the threads. */
update_stats_t render_session_update_totals(const render_session_t *s);

/* Continue from opt.resume (render_open, after the grid): 0, or -1 with err. */
int render_session_resume(render_session_t *s, char *err, size_t errlen);

/* Fault injection for the regression (tests/checks/engine_interrupt.sh): with the environment
 * variable PREE_TEST_INTERRUPT=PHASE, raise SIGINT, through the program's handler, as PHASE
 * (bvh, eye, grid, or blockK: this run's K-th photon block) begins; with PREE_TEST_KILL=PHASE,
 * raise SIGKILL there instead (a crash: what survives is the last checkpoint). */
void render_test_interrupt(const char *phase);

#endif
