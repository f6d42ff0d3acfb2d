// SPDX-License-Identifier: Apache-2.0
/* render_round.c: the photon pass across MPI ranks (docs/scale_out.md).
 *
 * A round deals one photon block to each rank (rank r: the round's block r, which keeps its
 * photon indices). Each rank traces its block and screens it against its copy of the whole grid,
 * routing every kept candidate to the rank that owns its hit point (render_dist_lo: contiguous
 * runs of the spatial order). One all-to-all exchange per round then sends each owner only its
 * candidates, with the photon words they need; every owner applies the round's blocks in photon
 * order to its hit points, exactly as one process would (the apply re-tests every candidate
 * against the current radius, so screening against an older radius keeps a superset). The ranks
 * share their owned radii before each re-filter, so that every grid drops the same entries. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "render_check.h"
#include "render_dist.h"
#include "render_round.h"
#include "render_screen.h"
#include "render_test_hook.h"
#include "render_trace.h"

/* The threads' kept lists: one per owning rank when screening, one per part when applying (the
 * same count for both, so that the lists keep their memory from round to round). */
#define LISTS(s) ((s)->nranks > (s)->T ? (s)->nranks : (s)->T)

/* The wire format, per (source block, owner): a header, the photons' words (double mode: the
 * flux; fp32: the binary32 position and flux the PREU takes), then the candidates. */
typedef struct { uint64_t photons, hits, entries; } seg_head_t;
typedef struct { uint32_t hit, hp; double v2; } seg_entry_t;
typedef struct { uint64_t w[3]; } seg_photon_t;   /* 3 doubles, or 6 binary32 words */

int render_round_open(render_session_t *s, char *err, size_t errlen)
{
    s->nranks = s->opt.one_rank ? 1 : render_dist_size();   /* one_rank: each rank renders alone */
    s->rank = s->opt.one_rank ? 0 : render_dist_rank();
    s->res->stats.mpi_ranks = s->nranks;
    if (s->nranks < 2) return 0;
    if (s->photon_major || s->opt.checkpoint || s->opt.resume || s->opt.time_limit > 0 || s->opt.write_at_n) {
        snprintf(err, errlen, "under MPI with %d ranks: --scan photon, --checkpoint, --resume, --time-limit, "
                 "--write-at/--write-every and recording operations are not supported", s->nranks);
        return -1;
    }
    const size_t n = s->res->hp.n, N = (size_t)s->nranks;
    s->own_lo = malloc((N + 1) * sizeof *s->own_lo);
    s->counts = malloc(N * sizeof *s->counts);
    s->rank_of = malloc((n ? n : 1) * sizeof *s->rank_of);
    int failed = !s->own_lo || !s->counts || !s->rank_of;
    for (int k = 0; k < 2; k++) {
        s->slot[k].sendcounts = malloc(N * sizeof *s->slot[k].sendcounts);
        s->slot[k].recvcounts = malloc(N * sizeof *s->slot[k].recvcounts);
        failed |= !s->slot[k].sendcounts || !s->slot[k].recvcounts;
    }
    if (failed) { snprintf(err, errlen, "out of memory"); return -1; }
    for (int r = 0; r <= s->nranks; r++) s->own_lo[r] = render_dist_lo(n, r, s->nranks);
    for (int r = 0; r < s->nranks; r++)
        for (size_t i = s->own_lo[r]; i < s->own_lo[r + 1]; i++) s->rank_of[i] = (uint16_t)r;
    /* The others' hit points: part T, which no thread applies (none arrive). */
    for (size_t i = 0; i < n; i++)
        if (s->rank_of[i] != s->rank) s->owner[i] = (uint16_t)s->T;
    return 0;
}

static seg_photon_t photon_words(const photon_hit_t *ph, precision_t prec)
{
    seg_photon_t w;
    if (prec == PRECISION_DOUBLE) {
        memcpy(w.w, &ph->flux, sizeof w.w);
        return w;
    }
    const preu_photon_t p = update_photon_fp32(ph);
    memcpy(w.w, &p, sizeof w.w);
    return w;
}

/* The photon hit the apply reads, from its words: in fp32 mode the binary32 values widened to
 * double, which update_photon_fp32 rounds back to the same words. */
