// SPDX-License-Identifier: Apache-2.0
/* render_run.c: a whole render driven through its session: the photon blocks, the stopping
 * rules (interrupt, time limit), and the checkpoints (model/ppm/checkpoint.h).
 *
 * Each hit point receives its photons in index order whatever the blocks, so an interrupted,
 * time-limited or resumed render holds the same bits as an uninterrupted one of the same photon
 * count, and a checkpoint of any photon count resumes to any larger one. */
#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "checkpoint.h"
#include "pree_env.h"
#include "render_session.h"

/* Continue from opt.resume: the state, the photons done and the pass counters. */
int render_session_resume(render_session_t *s, char *err, size_t errlen)
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

/* Write the state to opt.checkpoint. */
static int session_checkpoint(render_session_t *s, char *err, size_t errlen)
{
    const render_stats_t *st = &s->res->stats;
    checkpoint_info_t ci = {.fingerprint = s->fingerprint, .done_photons = s->done_photons,
                            .photon_hits = st->photon_hits, .photon_segments = st->photon_segments,
                            .no_cell = s->bb->no_cell, .note = s->opt.checkpoint_note};
    ci.upd = render_session_update_totals(s);
    s->last_checkpoint = s->done_photons;
    return checkpoint_save(s->opt.checkpoint, &ci, &s->res->hp, s->perm, s->opt.precision, err, errlen);
}

void render_test_interrupt(const char *phase)
{
    const char *want = pree_env(PREE_ENV_TEST_INTERRUPT), *kill = pree_env(PREE_ENV_TEST_KILL);
    if (want && !strcmp(want, phase)) raise(SIGINT);
    if (kill && !strcmp(kill, phase)) raise(SIGKILL);
}

int render_run(const scene_t *scene, const render_options_t *opt, render_result_t *res,
               char *err, size_t errlen)
{
    render_session_t *s = render_open(scene, opt, res, err, errlen);
    if (!s) return -1;
    const uint64_t every = render_checkpoint_every(opt);
    while (s->next_write < opt->write_at_n && opt->write_at[s->next_write] <= s->done_photons) s->next_write++;
    while (render_step(s, err, errlen) > 0) {
        const int more = s->done_photons < s->emitted_target;
        if (s->next_write < opt->write_at_n && s->done_photons == opt->write_at[s->next_write]) {
            s->next_write++;
            if (render_session_snapshot(s, err, errlen)) {
                s->failed = 1;
                break;
            }
        }
        if (opt->checkpoint && more && s->done_photons - s->last_checkpoint >= every && session_checkpoint(s, err, errlen)) {
            s->failed = 1;
            break;
        }
        if (more && opt->time_limit > 0 && omp_get_wtime() - s->t_start >= opt->time_limit) {
            res->stats.time_limited = 1;
            break;
        }
    }
    /* Whatever ended the photon pass, the checkpoint holds its state. */
    if (!s->failed && opt->checkpoint && s->done_photons && res->hp.n && session_checkpoint(s, err, errlen)) s->failed = 1;
    return render_close(s, err, errlen);   /* -1 after a failed step, with its message */
}
