// SPDX-License-Identifier: Apache-2.0
/* render_run.c: a whole render, the session's five phases in order (docs/engine.md, "The render
 * session"): open, eye pass (render.c, with render_setup.c: the BVH, the hit points, the grid, a
 * resume), the photon rounds (render_step.c, under MPI render_round.c) with the convergence
 * series' points, the checkpoints (render_checkpoint.h) and the time limit, the radiance and the
 * close (render.c, with render_radiance.c).
 *
 * Each hit point receives its photons in index order whatever the blocks, so an interrupted,
 * time-limited or resumed render holds the same bits as an uninterrupted one of the same photon
 * count, and a checkpoint of any photon count resumes to any larger one. */
#include <omp.h>
#include "render_checkpoint.h"
#include "render_radiance.h"
#include "render_session.h"

/* The photon rounds until the last photon, an interrupt, the time limit or a failure (s->failed,
 * with err; nothing after a failed eye pass): a series' image at each of its points, a checkpoint every checkpoint_every photons,
 * and one when the photon pass ends or stops. */
static void photon_rounds(render_session_t *s, char *err, size_t errlen)
{
    if (s->failed) return;
    const render_options_t *opt = &s->opt;
    const uint64_t every = render_checkpoint_every(opt);
    while (s->next_write < opt->write_at_n && opt->write_at[s->next_write] <= s->done_photons) s->next_write++;
    while (render_step(s, err, errlen) > 0) {
        const int more = s->done_photons < s->emitted_target;
        if (s->next_write < opt->write_at_n && s->done_photons == opt->write_at[s->next_write]) {
            s->next_write++;
            if (render_radiance_snapshot(s, err, errlen)) {
                s->failed = 1;
                break;
            }
        }
        if (opt->checkpoint && more && s->done_photons - s->last_checkpoint >= every &&
            render_checkpoint_write(s, err, errlen)) {
            s->failed = 1;
            break;
        }
        if (more && opt->time_limit > 0 && omp_get_wtime() - s->t_start >= opt->time_limit) {
            s->res->stats.time_limited = 1;
            break;
        }
    }
    /* Whatever ended the photon pass, the checkpoint holds its state. */
    if (!s->failed && opt->checkpoint && s->done_photons && s->res->hp.n && render_checkpoint_write(s, err, errlen))
        s->failed = 1;
}

int render_run(const scene_t *scene, const render_options_t *opt, render_result_t *res,
               char *err, size_t errlen)
{
    render_session_t *s = render_open(scene, opt, res, err, errlen);   /* options, threads, image */
    if (!s) return -1;
    render_eye_pass(s, err, errlen);   /* BVH, hit points, grid, a resume */
    photon_rounds(s, err, errlen);
    render_radiance(s, err, errlen);   /* radiance, hashes */
    return render_close(s);            /* -1 after a failed phase, with its message in err */
}
