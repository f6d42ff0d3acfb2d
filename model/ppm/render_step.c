// SPDX-License-Identifier: Apache-2.0
/* render_step.c: one step of the photon pass (render_step, render.h): under MPI with more than one
 * rank a round (render_round.h); in one process a screening batch of up to SCREEN_BLOCKS_MAX photon
 * blocks: each block traced in turn into its slot of the block buffers (render_trace.h), then the
 * whole batch updated at once (screened bucket-major against the radii at the batch's start,
 * render_screen.h, applied in photon order, model/ppm/update_batch.c), then each block counted as
 * done.
 *
 * The bits are those of block-by-block updates: radii only shrink, so screening against the
 * batch's first radii keeps every candidate a block's own screening would keep, and the apply
 * tests each against the current radius in photon order. The counters too: a batch ends where
 * the grid is re-filtered (after blocks 1, 2, 4, 8, ...), so every block of it is screened
 * against the grid it would have met alone; and where a checkpoint falls due, so checkpoints hold
 * the same photons. A stop (interrupt, time limit) ends the batch after its last whole block. */
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pree_env.h"
#include "render_check.h"
#include "render_round.h"
#include "render_screen.h"
#include "render_step.h"
#include "render_test_hook.h"
#include "render_trace.h"

/* PREE_SCREEN_BLOCKS=K (1 .. SCREEN_BLOCKS_MAX) sets the batch to K blocks whatever the memory
 * (still cut at re-filters and checkpoints), for the regression (tests/checks/engine_screen_batch.sh)
 * and make bench's before/after rows (like PREE_NO_REFILTER); the photon-major scan (and so the
 * co-simulation's recording) updates block by block, and so does the distributed render
 * (render_round.c, its own steps). */
int render_screen_blocks_set(render_session_t *s, char *err, size_t errlen)
{
    s->screen_blocks = SCREEN_BLOCKS_MAX;
    s->screen_forced = 0;
    const char *v = pree_env(PREE_ENV_SCREEN_BLOCKS);
    if (v) {
        char *end;
        const unsigned long k = strtoul(v, &end, 10);
        if (end == v || *end || k < 1 || k > SCREEN_BLOCKS_MAX) {
            snprintf(err, errlen, "PREE_SCREEN_BLOCKS=%s: expected a whole number from 1 to %u", v, SCREEN_BLOCKS_MAX);
            return -1;
        }
        s->screen_blocks = (unsigned)k;
        s->screen_forced = 1;
    }
    if (s->photon_major) s->screen_blocks = 1;
    return 0;
}

/* The update of the first `blocks` traced blocks: photon-major per owned part, or screened
 * bucket-major and applied per part. 0 or -1 (out of memory). */
static int update_batch_blocks(render_session_t *s, unsigned blocks)
{
    hitpoints_t *h = &s->res->hp;
    const precision_t prec = s->opt.precision;
    const int T = s->T;
    const photon_hits_t *chunk = s->bb->chunk;
    if (s->photon_major) {
        update_ops_t *ops = s->opt.record_ops ? &s->ops : NULL;
#pragma omp parallel num_threads(T)
        {
            const int p = omp_get_thread_num();
            for (unsigned c = 0; c < TRACE_CHUNKS * blocks; c++)
                update_part(h, &s->grid, p, prec, s->skip, chunk[c].hits, chunk[c].n, &s->ust[p], ops);
        }
        return ops && ops->failed ? -1 : 0;
    }
    if (render_screen_block(s, T > 1 ? s->owner : NULL, T, blocks)) return -1;
    int failed = 0;   /* applying: each thread its own part */
#pragma omp parallel for num_threads(T) schedule(static, 1) reduction(| : failed)
    for (int q = 0; q < T; q++)
        failed |= update_batch_apply(h, prec, &s->batch, q, s->scratch, T, &s->ust[omp_get_thread_num()]);
    return failed ? -1 : 0;
}

/* After each block: a re-filter when the block count is a power of two. 0 or -1 (memory). */
static int refilter_block(render_session_t *s)
{
    s->blocks++;
    if (s->blocks & (s->blocks - 1)) return 0;
    return render_refilter_point(s);
}

/* What the last batch of n blocks held, per block (its hits and kept candidates), and the most
 * candidates any batch kept (the lists keep their capacity). */
static void batch_measure(render_session_t *s, unsigned n)
{
    const size_t kept = update_batch_kept(s->scratch, s->T);
    s->hits_per_block = s->batch.n / n;
    s->kept_per_block = kept / n;
    if (kept > s->kept_most) s->kept_most = kept;
}

/* The memory a batch of k blocks adds to a one-block batch's: k - 1 more blocks of traced hits
 * (with their batch copies), and the kept lists' growth past the most kept so far; half as much
 * again for what the arrays' growth leaves unused and the lists' uneven split over threads and
 * parts. */
static uint64_t batch_extra_bytes(const render_session_t *s, uint64_t k)
{
    const uint64_t hit = sizeof(photon_hit_t) + UPDATE_BATCH_HIT_BYTES;
    const uint64_t kept = k * s->kept_per_block;
    const uint64_t extra = (k - 1) * s->hits_per_block * hit +
                           (kept > s->kept_most ? (kept - s->kept_most) * update_batch_kept_bytes() : 0);
    return extra + extra / 2;
}

/* Blocks the next batch may take: at most screen_blocks; unless forced, no more than the memory that the
 * re-filters after the first have given back pays for (the photon pass's peak, that of the first
 * blocks with the whole grid, stays where one-block batches put it: they go one at a time); up to
 * the next re-filter (the block count's next power of two); and up to the block after which a
 * checkpoint falls due. */
