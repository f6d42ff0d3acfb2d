/* render.c: the render driver: phases in order, threads, timing, progress and interrupt.
 *
 * The photon pass runs in blocks: photons of a block are traced in parallel into ordered
 * chunk buffers, then each thread updates the hit points it owns from all of the block's
 * hits in photon order. So every hit point sees its photons in index order, and the result
 * does not depend on the number of threads. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>
#include "hp_order.h"
#include "grid_refilter.h"
#include "mem_check.h"
#include "photon_pass.h"
#include "radiance.h"
#include "checkpoint.h"
#include "render_check.h"
#include "render_dist.h"
#include "render_session.h"

#define SCREEN_GROUPS 256   /* bucket groups a thread screens at a time */

long render_peak_rss_kb(void)
{
    struct rusage ru;
    return getrusage(RUSAGE_SELF, &ru) == 0 ? ru.ru_maxrss : -1;
}

/* Hit-point state before the first photon: radius r0, no photons, no flux; the update rule's
 * alpha and, in fp32 mode, the datapath's state layout, which holds the weight (so the double
 * weight is dropped). */
static int init_state(hitpoints_t *h, const render_options_t *opt, double r0)
{
    h->alpha = render_alpha(opt);
    h->alpha32 = preu_f32(h->alpha);
    h->kappa32 = preu_kappa(h->alpha32);
    if (opt->precision != PRECISION_FP32) return hitpoints_init_double(h, r0);
    const int stable = opt->datapath == DATAPATH_STABLE;
    const size_t n = h->n ? h->n : 1;
    if (stable) h->stable = malloc(n * sizeof *h->stable);
    else h->fp32 = malloc(n * sizeof *h->fp32);
    h->r2_f32 = malloc(n * sizeof *h->r2_f32);
    if (!(stable ? (void *)h->stable : (void *)h->fp32) || !h->r2_f32) return -1;
    const uint32_t r2 = preu_f32(r0 * r0);
    for (size_t i = 0; i < h->n; i++) {
        const hp_hot_t *p = &h->hot[i];
        const uint32_t pos[3] = {preu_f32(p->px), preu_f32(p->py), preu_f32(p->pz)};
        const uint32_t f[3] = {preu_f32(h->weight[i].x), preu_f32(h->weight[i].y), preu_f32(h->weight[i].z)};
        if (stable) {
            preu_shp_t *s = &h->stable[i];
            memcpy(s->pos, pos, sizeof pos);
            memcpy(s->f, f, sizeof f);
            preu_stable_init(s, r0 * r0);
            h->r2_f32[i] = preu_stable_screen_r2(s->w);
        } else {
            preu_hp_t *s = &h->fp32[i];
            memcpy(s->pos, pos, sizeof pos);
            memcpy(s->f, f, sizeof f);
            s->tau[0] = s->tau[1] = s->tau[2] = 0;
            s->r2 = r2;
            s->n = 0;
            h->r2_f32[i] = r2;
        }
    }
    return hitpoints_drop_weight(h);
}

/* Trace the photons of sequence indices [first, first + count) into the ordered chunk buffers;
 * drop hits that reach no hit point's cell when skipping. Returns 0, -1 (out of memory) or 1
 * (stop was set: the block is abandoned, the counters untouched). */
static int trace_block(const scene_t *scene, const tracer_t *tr, const grid_t *g, int skip,
                       uint64_t first, uint64_t count, const stop_flag_t *stop, block_buffers_t *bb)
{
    int failed = 0, stopped = 0;
    unsigned long long no_cell = 0;
    const uint64_t per = (count + TRACE_CHUNKS - 1) / TRACE_CHUNKS;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : failed, stopped, no_cell)
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
        /* Work on a copy: neighbouring chunks share cache lines, and their counters change with
         * every segment and hit. */
        photon_hits_t local = bb->chunk[c];
        photon_hits_t *out = &local;
        out->n = 0;
        uint64_t lo = first + c * per, hi = lo + per;
        if (hi > first + count) hi = first + count;
        for (uint64_t i = lo; i < hi && !failed && !stopped; i++) {
            if (stop_requested(stop)) { stopped = 1; break; }
            size_t before = out->n;
            if (photon_trace(scene, tr, i, out)) { failed = 1; break; }
            /* Find each hit's bucket once, here in parallel; with skips, drop the hits
             * that reach no hit point's cell. */
            size_t keep = before;
            for (size_t k = before; k < out->n; k++) {
                photon_hit_t *ph = &out->hits[k];
                ph->bucket = grid_bucket(g, ph->x);
                if (skip && ph->bucket == GRID_NO_BUCKET) { no_cell++; continue; }
                out->hits[keep++] = *ph;
            }
            out->n = keep;
        }
        bb->chunk[c] = local;
    }
    if (failed) return -1;
    if (stopped) {
        for (unsigned c = 0; c < TRACE_CHUNKS; c++) bb->chunk[c].n = bb->chunk[c].segments = 0;
        return 1;
    }
    bb->no_cell += no_cell;
    return 0;
}

