// SPDX-License-Identifier: Apache-2.0
/* render_session.h: the render session's state, which its phases' modules share (render_run.c
 * lists them in order, docs/engine.md "The render session"), and the small reads of it that
 * several of them make. Private to model/ppm; each module's functions are in its own header. */
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
    int failed;              /* a phase or step failed: the later phases do nothing, close only
                              * releases */
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

/* Photons between checkpoints (render_run.c writes one after the block that reaches it). */
static inline uint64_t render_checkpoint_every(const render_options_t *opt)
{
    return opt->checkpoint_every ? opt->checkpoint_every : RENDER_CHECKPOINT_EVERY;
}

/* The update counters summed over the threads. */
static inline update_stats_t render_session_update_totals(const render_session_t *s)
{
    update_stats_t u = {0, 0, 0, 0};
    for (int p = 0; p < s->T; p++) {
        u.candidates += s->ust[p].candidates;
        u.skipped_radius += s->ust[p].skipped_radius;
        u.normal_passed += s->ust[p].normal_passed;
        u.accepted += s->ust[p].accepted;
    }
    return u;
}

/* Where the photon pass stops next: the series' next point, or the end (render_step.c). */
static inline uint64_t render_stop_at(const render_session_t *s)
{
    return s->next_write < s->opt.write_at_n && s->opt.write_at[s->next_write] < s->emitted_target
         ? s->opt.write_at[s->next_write] : s->emitted_target;
}

#endif