static unsigned batch_blocks(const render_session_t *s)
{
    const render_stats_t *st = &s->res->stats;
    uint64_t k = s->screen_blocks;
    const uint64_t freed = (uint64_t)(st->grid_entries - st->grid_entries_final - s->grid_dropped_first) * GRID_ENTRY_BYTES;
    while (!s->screen_forced && k > 1 && (!s->hits_per_block || batch_extra_bytes(s, k) > freed)) k--;
    if (render_refilter_enabled(s)) {
        uint64_t next = 1;
        while (next <= s->blocks) next <<= 1;
        if (next - s->blocks < k) k = next - s->blocks;
    }
    if (s->opt.checkpoint) {
        const uint64_t every = render_checkpoint_every(&s->opt), since = s->done_photons - s->last_checkpoint;
        const uint64_t left = every > since ? every - since : 1;
        const uint64_t due = (left + PHOTON_BLOCK - 1) / PHOTON_BLOCK;
        if (due < k) k = due;
    }
    return (unsigned)k;
}

/* Whether the batch stops taking blocks: an interrupt, or the time limit passed. */
static int batch_should_end(const render_session_t *s)
{
    if (s->opt.interrupt && *s->opt.interrupt) return 1;
    return s->opt.time_limit > 0 && omp_get_wtime() - s->t_start >= s->opt.time_limit;
}

/* Count block `slot` of the batch as done: its photons, hits and segments, the re-filter after it
 * and the progress line. 0 or -1 (memory). */
static int finish_block(render_session_t *s, unsigned slot, uint64_t count)
{
    render_stats_t *st = &s->res->stats;
    if (refilter_block(s)) return -1;
    if (s->blocks == 1) s->grid_dropped_first = st->grid_entries - st->grid_entries_final;
    photon_hits_t *chunk = s->bb->chunk + (size_t)slot * TRACE_CHUNKS;
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
        st->photon_hits += chunk[c].n;
        st->photon_segments += chunk[c].segments;
        chunk[c].segments = 0;
    }
    s->done_photons += count;
    render_progress(s);
    return 0;
}

static int step_batch(render_session_t *s, char *err, size_t errlen)
{
    render_stats_t *st = &s->res->stats;
    if (s->interrupted || s->done_photons >= s->emitted_target || !s->res->hp.n) return 0;
    const unsigned want = batch_blocks(s);
    const uint64_t stop = render_stop_at(s);   /* blocks end there (a series' point): same bits */
    uint64_t count[SCREEN_BLOCKS_MAX], next = s->done_photons;
    unsigned n = 0;
    int stopped = 0;
    update_ops_clear(&s->ops);
    double t = omp_get_wtime();
    while (n < want && next < stop) {
        count[n] = stop - next;
        if (count[n] > PHOTON_BLOCK) count[n] = PHOTON_BLOCK;
        char block_name[32];   /* fault injection: "block1" is this run's first block */
        snprintf(block_name, sizeof block_name, "block%llu",
                 (unsigned long long)((next - st->photons_resumed) / PHOTON_BLOCK + 1));
        render_test_interrupt(block_name);
        const int traced = render_trace_block(s, s->opt.photon_offset + next, count[n], n);
        if (traced < 0) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
        if (traced > 0) { stopped = 1; break; }   /* the image keeps the whole blocks done */
        if (s->opt.precision == PRECISION_FP32 &&
            render_fp32_check_hits(s->bb->chunk + (size_t)n * TRACE_CHUNKS, TRACE_CHUNKS, err, errlen))
            return -1;
        next += count[n++];
        if (batch_should_end(s)) break;
    }
    st->sec_trace += omp_get_wtime() - t;
    if (n) {
        t = omp_get_wtime();
        if (update_batch_blocks(s, n)) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
        st->sec_update += omp_get_wtime() - t;
        batch_measure(s, n);
        for (unsigned k = 0; k < n; k++)
            if (finish_block(s, k, count[k])) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
    }
    if (stopped || (s->opt.interrupt && *s->opt.interrupt && s->done_photons < s->emitted_target)) {
        /* Keep whole batches of 1000 photons so the radiance normalisation holds. */
        s->interrupted = 1;
        if (s->opt.progress) fputc('\n', stderr);
    }
    return n ? 1 : 0;
}

/* The photon pass's target and the threads' update counters and candidate lists. 0, or -1 with
 * err. */
int render_photon_pass_open(render_session_t *s, char *err, size_t errlen)
{
    s->emitted_target = render_emitted(s->opt.photons);
    s->ust = calloc((size_t)s->T, sizeof *s->ust);
    s->scratch = calloc((size_t)s->T, sizeof *s->scratch);
    if (!s->ust || !s->scratch) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    return 0;
}

/* What only the photon pass uses: the grid, the traced hits and the candidate lists (freed before
 * the radiance pass, so that its peak does not add to theirs). */
void render_photon_pass_free(render_session_t *s)
{
    if (s->bb)
        for (unsigned c = 0; c < TRACE_CHUNKS * SCREEN_BLOCKS_MAX; c++) photon_hits_free(&s->bb->chunk[c]);
    grid_free(&s->grid);
    update_prefilter_free(&s->prefilter);
    update_batch_free(&s->batch);
    if (s->scratch)
        for (int p = 0; p < s->T; p++) update_batch_scratch_free(&s->scratch[p]);
}

int render_step(render_session_t *s, char *err, size_t errlen)
{
    if (s->nranks > 1) {
        const int r = render_round_step(s, err, errlen);
        if (r < 0) s->failed = 1;
        return r;
    }
    const int r = step_batch(s, err, errlen);
    if (r < 0) s->failed = 1;
    return r;
}