/* Progress on stderr; a failed write (EPIPE from a closed pipe, SIGPIPE ignored) only stops
 * the printing, never the render. */
static void progress(render_options_t *opt, uint64_t done, uint64_t total, double t0, int *last_decile)
{
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

/* What only the photon pass uses: the grid, the traced hits and the candidate lists (freed before
 * the radiance pass, so that its peak does not add to theirs). */
static void free_photon_pass(render_session_t *s)
{
    if (s->bb)
        for (unsigned c = 0; c < TRACE_CHUNKS; c++) photon_hits_free(&s->bb->chunk[c]);
    grid_free(&s->grid);
    update_batch_free(&s->batch);
    if (s->scratch)
        for (int p = 0; p < s->T; p++) update_batch_scratch_free(&s->scratch[p]);
}

static void session_free(render_session_t *s)
{
    free_photon_pass(s);
    free(s->bb);
    free(s->perm);
    free(s->owner);
    free(s->scratch);
    free(s->ust);
    update_ops_free(&s->ops);
    tracer_destroy(s->tr);
    free(s->own_lo);
    free(s->counts);
    free(s->sendbuf);
    free(s->recvbuf);
    free(s);
}

/* More than one MPI rank: the partition and the options it supports. Rank r owns the hit
 * points [r n / N, (r + 1) n / N) of the spatial order (hp_order.c, render_dist_lo): contiguous runs of nearby
 * hit points, so a photon's candidates mostly belong to one rank. The others' hit points go to
 * part T, which no thread applies. opt.one_rank: one rank, whatever the launcher. 0, or -1 with err. */
static int dist_open(render_session_t *s, char *err, size_t errlen)
{
    s->nranks = s->opt.one_rank ? 1 : render_dist_size();
    s->rank = s->opt.one_rank ? 0 : render_dist_rank();
    s->res->stats.mpi_ranks = s->nranks;
    if (s->nranks < 2) return 0;
    if (s->photon_major || s->opt.checkpoint || s->opt.resume || s->opt.time_limit > 0) {
        snprintf(err, errlen, "under MPI with %d ranks: --scan photon, --checkpoint, --resume, --time-limit and "
                 "recording operations are not supported", s->nranks);
        return -1;
    }
    const size_t n = s->res->hp.n;
    s->own_lo = malloc((size_t)(s->nranks + 1) * sizeof *s->own_lo);
    s->counts = malloc((size_t)s->nranks * sizeof *s->counts);
    if (!s->own_lo || !s->counts) { snprintf(err, errlen, "out of memory"); return -1; }
    for (int r = 0; r <= s->nranks; r++) s->own_lo[r] = render_dist_lo(n, r, s->nranks);
    for (size_t i = 0; i < n; i++)
        if (i < s->own_lo[s->rank] || i >= s->own_lo[s->rank + 1]) s->owner[i] = (uint16_t)s->T;
    return 0;
}

render_session_t *render_open(const scene_t *scene, const render_options_t *opt, render_result_t *res,
                              char *err, size_t errlen)
{
    memset(res, 0, sizeof *res);
    render_session_t *s = calloc(1, sizeof *s);
    if (!s) { snprintf(err, errlen, "out of memory"); return NULL; }
    s->scene = scene;
    s->opt = *opt;
    s->res = res;
    render_stats_t *st = &res->stats;
    s->t_start = omp_get_wtime();
    const char *phase = "set-up";
    if (!(opt->alpha == 0 || (opt->alpha > 0 && opt->alpha <= 1))) {
        snprintf(err, errlen, "alpha %g is not in (0, 1]", opt->alpha);
        goto fail;
    }
    if (opt->record_ops && opt->precision != PRECISION_FP32) {
        snprintf(err, errlen, "recording the PREE operations needs --precision fp32");
        goto fail;
    }
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
    s->T = opt->record_ops ? 1 : omp_get_max_threads();
    render_stats_scene(st, scene);
    st->threads = s->T;
    s->skip = !opt->no_skip && opt->grid == GRID_CELLS;
    s->npix = (size_t)opt->width * (size_t)opt->height;
    /* Memory: before anything large, with one hit point a pixel; again with the true count. */
    if (mem_check(mem_estimate_start(st->scene_triangles, s->npix), opt->max_memory, MEM_START_WHAT, err, errlen))
        goto fail;
    s->bb = calloc(1, sizeof *s->bb);
    res->rgb = calloc(s->npix * 3, sizeof *res->rgb);
    if (!s->bb || !res->rgb) { snprintf(err, errlen, "out of memory for a %dx%d image", opt->width, opt->height); goto fail; }
    res->width = opt->width;
    res->height = opt->height;

    /* Acceleration structure and eye pass. */
    phase = "BVH build";
    render_test_interrupt("bvh");
    double t = omp_get_wtime();
    s->tr = tracer_create(scene, opt->interrupt, err, errlen);
    if (!s->tr) goto fail;
    st->sec_bvh = omp_get_wtime() - t;
    phase = "eye pass";
    render_test_interrupt("eye");
    t = omp_get_wtime();
    eye_stats_t es;
    if (eye_pass(scene, s->tr, opt->width, opt->height, &res->hp, &es, opt->interrupt, err, errlen)) goto fail;
    if (opt->checkpoint || opt->resume) s->fingerprint = checkpoint_fingerprint(scene, opt, &res->hp);
    st->sec_eye = omp_get_wtime() - t;
    st->hit_points = res->hp.n;
    if (mem_check((uint64_t)res->hp.n * MEM_HIT_POINT_BYTES, opt->max_memory, "the hit points' state and grid",
                  err, errlen))
        goto fail;
    st->eye_rays = es.rays;
    st->glass_splits = es.glass_splits;
    for (size_t i = 0; i < res->hp.n; i++) st->hit_points_zero_weight += hitpoints_zero_weight(&res->hp, i);

    /* Initial radius, hit-point state, and the grid. */
    phase = "grid build";
    render_test_interrupt("grid");
    t = omp_get_wtime();
    st->r0 = grid_initial_radius(&res->hp, opt->width, opt->height);
    if (res->hp.n && !(st->r0 > 0)) {   /* e.g. a 1x1 image: one hit point, a box of size 0 */
        snprintf(err, errlen, "the %zu hit point(s) lie at one place, so the initial radius (from their "
                 "bounding box) is 0: use a larger image", res->hp.n);
        goto fail;
    }
    /* The photon pass holds the hit points in spatial order (model/ppm/hp_order.c); the state is
     * set per hit point, so it is made after the reordering, which then moves fewer arrays. */
    s->perm = hp_order_spatial(&res->hp, opt->width, s->T, st->r0);
    if (!s->perm || hp_order_apply(&res->hp, s->perm)) { snprintf(err, errlen, "out of memory for hit points"); goto fail; }
    if (init_state(&res->hp, opt, st->r0)) { snprintf(err, errlen, "out of memory for hit points"); goto fail; }
    /* The photon-major scan reads a grid part per thread; the bucket-major screening reads one
     * grid of every hit point and routes what it keeps to the owning part. */
    s->photon_major = opt->record_ops || opt->scan == SCAN_PHOTON;
    s->owner = malloc((res->hp.n ? res->hp.n : 1) * sizeof *s->owner);
    if (!s->owner) { snprintf(err, errlen, "out of memory for hit points"); goto fail; }
    for (size_t i = 0; i < res->hp.n; i++) s->owner[i] = (uint16_t)grid_owner(&res->hp, i, opt->width, s->T);
    if (dist_open(s, err, errlen)) goto fail;
    if (res->hp.n && grid_build(&s->grid, opt->grid, &res->hp, st->r0, opt->width, s->photon_major ? s->T : 1,
                                !s->skip, opt->interrupt, err, errlen))
        goto fail;
    st->r_safe = s->grid.r_safe;
    for (int p = 0; p < s->grid.num_parts; p++) st->grid_entries += s->grid.parts[p].num_entries;
    st->grid_entries_final = st->grid_entries;
    st->hit_point_bytes = hitpoints_bytes_each(&res->hp);
    st->grid_entry_bytes = GRID_ENTRY_BYTES;
    st->sec_grid = omp_get_wtime() - t;

    s->emitted_target = render_emitted(opt->photons);
    s->ust = calloc((size_t)s->T, sizeof *s->ust);
    s->scratch = calloc((size_t)s->T, sizeof *s->scratch);
    if (!s->ust || !s->scratch) { snprintf(err, errlen, "out of memory"); goto fail; }
    if (opt->resume && render_session_resume(s, err, errlen)) goto fail;
    s->t_photons = omp_get_wtime();
    return s;
fail:
    if (stop_requested(opt->interrupt)) snprintf(err, errlen, STOP_MESSAGE " during the %s", phase);
    session_free(s);
    return NULL;
}

/* The update of one traced block: photon-major per owned part, or screened bucket-major and
 * applied per part. 0 or -1 (out of memory). */
static int update_block(render_session_t *s)
{
    hitpoints_t *h = &s->res->hp;
    const precision_t prec = s->opt.precision;
    const int T = s->T;
    block_buffers_t *bb = s->bb;
    if (s->photon_major) {
        update_ops_t *ops = s->opt.record_ops ? &s->ops : NULL;
#pragma omp parallel num_threads(T)
        {
            const int p = omp_get_thread_num();
            for (unsigned c = 0; c < TRACE_CHUNKS; c++)
                update_part(h, &s->grid, p, prec, s->skip, bb->chunk[c].hits, bb->chunk[c].n, &s->ust[p], ops);
        }
        return ops && ops->failed ? -1 : 0;
    }
    int failed = update_batch_prepare(&s->batch, bb->chunk, TRACE_CHUNKS, s->grid.num_buckets);
    const int dist = s->nranks > 1;   /* part T: the other ranks' hit points, never applied */
    s->batch.owner = T > 1 || dist ? s->owner : NULL;
    for (int p = 0; p < T && !failed; p++) failed |= update_batch_scratch_reset(&s->scratch[p], T + dist);
    if (failed) return -1;
    /* Screening: any thread, bucket groups; applying: each thread its own part. */
#pragma omp parallel num_threads(T) reduction(| : failed)
    {
        const int p = omp_get_thread_num();
#pragma omp for schedule(dynamic, 1)
        for (size_t gi = 0; gi < s->batch.n_groups; gi += SCREEN_GROUPS)
            failed |= update_batch_screen(h, &s->grid, prec, s->skip, &s->batch, gi, gi + SCREEN_GROUPS,
                                          &s->ust[p], &s->scratch[p]);
#pragma omp for schedule(static, 1)
        for (int q = 0; q < T; q++)
            failed |= update_batch_apply(h, prec, &s->batch, q, s->scratch, T, &s->ust[p]);
    }
    for (int p = 0; dist && s->own_block && p < T; p++)
        for (int q = 0; q <= T; q++) {
            s->res->stats.mpi_kept += s->scratch[p].list[q].n;
            if (q == T) s->res->stats.mpi_kept_foreign += s->scratch[p].list[q].n;
        }
    return failed ? -1 : 0;
}

/* Radii only shrink: after blocks 1, 2, 4, 8, ... drop the grid entries that the current radii
 * rule out (model/ppm/grid_refilter.c). Not with --no-skip (the oracle) nor when recording the
 * co-simulation's operations (the host does not read the PREE's radii), nor with the environment
 * variable PREE_NO_REFILTER set (make bench's before/after rows, like PREE_NO_AVX2). 0 or -1 (memory). */
static int refilter_block(render_session_t *s)
{
    s->blocks++;
    if (!s->skip || s->opt.record_ops || (s->blocks & (s->blocks - 1)) || getenv("PREE_NO_REFILTER")) return 0;
    render_stats_t *st = &s->res->stats;
    const double t = omp_get_wtime();
    const long long dropped = grid_refilter(&s->grid, &s->res->hp, s->opt.precision, s->T);
    if (dropped < 0) return -1;
    st->grid_refilters++;
    st->grid_entries_final -= (size_t)dropped;
    st->sec_refilter += omp_get_wtime() - t;
    return 0;
}

static int step_block(render_session_t *s, char *err, size_t errlen)
{
    render_stats_t *st = &s->res->stats;
    if (s->interrupted || s->done_photons >= s->emitted_target || !s->res->hp.n) return 0;
    uint64_t count = s->emitted_target - s->done_photons;
    if (count > PHOTON_BLOCK) count = PHOTON_BLOCK;
    update_ops_clear(&s->ops);
    char block_name[32];   /* fault injection: "block1" is this run's first block */
    snprintf(block_name, sizeof block_name, "block%llu",
             (unsigned long long)((s->done_photons - s->res->stats.photons_resumed) / PHOTON_BLOCK + 1));
    render_test_interrupt(block_name);
    double t = omp_get_wtime();
    const int traced = trace_block(s->scene, s->tr, &s->grid, s->skip, s->opt.photon_offset + s->done_photons, count,
                                   s->opt.interrupt, s->bb);
    if (traced < 0) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
    if (traced > 0) {   /* interrupted: the image keeps the whole blocks done */
        s->interrupted = 1;
        if (s->opt.progress) fputc('\n', stderr);
        return 0;
    }
    st->sec_trace += omp_get_wtime() - t;
    if (s->opt.precision == PRECISION_FP32 && render_fp32_check_hits(s->bb->chunk, TRACE_CHUNKS, err, errlen)) return -1;
    t = omp_get_wtime();
    if (update_block(s)) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
    st->sec_update += omp_get_wtime() - t;
    if (refilter_block(s)) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
        st->photon_hits += s->bb->chunk[c].n;
        st->photon_segments += s->bb->chunk[c].segments;
        s->bb->chunk[c].segments = 0;
    }
    s->done_photons += count;
    progress(&s->opt, s->done_photons, s->emitted_target, s->t_photons, &s->last_decile);
    if (s->opt.interrupt && *s->opt.interrupt && s->done_photons < s->emitted_target) {
        /* Keep whole batches of 1000 photons so the radiance normalisation holds. */
        s->interrupted = 1;
        if (s->opt.progress) fputc('\n', stderr);
    }
    return 1;
}