static photon_hit_t photon_from_words(const seg_photon_t *w, precision_t prec)
{
    photon_hit_t ph;
    memset(&ph, 0, sizeof ph);
    if (prec == PRECISION_DOUBLE) {
        memcpy(&ph.flux, w->w, sizeof ph.flux);
        return ph;
    }
    preu_photon_t p;
    memcpy(&p, w->w, sizeof p);
    ph.x = v3(fp32_from_bits(p.pos[0]), fp32_from_bits(p.pos[1]), fp32_from_bits(p.pos[2]));
    ph.flux = v3(fp32_from_bits(p.phi[0]), fp32_from_bits(p.phi[1]), fp32_from_bits(p.phi[2]));
    return ph;
}

static int reserve(void **buf, size_t *cap, size_t need)
{
    if (need <= *cap) return 0;
    void *p = realloc(*buf, need);
    if (!p) return -1;
    *buf = p;
    *cap = need;
    return 0;
}

/* Screen this rank's traced block (bb) and pack each owner's segment into x's send buffer, in
 * rank order; sendcounts[d]: owner d's bytes. 0 or -1 (memory). */
static int screen_and_pack(render_session_t *s, uint64_t photons, round_slot_t *x)
{
    const int T = s->T, N = s->nranks;
    const precision_t prec = s->opt.precision;
    if (render_screen_block(s, s->rank_of, LISTS(s), 1)) return -1;
    size_t used = 0;
    for (int d = 0; d < N; d++) {
        if (update_batch_gather(&s->xs, s->scratch, T, d, s->batch.n)) return -1;
        /* The photons of the candidates, each once: the candidates come grouped by hit. */
        seg_head_t head = {photons, 0, s->xs.n_sorted};   /* every owner counts the block */
        uint32_t last = UINT32_MAX, hit, hp;
        double v2;
        for (size_t i = 0; i < s->xs.n_sorted; i++) {
            update_batch_sorted_at(&s->xs, i, &hit, &hp, &v2);
            if (hit != last) head.hits++, last = hit;
        }
        const size_t bytes = sizeof head + head.hits * sizeof(seg_photon_t) + head.entries * sizeof(seg_entry_t);
        if (reserve(&x->send, &x->send_cap, used + bytes)) return -1;
        char *o = (char *)x->send + used;
        memcpy(o, &head, sizeof head);
        seg_photon_t *pw = (seg_photon_t *)(o + sizeof head);
        seg_entry_t *en = (seg_entry_t *)(pw + head.hits);
        last = UINT32_MAX;
        uint32_t nh = 0;   /* the candidates' photons, numbered in this segment */
        for (size_t i = 0; i < s->xs.n_sorted; i++) {
            update_batch_sorted_at(&s->xs, i, &hit, &hp, &v2);
            if (hit != last) {
                pw[nh++] = photon_words(s->batch.hit[hit], prec);
                last = hit;
            }
            en[i] = (seg_entry_t){nh - 1, hp, v2};
        }
        x->sendcounts[d] = bytes;
        used += bytes;
        s->res->stats.mpi_kept += head.entries;
        if (d != s->rank) {
            s->res->stats.mpi_kept_foreign += head.entries;
            s->bytes_sent += bytes;
        }
    }
    return 0;
}

/* Apply one received segment (a block's candidates on this rank's hit points): each thread its
 * own part, in photon order. 0 or -1 (memory). */
static int apply_segment(render_session_t *s, const char *in, const seg_head_t *head)
{
    const int T = s->T;
    const precision_t prec = s->opt.precision;
    const seg_photon_t *pw = (const seg_photon_t *)(in + sizeof *head);
    const seg_entry_t *en = (const seg_entry_t *)(pw + head->hits);
    if (reserve((void **)&s->rhits, &s->rhits_cap, (head->hits ? head->hits : 1) * sizeof *s->rhits) ||
        reserve((void **)&s->rhit_ptr, &s->rptr_cap, (head->hits ? head->hits : 1) * sizeof *s->rhit_ptr))
        return -1;
    for (size_t i = 0; i < head->hits; i++) {
        s->rhits[i] = photon_from_words(&pw[i], prec);
        s->rhit_ptr[i] = &s->rhits[i];
    }
    int failed = 0;
    for (int p = 0; p < T && !failed; p++) failed |= update_batch_scratch_reset(&s->scratch[p], LISTS(s));
    for (size_t i = 0; i < head->entries && !failed; i++)
        failed |= update_batch_keep_in(&s->scratch[0], s->owner[en[i].hp], en[i].hit, en[i].hp, en[i].v2);
    if (failed) return -1;
    update_batch_t ab = s->batch;   /* only hit and n are read by the apply */
    ab.hit = s->rhit_ptr;
    ab.n = head->hits;
#pragma omp parallel for num_threads(T) schedule(static, 1) reduction(| : failed)
    for (int q = 0; q < T; q++)
        failed |= update_batch_apply(&s->res->hp, prec, &ab, q, s->scratch, T, &s->ust[omp_get_thread_num()]);
    return failed ? -1 : 0;
}

