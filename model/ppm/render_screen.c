// SPDX-License-Identifier: Apache-2.0
/* render_screen.c: the photon pass's screening of traced blocks against the grid and the grid's
 * re-filter (see render_screen.h), shared by the one-process batches (render_step.c) and the MPI
 * rounds (render_round.c); the re-filter with the caller's radii (render_refilter_due and
 * render_refilter_from, render.h). */
#include <omp.h>
#include <stdio.h>
#include "grid_refilter.h"
#include "pree_env.h"
#include "render_screen.h"

#define SCREEN_GROUPS 256   /* bucket groups a thread screens at a time */

int render_screen_block(render_session_t *s, const uint16_t *owner, int lists, unsigned blocks)
{
    const int T = s->T;
    int failed = update_batch_prepare(&s->batch, s->bb->chunk, TRACE_CHUNKS * blocks, s->grid.num_buckets);
    s->batch.owner = owner;
    /* The ranges stand for owner[] only where they describe it: this rank's own parts (owner[]
     * itself is freed where they do, so the caller passes NULL). */
    s->batch.owner_end = owner == s->owner ? s->owner_end : NULL;
    s->batch.parts = lists;
    s->batch.prefilter = &s->prefilter;
    for (int p = 0; p < T && !failed; p++) failed |= update_batch_scratch_reset(&s->scratch[p], lists);
    if (failed) return -1;
#pragma omp parallel num_threads(T) reduction(| : failed)
    {
        const int p = omp_get_thread_num();
#pragma omp for schedule(dynamic, 1)
        for (size_t gi = 0; gi < s->batch.n_groups; gi += SCREEN_GROUPS)
            failed |= update_batch_screen(&s->res->hp, &s->grid, s->opt.precision, s->skip, &s->batch, gi,
                                          gi + SCREEN_GROUPS, &s->ust[p], &s->scratch[p]);
    }
    return failed ? -1 : 0;
}

/* Radii only shrink: after blocks 1, 2, 4, 8, ... drop the grid entries that the current radii
 * rule out (model/ppm/grid_refilter.c). Not with --no-skip (the oracle) nor with the environment
 * variable PREE_NO_REFILTER set (make bench's before/after rows, like PREE_NO_AVX2). When recording
 * the co-simulation's operations, the caller re-filters with the radii it reads back from the
 * PREE (render_refilter_from). */
int render_refilter_enabled(const render_session_t *s)
{
    return s->skip && !pree_env(PREE_ENV_NO_REFILTER);
}

/* The re-filter with the session's radii, or r2_bits (render_refilter_from). 0 or -1 (memory). */
static int refilter_with(render_session_t *s, const uint32_t *r2_bits)
{
    render_stats_t *st = &s->res->stats;
    const double t = omp_get_wtime();
    const long long dropped = grid_refilter(&s->grid, &s->res->hp, s->opt.precision, r2_bits, s->T);
    if (dropped < 0) return -1;
    st->grid_refilters++;
    st->grid_entries_final -= (size_t)dropped;
    st->sec_refilter += omp_get_wtime() - t;
    return 0;
}

int render_refilter_point(render_session_t *s)
{
    if (!render_refilter_enabled(s)) return 0;
    if (!s->opt.record_ops) return refilter_with(s, NULL);
    s->refilter_due = 1;
    return 0;
}

int render_refilter_due(const render_session_t *s)
{
    return s->refilter_due && !s->interrupted && s->done_photons < s->emitted_target;
}

int render_refilter_from(render_session_t *s, const uint32_t *r2_bits, char *err, size_t errlen)
{
    s->refilter_due = 0;
    if (s->opt.precision != PRECISION_FP32) {
        snprintf(err, errlen, "binary32 radii for a double-precision render");
        return -1;
    }
    if (refilter_with(s, r2_bits)) {
        snprintf(err, errlen, "out of memory in the photon pass");
        return -1;
    }
    return 0;
}