/* The traced block in bb as bytes: the photon count, then per chunk its hit count, segments and
 * hits. 0 or -1 (memory). */
static int block_pack(render_session_t *s, uint64_t count, size_t *bytes)
{
    size_t n = sizeof(uint64_t);
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) n += 2 * sizeof(uint64_t) + s->bb->chunk[c].n * sizeof(photon_hit_t);
    if (n > s->send_cap) {
        void *p = realloc(s->sendbuf, n);
        if (!p) return -1;
        s->sendbuf = p;
        s->send_cap = n;
    }
    char *o = s->sendbuf;
    memcpy(o, &count, sizeof count), o += sizeof count;
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
        const photon_hits_t *ch = &s->bb->chunk[c];
        const uint64_t hdr[2] = {ch->n, ch->segments};
        memcpy(o, hdr, sizeof hdr), o += sizeof hdr;
        if (ch->n) memcpy(o, ch->hits, ch->n * sizeof *ch->hits), o += ch->n * sizeof *ch->hits;
    }
    *bytes = n;
    return 0;
}

/* A packed block back into bb; its photon count. -1 (memory). */
static long long block_unpack(render_session_t *s, const char *in)
{
    uint64_t count;
    memcpy(&count, in, sizeof count), in += sizeof count;
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
        photon_hits_t *ch = &s->bb->chunk[c];
        uint64_t hdr[2];
        memcpy(hdr, in, sizeof hdr), in += sizeof hdr;
        if (hdr[0] > ch->cap) {
            void *p = realloc(ch->hits, hdr[0] * sizeof *ch->hits);
            if (!p) return -1;
            ch->hits = p;
            ch->cap = hdr[0];
        }
        ch->n = hdr[0];
        ch->segments = hdr[1];
        if (ch->n) memcpy(ch->hits, in, ch->n * sizeof *ch->hits), in += ch->n * sizeof *ch->hits;
    }
    return (long long)count;
}

