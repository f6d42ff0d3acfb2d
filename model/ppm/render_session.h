// SPDX-License-Identifier: Apache-2.0
/* render_session.h: the render session's state, shared by the phases (render.c) and the
 * driver with its stopping rules and checkpoints (render_run.c). Private to model/ppm. */
#ifndef PREE_RENDER_SESSION_H
#define PREE_RENDER_SESSION_H

#include "photon_pass.h"
#include "render.h"
#include "render_dist.h"
#include "update_batch.h"

#define PHOTON_BLOCK RENDER_PHOTON_BLOCK   /* whole batches of 1000 photons */
#define TRACE_CHUNKS 64u
/* Photon blocks traced before one update (a screening batch, render_step.c): the update screens
 * them together against the radii at the batch's start and applies them in photon order. */
#define SCREEN_BLOCKS_MAX 4u
_Static_assert(TRACE_CHUNKS * SCREEN_BLOCKS_MAX <= UPDATE_BATCH_MAX_CHUNKS,
               "update_batch_prepare takes at most UPDATE_BATCH_MAX_CHUNKS chunks");

/* The traced hits: block k of a batch in chunk[k * TRACE_CHUNKS ..], in photon order. */
typedef struct {
    photon_hits_t chunk[TRACE_CHUNKS * SCREEN_BLOCKS_MAX];
    unsigned long long no_cell;
} block_buffers_t;

/* A round's exchange buffers: what this rank sends each owner, and what it receives. */
typedef struct {
    void *send, *recv;
    size_t send_cap, recv_cap, *sendcounts, *recvcounts;
} round_slot_t;

struct render_session {
    const scene_t *scene;
    render_options_t opt;
    render_result_t *res;
    double t_start, t_photons, cpu_start;   /* cpu_start: the process's CPU seconds at render_open */
    int T, skip, photon_major, interrupted, last_decile;
    unsigned screen_blocks;  /* blocks a screening batch takes at most (1 .. SCREEN_BLOCKS_MAX) */
    int screen_forced;       /* screen_blocks set by PREE_SCREEN_BLOCKS: no memory rule */
    size_t hits_per_block, kept_per_block, kept_most;   /* the last batch's, per block; the most kept */
    size_t grid_dropped_first;   /* grid entries the first block's re-filter dropped */
    size_t npix;
    grid_t grid;
    update_prefilter_t prefilter;   /* the screening's binary32 prefilter (update_prefilter.h) */
    block_buffers_t *bb;
    tracer_t *tr;
    uint32_t *perm;
    uint16_t *owner;
    uint32_t *owner_end;   /* owner[] as ranges: part p owns [owner_end[p-1], owner_end[p]) (NULL
                            * where it is not monotone) */
    update_batch_t batch;
    update_scratch_t *scratch;
    update_stats_t *ust;
    update_ops_t ops;
    uint64_t emitted_target, done_photons, last_checkpoint;
    int next_write;          /* the convergence series' next point (opt.write_at[next_write]) */
    uint64_t blocks;         /* blocks updated: the grid is re-filtered after blocks 1, 2, 4, 8, ... */
    int refilter_due;        /* recording the PREE's operations: such a point passed, the caller's
                              * re-filter (render_refilter_from) not yet made */
    uint64_t fingerprint;    /* checkpoint_fingerprint, with a checkpoint or a resume */
    int failed;              /* a step failed: close only releases */
    /* More than one MPI rank (render_round.c, docs/scale_out.md): rank `rank` of `nranks` owns
     * the hit points [own_lo[rank], own_lo[rank + 1]) of the spatial order (rank_of[i]: hit point
     * i's rank); the others' are in part T, which no thread applies. */
    int nranks, rank;
    size_t *own_lo;
    uint16_t *rank_of;
    void *recvbuf;                   /* the ranks' error messages */
    size_t recv_cap, *counts;
    round_slot_t slot[2];            /* rounds alternate: one exchange in flight, one being packed */
    render_dist_xchg_t *pending;     /* the exchange in flight (slot[pending_slot]), or NULL */
    int pending_slot;
    uint64_t next_photon;            /* the first photon of the next round */
    update_scratch_t xs;             /* one owner's kept candidates, grouped by hit, to pack */
    photon_hit_t *rhits;             /* a received segment's photons */
    const photon_hit_t **rhit_ptr;
    size_t rhits_cap, rptr_cap;
    unsigned long long bytes_sent;   /* this rank's bytes to the other ranks */
};

