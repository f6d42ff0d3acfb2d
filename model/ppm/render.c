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
#include "photon_pass.h"
#include "radiance.h"
#include "render.h"
#include "update_batch.h"

#define PHOTON_BLOCK 32000u   /* whole batches of 1000 photons */
#define TRACE_CHUNKS 64u
_Static_assert(TRACE_CHUNKS <= UPDATE_BATCH_MAX_CHUNKS, "update_batch_prepare takes at most UPDATE_BATCH_MAX_CHUNKS chunks");
#define SCREEN_GROUPS 256   /* bucket groups a thread screens at a time */

static long peak_rss_kb(void)
{
    struct rusage ru;
    return getrusage(RUSAGE_SELF, &ru) == 0 ? ru.ru_maxrss : -1;
}

/* Hit-point state before the first photon: radius r0, no photons, no flux; the update rule's
 * alpha and, in fp32 mode, the datapath's state layout. */
static int init_state(hitpoints_t *h, const render_options_t *opt, double r0)
{
    h->alpha = render_alpha(opt);
    h->alpha32 = preu_f32(h->alpha);
    h->kappa32 = preu_kappa(h->alpha32);
    for (size_t i = 0; i < h->n; i++) {
        h->r2[i] = r0 * r0;
        h->hot[i].count = 0;
        h->flux[i] = v3(0, 0, 0);
    }
    if (opt->precision != PRECISION_FP32) return 0;
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
    return 0;
}

typedef struct {
    photon_hits_t chunk[TRACE_CHUNKS];
    unsigned long long no_cell;
} block_buffers_t;

/* Trace the photons of sequence indices [first, first + count) into the ordered chunk buffers;
 * drop hits that reach no hit point's cell when skipping. Returns 0 or -1 (out of memory). */
static int trace_block(const scene_t *scene, const tracer_t *tr, const grid_t *g, int skip,
                       uint64_t first, uint64_t count, block_buffers_t *bb)
{
    int failed = 0;
    unsigned long long no_cell = 0;
    const uint64_t per = (count + TRACE_CHUNKS - 1) / TRACE_CHUNKS;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : failed, no_cell)
    for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
        /* Work on a copy: neighbouring chunks share cache lines, and their counters change with
         * every segment and hit. */
        photon_hits_t local = bb->chunk[c];
        photon_hits_t *out = &local;
        out->n = 0;
        uint64_t lo = first + c * per, hi = lo + per;
        if (hi > first + count) hi = first + count;
        for (uint64_t i = lo; i < hi && !failed; i++) {
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
    bb->no_cell += no_cell;
    return failed ? -1 : 0;
}

static void progress(const render_options_t *opt, uint64_t done, uint64_t total, double t0, int *last_decile)
{
    if (!opt->progress) return;
    const int tty = isatty(2);
    const int decile = (int)(10 * done / total);
    if (!tty && decile == *last_decile) return;
    *last_decile = decile;
    double el = omp_get_wtime() - t0;
    fprintf(stderr, "%spree: photons %llu/%llu (%3.0f%%) %.1fs%s", tty ? "\r" : "", (unsigned long long)done,
            (unsigned long long)total, 100.0 * (double)done / (double)total, el, tty && done < total ? "" : "\n");
    fflush(stderr);
}

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) { h ^= p[i]; h *= 0x100000001b3ull; }
    return h;
}

/* Hashes of the image and of the final hit-point state, for determinism checks. */
static void hash_results(render_result_t *res, precision_t prec)
{
    const uint64_t basis = 0xcbf29ce484222325ull;
    const hitpoints_t *h = &res->hp;
    res->stats.image_hash = fnv1a(basis, res->rgb, (size_t)res->width * res->height * 3 * sizeof *res->rgb);
    uint64_t s = basis;
    if (prec == PRECISION_FP32 && h->stable) s = fnv1a(s, h->stable, h->n * sizeof *h->stable);
    else if (prec == PRECISION_FP32) s = fnv1a(s, h->fp32, h->n * sizeof *h->fp32);
    else {
        s = fnv1a(s, h->r2, h->n * sizeof *h->r2);
        s = fnv1a(s, h->flux, h->n * sizeof *h->flux);
        for (size_t i = 0; i < h->n; i++) s = fnv1a(s, &h->hot[i].count, sizeof h->hot[i].count);
    }
    res->stats.state_hash = s;
}

/* fp32 mode: every photon hit crosses into the PREE as binary32 (update_photon_fp32); a flux or
 * position beyond binary32's range there is an error naming the photon. */
