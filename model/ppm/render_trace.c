// SPDX-License-Identifier: Apache-2.0
/* render_trace.c: a photon block traced into the session's chunk buffers, each hit with its grid
 * bucket, and the photon pass's progress line. */
#include <omp.h>
#include <stdio.h>
#include <unistd.h>
#include "photon_pass.h"
#include "render_dist.h"
#include "render_trace.h"

/* Photon hits whose cell look-up is fetched ahead of the one being made. */
#define BUCKET_AHEAD 8

int render_trace_block(render_session_t *s, uint64_t first, uint64_t count, unsigned slot)
{
    const scene_t *scene = s->scene;
    const tracer_t *tr = s->tr;
    const grid_t *g = &s->grid;
    const int skip = s->skip;
    const stop_flag_t *stop = s->opt.interrupt;
    block_buffers_t *bb = s->bb;
    photon_hits_t *chunk = bb->chunk + (size_t)slot * TRACE_CHUNKS;
    int failed = 0, stopped = 0;
    unsigned long long no_cell = 0;
    const uint64_t per = (count + TRACE_CHUNKS - 1) / TRACE_CHUNKS;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : failed, stopped, no_cell)
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
        /* Work on a copy: neighbouring chunks share cache lines, and their counters change with
         * every segment and hit. */
        photon_hits_t local = chunk[c];
        photon_hits_t *out = &local;
        out->n = 0;
        uint64_t lo = first + c * per, hi = lo + per;
        if (hi > first + count) hi = first + count;
        for (uint64_t i = lo; i < hi && !failed && !stopped; i++) {
            if (stop_requested(stop)) { stopped = 1; break; }
            /* Under MPI the previous round's exchange progresses while this one traces. */
            if (s->pending && (i & 63) == 0 && omp_get_thread_num() == 0) render_dist_exchange_poll(s->pending);
            if (photon_trace(scene, tr, i, out)) { failed = 1; break; }
        }
        /* Find each hit's bucket once, here in parallel, the look-ups BUCKET_AHEAD hits ahead
         * already fetched (the cell table of a big frame is far larger than the caches); with
         * skips, drop the hits that reach no hit point's cell. */
        size_t keep = 0;
        grid_probe_t ahead[BUCKET_AHEAD];   /* hit k's look-up, begun, in ahead[k % BUCKET_AHEAD] */
        for (size_t k = 0; k < out->n && k < BUCKET_AHEAD; k++) ahead[k] = grid_probe_begin(g, out->hits[k].x);
        for (size_t k = 0; k < out->n && !failed && !stopped; k++) {
            photon_hit_t *ph = &out->hits[k];
            ph->bucket = grid_probe_end(g, ahead[k % BUCKET_AHEAD]);
            /* Hits from k + 1 on are not yet moved (keep <= k). */
            if (k + BUCKET_AHEAD < out->n) ahead[k % BUCKET_AHEAD] = grid_probe_begin(g, out->hits[k + BUCKET_AHEAD].x);
            if (skip && ph->bucket == GRID_NO_BUCKET) { no_cell++; continue; }
            out->hits[keep++] = *ph;
        }
        if (!failed && !stopped) out->n = keep;
        chunk[c] = local;
    }
    if (failed) return -1;
    if (stopped) {
        for (unsigned c = 0; c < TRACE_CHUNKS; c++) chunk[c].n = chunk[c].segments = 0;
        return 1;
    }
    bb->no_cell += no_cell;
    return 0;
}

void render_progress(render_session_t *s)
{
    render_options_t *opt = &s->opt;
    const uint64_t done = s->done_photons, total = s->emitted_target;
    const double t0 = s->t_photons;
    int *last_decile = &s->last_decile;
    if (!opt->progress) return;
    const int tty = isatty(2);
    const int decile = (int)(10 * done / total);
    if (!tty && decile == *last_decile) return;
    *last_decile = decile;
    double el = omp_get_wtime() - t0;
    fprintf(stderr, "%spree: photons %llu/%llu (%3.0f%%) %.1fs%s", tty ? "\r" : "", (unsigned long long)done,
            (unsigned long long)total, 100.0 * (double)done / (double)total, el, tty && done < total ? "" : "\n");
    if (fflush(stderr) != 0 || ferror(stderr)) opt->progress = 0;
}