/* One round under MPI (docs/scale_out.md): rank r traces the round's block r (blocks keep their
 * photon indices); the ranks agree on failing or stopping; every rank receives every block and
 * applies them in photon order to the hit points it owns. 1 (a round done), 0 (ended), -1. */
static int dist_round(render_session_t *s, char *err, size_t errlen)
{
    render_stats_t *st = &s->res->stats;
    if (s->interrupted || s->done_photons >= s->emitted_target || !s->res->hp.n) return 0;
    enum { GO = 0, STOP_AFTER = 1, ABANDONED = 2, FAILED = 3 };
    const uint64_t first = s->done_photons + (uint64_t)s->rank * PHOTON_BLOCK;
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
        const int traced = trace_block(s->scene, s->tr, &s->grid, s->skip, s->opt.photon_offset + first, count,
                                       s->opt.interrupt, s->bb);
        if (traced < 0) { snprintf(mine, sizeof mine, "out of memory in the photon pass"); status = FAILED; }
        else if (traced > 0) status = ABANDONED;
        else if (s->opt.precision == PRECISION_FP32 && render_fp32_check_hits(s->bb->chunk, TRACE_CHUNKS, mine, sizeof mine))
            status = FAILED;
    }
    if (status == GO && s->opt.interrupt && *s->opt.interrupt) status = STOP_AFTER;
    size_t bytes = 0;
    if (status == GO || status == STOP_AFTER) {
        if (block_pack(s, count, &bytes)) { snprintf(mine, sizeof mine, "out of memory in the photon pass"); status = FAILED; }
    }
    st->sec_trace += omp_get_wtime() - t;
    status = render_dist_max(status);
    if (status == FAILED) {   /* rank 0 reports the first failing rank's message */
        if (render_dist_allgather(mine, sizeof mine, &s->recvbuf, &s->recv_cap, s->counts)) {
            snprintf(err, errlen, "out of memory in the photon pass");
            return -1;
        }
        err[0] = '\0';
        for (int r = 0; r < s->nranks && !err[0]; r++) snprintf(err, errlen, "%s", (const char *)s->recvbuf + (size_t)r * sizeof mine);
        if (!err[0]) snprintf(err, errlen, "a rank failed in the photon pass");
        return -1;
    }
    if (status == ABANDONED) {   /* the image keeps the rounds done */
        s->interrupted = 1;
        if (s->opt.progress) fputc('\n', stderr);
        return 0;
    }
    t = omp_get_wtime();
    if (render_dist_allgather(s->sendbuf, bytes, &s->recvbuf, &s->recv_cap, s->counts)) {
        snprintf(err, errlen, "out of memory in the photon pass");
        return -1;
    }
    s->bytes_sent += (unsigned long long)bytes * (unsigned long long)(s->nranks - 1);
    st->sec_trace += omp_get_wtime() - t;
    const char *in = s->recvbuf;
    for (int r = 0; r < s->nranks; in += s->counts[r], r++) {
        const long long n = block_unpack(s, in);
        if (n < 0) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
        if (!n) continue;
        t = omp_get_wtime();
        s->own_block = r == s->rank;   /* the crossing figure counts each block once, on its tracer */
        if (update_block(s) || refilter_block(s)) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
        st->sec_update += omp_get_wtime() - t;
        for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
            st->photon_hits += s->bb->chunk[c].n;
            st->photon_segments += s->bb->chunk[c].segments;
        }
        s->done_photons += (uint64_t)n;
    }
    progress(&s->opt, s->done_photons, s->emitted_target, s->t_photons, &s->last_decile);
    if (status == STOP_AFTER && s->done_photons < s->emitted_target) {
        s->interrupted = 1;
        if (s->opt.progress) fputc('\n', stderr);
    }
    return 1;
}