static int fp32_check_hits(const block_buffers_t *bb, char *err, size_t errlen)
{
    for (unsigned c = 0; c < TRACE_CHUNKS; c++)
        for (size_t i = 0; i < bb->chunk[c].n; i++) {
            const photon_hit_t *h = &bb->chunk[c].hits[i];
            const double v[6] = {h->flux.x, h->flux.y, h->flux.z, h->x.x, h->x.y, h->x.z};
            for (int k = 0; k < 6; k++)
                if (!isfinite((float)v[k])) {
                    snprintf(err, errlen, "fp32: photon %llu's %s (%g, %g, %g) is beyond binary32's range at the "
                             "PREE boundary: scale the light or the scene down, or use --precision double",
                             (unsigned long long)h->photon, k < 3 ? "flux" : "hit position",
                             v[k < 3 ? 0 : 3], v[k < 3 ? 1 : 4], v[k < 3 ? 2 : 5]);
                    return -1;
                }
        }
    return 0;
}

/* fp32 mode: count the stable datapath's saturated hit points, and refuse an image with an
 * infinite or NaN pixel (docs/numerics.md: what overflows where). */
static int fp32_result_check(render_result_t *res, char *err, size_t errlen)
{
    const hitpoints_t *h = &res->hp;
    unsigned long long sat = 0;
    for (size_t i = 0; h->stable && i < h->n; i++) {
        const preu_shp_t *s = &h->stable[i];
        sat += s->w == WIDE_MAX || s->T[0] == WIDE_MAX || s->T[1] == WIDE_MAX || s->T[2] == WIDE_MAX;
    }
    res->stats.hit_points_saturated = sat;
    const size_t n = (size_t)res->width * (size_t)res->height * 3;
    size_t bad = 0, first = 0;
    for (size_t j = 0; j < n; j++)
        if (!isfinite(res->rgb[j]) && !bad++) first = j / 3;
    if (!bad) return 0;
    snprintf(err, errlen, "fp32: %zu pixel values are infinite or NaN (first at pixel %zu, %zu): a value left "
             "binary32's range (light flux above 3.4e38, or the %s datapath's radius collapsed); "
             "try --precision double%s", bad, first % (size_t)res->width, first / (size_t)res->width,
             h->stable ? "stable" : "paper", h->stable ? "" : " or --datapath stable");
    return -1;
}

struct render_session {
    const scene_t *scene;
    render_options_t opt;
    render_result_t *res;
    double t_start, t_photons;
    int T, skip, photon_major, interrupted, last_decile;
    size_t npix;
    grid_t grid;
    block_buffers_t *bb;
    tracer_t *tr;
    uint32_t *perm;
    uint16_t *owner;
    update_batch_t batch;
    update_scratch_t *scratch;
    update_stats_t *ust;
    update_ops_t ops;
    uint64_t emitted_target, done_photons;
    int failed;              /* a step failed: close only releases */
};