/* The photon pass's steps that render_round.c shares (render_trace.c, render_step.c): trace the
 * photons of sequence indices [first, first + count) into the block buffers' slot for block
 * `slot` of a batch, dropping hits that reach no hit point's cell when skipping (0, -1 out of
 * memory, or 1: stopped, the block abandoned); progress on stderr (a failed write only stops the
 * printing); whether the grid is re-filtered, and a re-filter now (0 or -1). */
int render_trace_block(render_session_t *s, uint64_t first, uint64_t count, unsigned slot);
void render_progress(render_session_t *s);
int render_refilter_enabled(const render_session_t *s);
/* A point of the re-filter schedule passed: the re-filter now (0 or -1, memory), or, when recording
 * the PREE's operations, render_refilter_due's flag raised for the caller. */
int render_refilter_point(render_session_t *s);
/* Screen the first `blocks` traced blocks (bb) with the session's T threads into their scratch
 * lists (`lists` of them), each kept candidate in list owner[hit point] (list 0 when owner is
 * NULL). 0 or -1 (memory). */
int render_screen_block(render_session_t *s, const uint16_t *owner, int lists, unsigned blocks);

/* More than one MPI rank (render_round.c): the partition (0, or -1 with err), a round of photon
 * blocks (1, 0 when ended, -1 with err), and every rank's state and counters to rank 0. */
int render_round_open(render_session_t *s, char *err, size_t errlen);
int render_round_step(render_session_t *s, char *err, size_t errlen);
void render_round_close(render_session_t *s);

/* The batch's cap (screen_blocks) from the scan and PREE_SCREEN_BLOCKS (render_step.c): 0, or
 * -1 with err for a value out of range. */
int render_screen_blocks_set(render_session_t *s, char *err, size_t errlen);

/* Photons between checkpoints (render_run.c writes one after the block that reaches it). */
static inline uint64_t render_checkpoint_every(const render_options_t *opt)
{
    return opt->checkpoint_every ? opt->checkpoint_every : RENDER_CHECKPOINT_EVERY;
}

/* The update counters summed over the threads. */
update_stats_t render_session_update_totals(const render_session_t *s);

/* Where the photon pass stops next: the series' next point, or the end (render_step.c). */
static inline uint64_t render_stop_at(const render_session_t *s)
{
    return s->next_write < s->opt.write_at_n && s->opt.write_at[s->next_write] < s->emitted_target
         ? s->opt.write_at[s->next_write] : s->emitted_target;
}

/* The convergence series' point reached (render.c): the image and statistics of the photons
 * done handed to opt.snapshot, the state left as it was. 0, or -1 with err. */
int render_session_snapshot(render_session_t *s, char *err, size_t errlen);

/* Continue from opt.resume (render_open, after the grid): 0, or -1 with err. */
int render_session_resume(render_session_t *s, char *err, size_t errlen);

/* Fault injection for the regression (tests/checks/engine_interrupt.sh): with the environment
 * variable PREE_TEST_INTERRUPT=PHASE, raise SIGINT, through the program's handler, as PHASE
 * (bvh, eye, grid, or blockK: this run's K-th photon block) begins; with PREE_TEST_KILL=PHASE,
 * raise SIGKILL there instead (a crash: what survives is the last checkpoint). */
void render_test_interrupt(const char *phase);

#endif