/* After a round of nblocks blocks: re-filter when the one-process schedule (after blocks 1, 2,
 * 4, 8, ...) passed a point in it, with every rank's current radii. 0 or -1 (memory). */
static int refilter_round(render_session_t *s, uint64_t nblocks)
{
    const uint64_t before = s->blocks;
    s->blocks += nblocks;
    uint64_t top = 1;
    while (top * 2 <= s->blocks) top *= 2;
    if (top <= before || !render_refilter_enabled(s)) return 0;
    if (s->opt.record_ops) return render_refilter_point(s);   /* the caller's radii */
    hitpoints_t *h = &s->res->hp;
    const double t = omp_get_wtime();   /* sharing the radii counts as the re-filter's */
    if (s->opt.precision == PRECISION_DOUBLE) render_dist_share_ranges(h->r2, sizeof *h->r2, s->own_lo);
    else render_dist_share_ranges(h->r2_f32, sizeof *h->r2_f32, s->own_lo);
    s->res->stats.sec_refilter += omp_get_wtime() - t;
    return render_refilter_point(s);
}

/* The exchange in flight: wait for it, apply its blocks in photon order, re-filter when due.
 * 0 or -1 with err. */
static int finish_pending(render_session_t *s, char *err, size_t errlen)
{
    if (!s->pending) return 0;
    render_stats_t *st = &s->res->stats;
    double t = omp_get_wtime();
    render_dist_exchange_wait(s->pending);
    s->pending = NULL;
    st->sec_trace += omp_get_wtime() - t;   /* the exchange's wait, with the tracing it overlaps */
    t = omp_get_wtime();
    const round_slot_t *x = &s->slot[s->pending_slot];
    const char *in = x->recv;
    uint64_t nblocks = 0;
    for (int r = 0; r < s->nranks; in += x->recvcounts[r], r++) {   /* blocks in photon order */
        seg_head_t head;
        memcpy(&head, in, sizeof head);
        if (!head.photons) continue;
        if (apply_segment(s, in, &head)) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
        s->done_photons += head.photons;
        nblocks++;
    }
    st->sec_update += omp_get_wtime() - t;   /* the re-filter counts its own seconds */
    if (refilter_round(s, nblocks)) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
    render_progress(s);
    return 0;
}

/* The first failing rank's message, on every rank. */
static void agree_error(render_session_t *s, const char *mine, size_t size, char *err, size_t errlen)
{
    err[0] = '\0';
    if (render_dist_allgather(mine, size, &s->recvbuf, &s->recv_cap, s->counts)) {
        snprintf(err, errlen, "out of memory in the photon pass");
        return;
    }
    for (int r = 0; r < s->nranks && !err[0]; r++) snprintf(err, errlen, "%s", (const char *)s->recvbuf + (size_t)r * size);
    if (!err[0]) snprintf(err, errlen, "a rank failed in the photon pass");
}

/* One round: this rank traces and screens its block while the previous round's exchange is in
 * flight, then applies that round and starts this one's. 1 (a step done), 0 (ended: nothing in
 * flight), -1 with err. */
