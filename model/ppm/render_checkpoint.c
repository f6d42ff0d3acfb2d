// SPDX-License-Identifier: Apache-2.0
/* render_checkpoint.c: the session's state to and from a checkpoint (see render_checkpoint.h):
 * the hit points' state in the photon pass's order, the photons done and the pass counters. */
#include <stdio.h>
#include "checkpoint.h"
#include "render_checkpoint.h"

int render_checkpoint_resume(render_session_t *s, char *err, size_t errlen)
{
    checkpoint_info_t ci = {.fingerprint = s->fingerprint};
    if (checkpoint_load(s->opt.resume, &ci, &s->res->hp, s->perm, s->opt.precision, err, errlen)) return -1;
    if (ci.done_photons > s->emitted_target) {
        snprintf(err, errlen, "%s: the checkpoint holds %llu photons; a render of %llu photons does not pass there "
                 "(resume with at least that many)", s->opt.resume,
                 (unsigned long long)ci.done_photons, (unsigned long long)s->emitted_target);
        return -1;
    }
    render_stats_t *st = &s->res->stats;
    s->done_photons = s->last_checkpoint = ci.done_photons;
    st->photons_resumed = ci.done_photons;
    st->photon_hits = ci.photon_hits;
    st->photon_segments = ci.photon_segments;
    s->bb->no_cell = ci.no_cell;
    s->ust[0] = ci.upd;
    return 0;
}

int render_checkpoint_write(render_session_t *s, char *err, size_t errlen)
{
    const render_stats_t *st = &s->res->stats;
    checkpoint_info_t ci = {.fingerprint = s->fingerprint, .done_photons = s->done_photons,
                            .photon_hits = st->photon_hits, .photon_segments = st->photon_segments,
                            .no_cell = s->bb->no_cell, .note = s->opt.checkpoint_note};
    ci.upd = render_session_update_totals(s);
    s->last_checkpoint = s->done_photons;
    return checkpoint_save(s->opt.checkpoint, &ci, &s->res->hp, s->perm, s->opt.precision, err, errlen);
}
