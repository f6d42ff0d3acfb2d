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
    h->alpha = opt->alpha > 0 ? opt->alpha : UPDATE_ALPHA;
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

int render_run(const scene_t *scene, const render_options_t *opt, render_result_t *res,
               char *err, size_t errlen)
{
    memset(res, 0, sizeof *res);
    render_stats_t *st = &res->stats;
    const double t_start = omp_get_wtime();
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
    const int T = opt->sink ? 1 : omp_get_max_threads();
    if (!(opt->alpha == 0 || (opt->alpha > 0 && opt->alpha <= 1))) {
        snprintf(err, errlen, "alpha %g is not in (0, 1]", opt->alpha);
        return -1;
    }
    if (opt->sink && opt->precision != PRECISION_FP32) {
        snprintf(err, errlen, "co-simulation needs --precision fp32");
        return -1;
    }
    st->threads = T;
    st->scene_spheres = (unsigned long long)scene->num_spheres;
    for (int m = 0; m < scene->num_meshes; m++) st->scene_triangles += scene->meshes[m].num_triangles;
    st->scene_lights = (unsigned long long)scene->num_lights;
    st->scene_mirror = scene->has_mirror;
    st->scene_glass = scene->has_glass;
    const int skip = !opt->no_skip && opt->grid == GRID_CELLS;
    const size_t npix = (size_t)opt->width * (size_t)opt->height;
    int rc = -1;
    grid_t grid;
    memset(&grid, 0, sizeof grid);
    block_buffers_t *bb = calloc(1, sizeof *bb);
    res->rgb = calloc(npix * 3, sizeof *res->rgb);
    tracer_t *tr = NULL;
    uint32_t *perm = NULL;
    uint16_t *owner = NULL;
    update_batch_t batch;
    memset(&batch, 0, sizeof batch);
    update_scratch_t *scratch = NULL;
    if (!bb || !res->rgb) { snprintf(err, errlen, "out of memory for a %dx%d image", opt->width, opt->height); goto done; }
    res->width = opt->width;
    res->height = opt->height;

    /* Acceleration structure and eye pass. */
    double t = omp_get_wtime();
    tr = tracer_create(scene, err, errlen);
    if (!tr) goto done;
    st->sec_bvh = omp_get_wtime() - t;
    t = omp_get_wtime();
    eye_stats_t es;
    if (eye_pass(scene, tr, opt->width, opt->height, &res->hp, &es, err, errlen)) goto done;
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
    if (init_state(&res->hp, opt, st->r0)) { snprintf(err, errlen, "out of memory for hit points"); goto done; }
    if (opt->begin && opt->begin(opt->sink->user, &res->hp, render_emitted(opt->photons))) {
        snprintf(err, errlen, "the co-simulation could not start");
        goto done;
    }
    /* The photon pass holds the hit points in spatial order (model/hp_order.c). */
    perm = hp_order_spatial(&res->hp, opt->width, T, st->r0);
    if (!perm || hp_order_apply(&res->hp, perm)) { snprintf(err, errlen, "out of memory for hit points"); goto done; }
    if (opt->sink) opt->sink->addr = perm;
    /* The photon-major scan reads a grid part per thread; the bucket-major screening reads one
     * grid of every hit point and routes what it keeps to the owning part. */
    const int photon_major = opt->sink || opt->scan == SCAN_PHOTON;
    owner = malloc((res->hp.n ? res->hp.n : 1) * sizeof *owner);
    if (!owner) { snprintf(err, errlen, "out of memory for hit points"); goto done; }
    for (size_t i = 0; i < res->hp.n; i++) owner[i] = (uint16_t)grid_owner(&res->hp, i, opt->width, T);
    if (res->hp.n && grid_build(&grid, opt->grid, &res->hp, st->r0, opt->width, photon_major ? T : 1, !skip, err, errlen))
        goto done;
    st->r_safe = grid.r_safe;
    for (int p = 0; p < grid.num_parts; p++) st->grid_entries += grid.parts[p].num_entries;
    st->sec_grid = omp_get_wtime() - t;

    /* Photon pass: trace a block in parallel, then ordered updates per owned part. */
    const uint64_t emitted_target = render_emitted(opt->photons);
    uint64_t done_photons = 0;
    update_stats_t *ust = calloc((size_t)T, sizeof *ust);
    scratch = calloc((size_t)T, sizeof *scratch);
    if (!ust || !scratch) { snprintf(err, errlen, "out of memory"); goto done; }
    const double t_photons = omp_get_wtime();
    int interrupted = 0, last_decile = 0;
    while (done_photons < emitted_target && res->hp.n) {
        uint64_t count = emitted_target - done_photons;
        if (count > PHOTON_BLOCK) count = PHOTON_BLOCK;
        t = omp_get_wtime();
        if (trace_block(scene, tr, &grid, skip, opt->photon_offset + done_photons, count, bb)) {
            snprintf(err, errlen, "out of memory in the photon pass");
            free(ust);
            goto done;
        }
        st->sec_trace += omp_get_wtime() - t;
        if (opt->precision == PRECISION_FP32 && fp32_check_hits(bb, err, errlen)) { free(ust); goto done; }
        t = omp_get_wtime();
        if (photon_major) {
#pragma omp parallel num_threads(T)
            {
                const int p = omp_get_thread_num();
                for (unsigned c = 0; c < TRACE_CHUNKS; c++)
                    update_part(&res->hp, &grid, p, opt->precision, skip, bb->chunk[c].hits, bb->chunk[c].n, &ust[p], opt->sink);
            }
        } else {
            int failed = update_batch_prepare(&batch, bb->chunk, TRACE_CHUNKS, grid.num_buckets);
            batch.owner = T > 1 ? owner : NULL;
            for (int p = 0; p < T && !failed; p++) failed |= update_batch_scratch_reset(&scratch[p], T);
            if (!failed) {
                /* Screening: any thread, bucket groups; applying: each thread its own part. */
#pragma omp parallel num_threads(T) reduction(| : failed)
                {
                    const int p = omp_get_thread_num();
#pragma omp for schedule(dynamic, 1)
                    for (size_t gi = 0; gi < batch.n_groups; gi += SCREEN_GROUPS)
                        failed |= update_batch_screen(&res->hp, &grid, opt->precision, skip, &batch, gi, gi + SCREEN_GROUPS,
                                                      &ust[p], &scratch[p]);
#pragma omp for schedule(static, 1)
                    for (int q = 0; q < T; q++)
                        failed |= update_batch_apply(&res->hp, opt->precision, &batch, q, scratch, T, &ust[p]);
                }
            }
            if (failed) {
                snprintf(err, errlen, "out of memory in the photon pass");
                free(ust);
                goto done;
            }
        }
        if (opt->sink && opt->sink->failed) {
            snprintf(err, errlen, "the co-simulation stopped");
            free(ust);
            goto done;
        }
        st->sec_update += omp_get_wtime() - t;
        for (unsigned c = 0; c < TRACE_CHUNKS; c++) {
            st->photon_hits += bb->chunk[c].n;
            st->photon_segments += bb->chunk[c].segments;
            bb->chunk[c].segments = 0;
        }
        done_photons += count;
        progress(opt, done_photons, emitted_target, t_photons, &last_decile);
        if (opt->interrupt && *opt->interrupt && done_photons < emitted_target) {
            /* Keep whole batches of 1000 photons so the radiance normalisation holds. */
            interrupted = 1;
            if (opt->progress) fputc('\n', stderr);
            break;
        }
    }
    for (int p = 0; p < T; p++) {
        st->upd.candidates += ust[p].candidates;
        st->upd.skipped_radius += ust[p].skipped_radius;
        st->upd.normal_passed += ust[p].normal_passed;
        st->upd.accepted += ust[p].accepted;
    }
    free(ust);
    st->photon_hits_no_cell = bb->no_cell;
    st->photon_hits += bb->no_cell;
    st->photons_emitted = res->hp.n ? done_photons : emitted_target;
    if (hp_order_restore(&res->hp, perm)) { snprintf(err, errlen, "out of memory for hit points"); goto done; }

    /* Radiance evaluation. */
    t = omp_get_wtime();
    if (radiance_evaluate_preu(&res->hp, opt->precision, st->photons_emitted, skip, opt->preu ? opt->preu : 4,
                               res->rgb, npix, &st->radiance_skipped)) {
        snprintf(err, errlen, "out of memory in radiance evaluation");
        goto done;
    }
    st->sec_radiance = omp_get_wtime() - t;
    if (opt->precision == PRECISION_FP32 && fp32_result_check(res, err, errlen)) goto done;
    hash_results(res, opt->precision);
    rc = interrupted ? 1 : 0;
done:
    if (bb) {
        for (unsigned c = 0; c < TRACE_CHUNKS; c++) photon_hits_free(&bb->chunk[c]);
        free(bb);
    }
    grid_free(&grid);
    free(perm);
    free(owner);
    update_batch_free(&batch);
    if (scratch)
        for (int p = 0; p < T; p++) update_batch_scratch_free(&scratch[p]);
    free(scratch);
    if (opt->sink) opt->sink->addr = NULL;
    tracer_destroy(tr);
    st->sec_total = omp_get_wtime() - t_start;
    st->peak_rss_kb = peak_rss_kb();
    return rc;
}

void render_result_free(render_result_t *res)
{
    free(res->rgb);
    hitpoints_free(&res->hp);
    memset(res, 0, sizeof *res);
}