/* Under MPI, after the photon pass: every rank's hit points to rank 0 (in the spatial order,
 * before it is undone), and the counters summed. */
static void dist_close(render_session_t *s)
{
    hitpoints_t *h = &s->res->hp;
    render_stats_t *st = &s->res->stats;
    const size_t *lo = s->own_lo;
    render_dist_gather_ranges(h->hot, sizeof *h->hot, lo);
    if (h->flux) render_dist_gather_ranges(h->flux, sizeof *h->flux, lo);
    if (h->r2) render_dist_gather_ranges(h->r2, sizeof *h->r2, lo);
    if (h->r2_f32) render_dist_gather_ranges(h->r2_f32, sizeof *h->r2_f32, lo);
    if (h->fp32) render_dist_gather_ranges(h->fp32, sizeof *h->fp32, lo);
    if (h->stable) render_dist_gather_ranges(h->stable, sizeof *h->stable, lo);
    /* Every rank traced its own blocks (no_cell) and applied only its hit points (accepted). */
    unsigned long long v[5] = {s->bb->no_cell, st->upd.accepted, s->bytes_sent, st->mpi_kept, st->mpi_kept_foreign};
    render_dist_sum(v, 5);
    s->bb->no_cell = v[0];
    st->upd.accepted = v[1];
    st->mpi_bytes_sent = v[2];
    st->mpi_kept = v[3];
    st->mpi_kept_foreign = v[4];
}