static void session_free(render_session_t *s)
{
    if (s->bb) {
        for (unsigned c = 0; c < TRACE_CHUNKS; c++) photon_hits_free(&s->bb->chunk[c]);
        free(s->bb);
    }
    grid_free(&s->grid);
    free(s->perm);
    free(s->owner);
    update_batch_free(&s->batch);
    if (s->scratch)
        for (int p = 0; p < s->T; p++) update_batch_scratch_free(&s->scratch[p]);
    free(s->scratch);
    free(s->ust);
    update_ops_free(&s->ops);
    tracer_destroy(s->tr);
    free(s);
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
    st->threads = s->T;
    st->scene_spheres = (unsigned long long)scene->num_spheres;
    for (int m = 0; m < scene->num_meshes; m++) st->scene_triangles += scene->meshes[m].num_triangles;
    st->scene_lights = (unsigned long long)scene->num_lights;
    st->scene_mirror = scene->has_mirror;
    st->scene_glass = scene->has_glass;
    s->skip = !opt->no_skip && opt->grid == GRID_CELLS;
    s->npix = (size_t)opt->width * (size_t)opt->height;
    s->bb = calloc(1, sizeof *s->bb);
    res->rgb = calloc(s->npix * 3, sizeof *res->rgb);
    if (!s->bb || !res->rgb) { snprintf(err, errlen, "out of memory for a %dx%d image", opt->width, opt->height); goto fail; }
    res->width = opt->width;
    res->height = opt->height;

    /* Acceleration structure and eye pass. */
    double t = omp_get_wtime();
    s->tr = tracer_create(scene, err, errlen);
    if (!s->tr) goto fail;
    st->sec_bvh = omp_get_wtime() - t;
    t = omp_get_wtime();
    eye_stats_t es;
    if (eye_pass(scene, s->tr, opt->width, opt->height, &res->hp, &es, err, errlen)) goto fail;
    st->sec_eye = omp_get_wtime() - t;
    st->hit_points = res->hp.n;
    st->eye_rays = es.rays;
    st->glass_splits = es.glass_splits;
    for (size_t i = 0; i < res->hp.n; i++) {
        vec3 w = res->hp.weight[i];
        st->hit_points_zero_weight += (w.x == 0 && w.y == 0 && w.z == 0);
    }

    /* Initial radius, hit-point state, and the grid. */
    t = omp_get_wtime();
    st->r0 = grid_initial_radius(&res->hp, opt->width, opt->height);
    if (init_state(&res->hp, opt, st->r0)) { snprintf(err, errlen, "out of memory for hit points"); goto fail; }
    /* The photon pass holds the hit points in spatial order (model/ppm/hp_order.c). */
    s->perm = hp_order_spatial(&res->hp, opt->width, s->T, st->r0);
    if (!s->perm || hp_order_apply(&res->hp, s->perm)) { snprintf(err, errlen, "out of memory for hit points"); goto fail; }
    /* The photon-major scan reads a grid part per thread; the bucket-major screening reads one
     * grid of every hit point and routes what it keeps to the owning part. */
    s->photon_major = opt->record_ops || opt->scan == SCAN_PHOTON;
    s->owner = malloc((res->hp.n ? res->hp.n : 1) * sizeof *s->owner);
    if (!s->owner) { snprintf(err, errlen, "out of memory for hit points"); goto fail; }
    for (size_t i = 0; i < res->hp.n; i++) s->owner[i] = (uint16_t)grid_owner(&res->hp, i, opt->width, s->T);
    if (res->hp.n && grid_build(&s->grid, opt->grid, &res->hp, st->r0, opt->width, s->photon_major ? s->T : 1,
                                !s->skip, err, errlen))
        goto fail;
    st->r_safe = s->grid.r_safe;
    for (int p = 0; p < s->grid.num_parts; p++) st->grid_entries += s->grid.parts[p].num_entries;
    st->sec_grid = omp_get_wtime() - t;

    s->emitted_target = render_emitted(opt->photons);
    s->ust = calloc((size_t)s->T, sizeof *s->ust);
    s->scratch = calloc((size_t)s->T, sizeof *s->scratch);
    if (!s->ust || !s->scratch) { snprintf(err, errlen, "out of memory"); goto fail; }
    s->t_photons = omp_get_wtime();
    return s;
fail:
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
    s->batch.owner = T > 1 ? s->owner : NULL;
    for (int p = 0; p < T && !failed; p++) failed |= update_batch_scratch_reset(&s->scratch[p], T);
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
    return failed ? -1 : 0;
}

static int step_block(render_session_t *s, char *err, size_t errlen)
{
    render_stats_t *st = &s->res->stats;
    if (s->interrupted || s->done_photons >= s->emitted_target || !s->res->hp.n) return 0;
    uint64_t count = s->emitted_target - s->done_photons;
    if (count > PHOTON_BLOCK) count = PHOTON_BLOCK;
    update_ops_clear(&s->ops);
    double t = omp_get_wtime();
    if (trace_block(s->scene, s->tr, &s->grid, s->skip, s->opt.photon_offset + s->done_photons, count, s->bb)) {
        snprintf(err, errlen, "out of memory in the photon pass");
        return -1;
    }
    st->sec_trace += omp_get_wtime() - t;
    if (s->opt.precision == PRECISION_FP32 && fp32_check_hits(s->bb, err, errlen)) return -1;
    t = omp_get_wtime();
    if (update_block(s)) { snprintf(err, errlen, "out of memory in the photon pass"); return -1; }
    st->sec_update += omp_get_wtime() - t;
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

int render_step(render_session_t *s, char *err, size_t errlen)
{
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
    for (int p = 0; p < s->T; p++) {
        st->upd.candidates += s->ust[p].candidates;
        st->upd.skipped_radius += s->ust[p].skipped_radius;
        st->upd.normal_passed += s->ust[p].normal_passed;
        st->upd.accepted += s->ust[p].accepted;
    }
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
    if (s->opt.precision == PRECISION_FP32 && fp32_result_check(res, err, errlen)) goto done;
    hash_results(res, s->opt.precision);
    rc = s->interrupted ? 1 : 0;
done:
    st->sec_total = omp_get_wtime() - s->t_start;
    session_free(s);
    st->peak_rss_kb = peak_rss_kb();
    return rc;
}

int render_run(const scene_t *scene, const render_options_t *opt, render_result_t *res,
               char *err, size_t errlen)
{
    render_session_t *s = render_open(scene, opt, res, err, errlen);
    if (!s) return -1;
    while (render_step(s, err, errlen) > 0) {}
    return render_close(s, err, errlen);   /* -1 after a failed step, with its message */
}

void render_result_free(render_result_t *res)
{
    free(res->rgb);
    hitpoints_free(&res->hp);
    memset(res, 0, sizeof *res);
}
