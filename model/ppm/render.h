/* render.h: one progressive photon mapping render: eye pass, grid, photon pass with ordered
 * updates, radiance evaluation. The output image is bit-identical for every thread count.
 *
 * render_run() returns 0 (complete), 1 (interrupted: the image holds the whole photon
 * batches done so far) or -1 with a one-line message in err. An fp32 render whose image holds
 * an infinity or a NaN (binary32 overflow of the light's flux, or the paper datapath's radius
 * collapsing) is an error (-1), never a silent image. */
#ifndef PREE_RENDER_H
#define PREE_RENDER_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>
#include "eye_pass.h"
#include "grid.h"
#include "hitpoints.h"
#include "scene.h"
#include "update.h"

typedef enum { SCAN_BUCKET = 0, SCAN_PHOTON = 1 } update_scan_t;

typedef struct {
    int width, height;
    uint64_t photons;        /* requested; emitted = max(photons / 1000, 1) * 1000 */
    uint64_t photon_offset;  /* photon k is traced with sequence index photon_offset + k (default 0) */
    precision_t precision;
    datapath_t datapath;     /* fp32: DATAPATH_PAPER (default) or DATAPATH_STABLE */
    double alpha;            /* radius reduction, in (0, 1]; 0: UPDATE_ALPHA */
    grid_kind_t grid;
    int threads;             /* 0: OpenMP's default */
    int no_skip;             /* 1: disable the skips (for proving them harmless) */
    update_scan_t scan;      /* SCAN_BUCKET (default): update_batch.c; SCAN_PHOTON: update_part, the oracle */
    int preu;                /* PREUs of the PREE whose radiance order fp32 mode reproduces (0: 4) */
    int progress;            /* 1: progress on stderr (a running line on a terminal, else every 10%) */
    volatile sig_atomic_t *interrupt;   /* set to stop after the current photon block */
    int record_ops;          /* fp32: record each block's PREE operations (render_block_ops); the
                              * update then runs photon-major on one thread */
} render_options_t;

typedef struct {
    unsigned long long hit_points, hit_points_zero_weight, eye_rays, glass_splits;
    unsigned long long photons_emitted, photon_segments, photon_hits, photon_hits_no_cell;
    update_stats_t upd;
    unsigned long long radiance_skipped;
    unsigned long long hit_points_saturated; /* stable datapath: w or T stopped at WIDE_MAX */
    double r0, r_safe;
    size_t grid_entries;
    double sec_bvh, sec_eye, sec_grid, sec_trace, sec_update, sec_radiance, sec_total;
    long peak_rss_kb;
    int threads;
    /* What the scene holds (the engine builds only what it needs). */
    unsigned long long scene_spheres, scene_triangles, scene_lights;
    int scene_mirror, scene_glass;
    uint64_t image_hash;     /* FNV-1a over the pixels' double bits */
    uint64_t state_hash;     /* FNV-1a over the final hit-point state (r2, count, flux or PREU words) */
} render_stats_t;

typedef struct {
    int width, height;
    double *rgb;             /* linear radiance, 3 per pixel, top row first */
    hitpoints_t hp;          /* final hit-point state */
    render_stats_t stats;
} render_result_t;

int render_run(const scene_t *scene, const render_options_t *opt, render_result_t *res,
               char *err, size_t errlen);

/* The same render driven step by step by its caller, who may look at each block's operations:
 *   render_open       eye pass, initial state, grid; NULL with err on failure (res is then to
 *                     be freed by render_result_free). res->hp holds the hit points in the
 *                     photon pass's order from here until render_close.
 *   render_hp_address photon-pass index -> hit-point address (the order of res->hp before
 *                     render_open reordered it and after render_close restores it)
 *   render_step       trace and apply the next photon block: 1 (a block done), 0 (no block
 *                     left, or interrupted), -1 with err
 *   render_block_ops  with opt->record_ops: the last block's operations, in photon order
 *   render_close      radiance, hashes; releases the session; returns as render_run */
typedef struct render_session render_session_t;
render_session_t *render_open(const scene_t *scene, const render_options_t *opt, render_result_t *res,
                              char *err, size_t errlen);
const uint32_t *render_hp_address(const render_session_t *s);
int render_step(render_session_t *s, char *err, size_t errlen);
const update_ops_t *render_block_ops(const render_session_t *s);
int render_close(render_session_t *s, char *err, size_t errlen);
void render_result_free(render_result_t *res);

/* The alpha a render uses: opt->alpha, or UPDATE_ALPHA when it is 0 (not set). */
static inline double render_alpha(const render_options_t *opt)
{
    return opt->alpha > 0 ? opt->alpha : UPDATE_ALPHA;
}

/* The emitted photon count for a request (whole batches of 1000, at least one). */
static inline uint64_t render_emitted(uint64_t requested)
{
    uint64_t b = requested / 1000;
    return (b ? b : 1) * 1000;
}

#endif