int render_step(render_session_t *s, char *err, size_t errlen)
{
    if (s->nranks > 1) {
        const int r = dist_round(s, err, errlen);
        if (r < 0) s->failed = 1;
        return r;
    }
    int r = step_block(s, err, errlen);
    if (r < 0) s->failed = 1;
    return r;
}

const update_ops_t *render_block_ops(const render_session_t *s) { return &s->ops; }

const uint32_t *render_hp_address(const render_session_t *s) { return s->perm; }

int render_close(render_session_t *s, char *err, size_t errlen)
{
    render_result_t *res = s->res;
    render_stats_t *st = &res->stats;
    int rc = -1;
    if (s->failed) goto done;
    if (s->interrupted && !s->done_photons) { snprintf(err, errlen, STOP_MESSAGE " during the first photon block"); goto done; }
    st->upd = render_session_update_totals(s);
    if (s->nranks > 1) {
        dist_close(s);
        if (s->rank) {   /* rank 0 evaluates and writes */
            rc = s->interrupted ? 1 : 0;
            goto done;
        }
    }
    free_photon_pass(s);
    st->photon_hits_no_cell = s->bb->no_cell;
    st->photon_hits += s->bb->no_cell;
    st->photons_emitted = res->hp.n ? s->done_photons : s->emitted_target;
    if (hp_order_restore(&res->hp, s->perm)) { snprintf(err, errlen, "out of memory for hit points"); goto done; }

    /* Radiance evaluation. */
    double t = omp_get_wtime();
    if (radiance_evaluate_preu(&res->hp, s->opt.precision, st->photons_emitted, s->skip, s->opt.preu ? s->opt.preu : 4,
                               res->rgb, s->npix, &st->radiance_skipped)) {
        snprintf(err, errlen, "out of memory in radiance evaluation");
        goto done;
    }
    st->sec_radiance = omp_get_wtime() - t;
    if (s->opt.precision == PRECISION_FP32 && render_fp32_result_check(res, err, errlen)) goto done;
    render_hash_results(res, s->opt.precision);
    rc = s->interrupted ? 1 : 0;
done:
    st->sec_total = omp_get_wtime() - s->t_start;
    session_free(s);
    st->peak_rss_kb = render_peak_rss_kb();
    if (st->hit_points) st->peak_bytes_per_hit_point = 1024.0 * (double)st->peak_rss_kb / (double)st->hit_points;
    return rc;
}

void render_stats_scene(render_stats_t *st, const scene_t *scene)
{
    st->scene_spheres = (unsigned long long)scene->num_spheres;
    for (int m = 0; m < scene->num_meshes; m++) st->scene_triangles += scene->meshes[m].num_triangles;
    st->scene_lights = (unsigned long long)scene->num_lights;
    st->scene_mirror = scene->has_mirror;
    st->scene_glass = scene->has_glass;
}

void render_result_free(render_result_t *res)
{
    free(res->rgb);
    hitpoints_free(&res->hp);
    memset(res, 0, sizeof *res);
}

update_stats_t render_session_update_totals(const render_session_t *s)
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