int render_round_step(render_session_t *s, char *err, size_t errlen)
{
    render_stats_t *st = &s->res->stats;
    if (!s->res->hp.n) return 0;
    if (s->interrupted || s->next_photon >= s->emitted_target) {
        if (!s->pending) return 0;
        return finish_pending(s, err, errlen) ? -1 : 1;
    }
    enum { GO = 0, STOP_AFTER = 1, ABANDONED = 2, FAILED = 3 };
    const uint64_t round_first = s->next_photon, first = round_first + (uint64_t)s->rank * PHOTON_BLOCK;
    uint64_t count = first < s->emitted_target ? s->emitted_target - first : 0;
    if (count > PHOTON_BLOCK) count = PHOTON_BLOCK;
    char mine[512] = "";
    int status = GO;
    double t = omp_get_wtime();
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) s->bb->chunk[c].n = s->bb->chunk[c].segments = 0;
    if (count) {
        char block_name[32];
        snprintf(block_name, sizeof block_name, "block%llu", (unsigned long long)(first / PHOTON_BLOCK + 1));
        render_test_interrupt(block_name);
        const int traced = render_trace_block(s, s->opt.photon_offset + first, count, 0);
        if (traced < 0) { snprintf(mine, sizeof mine, "out of memory in the photon pass"); status = FAILED; }
        else if (traced > 0) status = ABANDONED;
        else if (s->opt.precision == PRECISION_FP32 && render_fp32_check_hits(s->bb->chunk, TRACE_CHUNKS, mine, sizeof mine))
            status = FAILED;
    }
    if (status == GO && s->opt.interrupt && *s->opt.interrupt) status = STOP_AFTER;
    st->sec_trace += omp_get_wtime() - t;
    const int cur = s->pending ? !s->pending_slot : 0;
    t = omp_get_wtime();
    if ((status == GO || status == STOP_AFTER) && screen_and_pack(s, count, &s->slot[cur])) {
        snprintf(mine, sizeof mine, "out of memory in the photon pass");
        status = FAILED;
    }
    st->sec_update += omp_get_wtime() - t;
    status = render_dist_max(status);
    if (status == FAILED) {
        agree_error(s, mine, sizeof mine, err, errlen);
        return -1;
    }
    /* The previous round is whole on every rank: apply it, whatever this one became. */
    if (finish_pending(s, err, errlen)) return -1;
    if (status == ABANDONED) {   /* the image keeps the rounds done */
        s->interrupted = 1;
        if (s->opt.progress) fputc('\n', stderr);
        return 1;
    }
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) {   /* this rank's block; summed at the end */
        st->photon_hits += s->bb->chunk[c].n;
        st->photon_segments += s->bb->chunk[c].segments;
    }
    round_slot_t *x = &s->slot[cur];
    if (render_dist_exchange_start(&s->pending, x->send, x->sendcounts, &x->recv, &x->recv_cap, x->recvcounts)) {
        snprintf(err, errlen, "out of memory in the photon pass");
        return -1;
    }
    s->pending_slot = cur;
    const uint64_t round = (uint64_t)s->nranks * PHOTON_BLOCK;
    s->next_photon = s->emitted_target - round_first < round ? s->emitted_target : round_first + round;
    if (status == STOP_AFTER && s->next_photon < s->emitted_target) {
        s->interrupted = 1;   /* the next step applies this round and ends */
        if (s->opt.progress) fputc('\n', stderr);
    }
    return 1;
}

void render_round_close(render_session_t *s)
{
    hitpoints_t *h = &s->res->hp;
    render_stats_t *st = &s->res->stats;
    const size_t *lo = s->own_lo;
    render_dist_gather_ranges(h->hot, sizeof *h->hot, lo);
    if (h->acc) render_dist_gather_ranges(h->acc, sizeof *h->acc, lo);
    if (h->r2) render_dist_gather_ranges(h->r2, sizeof *h->r2, lo);
    if (h->r2_f32) render_dist_gather_ranges(h->r2_f32, sizeof *h->r2_f32, lo);
    if (h->fp32) render_dist_gather_ranges(h->fp32, sizeof *h->fp32, lo);
    if (h->stable) render_dist_gather_ranges(h->stable, sizeof *h->stable, lo);
    /* Every rank traced and screened its own blocks and applied only its own hit points. */
    const update_stats_t u = render_session_update_totals(s);
    unsigned long long v[10] = {s->bb->no_cell, u.candidates, u.skipped_radius, u.normal_passed, u.accepted,
                                s->bytes_sent, st->mpi_kept, st->mpi_kept_foreign, st->photon_hits,
                                st->photon_segments};
    render_dist_sum(v, 10);
    s->bb->no_cell = v[0];
    st->upd = (update_stats_t){v[1], v[2], v[3], v[4]};
    st->mpi_bytes_sent = v[5];
    st->mpi_kept = v[6];
    st->mpi_kept_foreign = v[7];
    st->photon_hits = v[8];
    st->photon_segments = v[9];
}

void render_round_free(render_session_t *s)
{
    free(s->own_lo);
    free(s->counts);
    render_dist_exchange_wait(s->pending);   /* a failed or stopped render's exchange in flight */
    for (int k = 0; k < 2; k++) {
        free(s->slot[k].send);
        free(s->slot[k].recv);
        free(s->slot[k].sendcounts);
        free(s->slot[k].recvcounts);
    }
    free(s->rank_of);
    update_batch_scratch_free(&s->xs);
    free(s->rhits);
    free(s->rhit_ptr);
    free(s->recvbuf);
}
