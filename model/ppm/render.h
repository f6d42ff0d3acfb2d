// SPDX-License-Identifier: Apache-2.0
/* render.h: one progressive photon mapping render: eye pass, grid, photon pass with ordered
 * updates, radiance evaluation. The output image is bit-identical for every thread count.
 *
 * render_run is the progressive estimator only: its caller chooses between it and the photon-map
 * estimator (model/pm/pm_render.h; `pree render --estimator`: cli/cli_pm.c), and render_run does
 * not read opt->estimator.
 *
 * render_run() returns 0 (complete, or stopped by the time limit: stats.time_limited), 1
 * (interrupted: the image holds the whole photon blocks done so far) or -1 with a one-line
 * message in err (STOP_MESSAGE when interrupted before the first photon block was done: the BVH
 * build, eye pass, grid build and photon tracing poll the interrupt flag). An fp32 render whose image holds
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
#include "pm_stats.h"
#include "scene.h"
#include "update.h"

typedef enum { SCAN_BUCKET = 0, SCAN_PHOTON = 1 } update_scan_t;
typedef enum { ESTIMATOR_PPM = 0, ESTIMATOR_PM = 1 } estimator_t;
typedef enum { KNN_CLUSTERED = 0, KNN_NAIVE = 1, KNN_KDTREE = 2 } knn_search_t;
/* Where the PREE holds the hit points, which sets its radiance pass's order (docs/pree_top.md,
 * "Hit-point layout"): address a holds the a-th hit point of the spatial order of one part
 * (render_hp_address of a photon pass on one thread) or of the eye pass's order. */
typedef enum { HP_LAYOUT_SPATIAL = 0, HP_LAYOUT_PIXEL = 1 } hp_layout_t;

#define RENDER_PHOTON_BLOCK 32000u            /* photons traced and applied together */
#define RENDER_CHECKPOINT_EVERY (32ull * RENDER_PHOTON_BLOCK)

typedef struct render_result render_result_t;

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
    /* fp32: the PREE whose radiance pass the image reproduces bit for bit (model/ppm/radiance.h). */
    int preu;                /* its PREUs (0: 4) */
    int pipe_fast;           /* 1: their deep pipelines (RTL PipeFast = 1: radiance depth 64, not 12) */
    hp_layout_t layout;      /* its hit-point layout */
    int prees;               /* > 1: a board of this many such PREEs (model/ppm/radiance.h), which holds
                              * the spatial layout (layout is then not read) */
    double initial_radius;   /* > 0: every hit point's radius before the first photon (--radius); 0: the
                              * radius from the hit points' bounds (grid_initial_radius) */
    int eye_rays;            /* eye rays a pixel (eye_pass.h; 0 or 1: one, through the pixel's centre) */
    double exposure;         /* not read by the engine: its callers scale what they write as 8-bit
                              * images (PNG, PPM) by 2^exposure before the tone curve */
    int hide_lights;         /* 1: the camera does not see the area lights' emitted radiance (the image
                             * is the photon radiance alone); 0 (default): it does (eye_pass.h) */
    int progress;            /* 1: progress on stderr (a running line on a terminal, else every 10%) */
    volatile sig_atomic_t *interrupt;   /* set to stop: the photon block in progress is abandoned */
    double time_limit;       /* render_run: > 0: stop after the block in progress once this many
                              * seconds have passed since render_open began */
    const char *checkpoint;  /* render_run: write the state here (model/ppm/checkpoint.h) every
                              * checkpoint_every photons and when the photon pass ends or stops */
    uint64_t checkpoint_every; /* 0: RENDER_CHECKPOINT_EVERY */
    const char *checkpoint_note; /* text the checkpoint carries, not read by the engine (the
                              * command line's options: cli/cli_resume.c); NULL: none */
    /* render_run: a convergence series. At each photon count write_at[k] (ascending, whole
     * thousands) the photon pass stops on a block boundary and calls snapshot with the image,
     * hashes and statistics of the photons done: the bits a render of that many photons gives.
     * snapshot returns 0, or -1 with err to stop the render. */
    const uint64_t *write_at;
    int write_at_n;
    int (*snapshot)(void *ctx, const render_result_t *res, char *err, size_t errlen);
    void *snapshot_ctx;
    const char *resume;      /* render_eye_pass: continue from this checkpoint */
    uint64_t max_memory;     /* bytes the render may hold (mem_check.h); 0: RLIMIT_AS and MemAvailable */
    int record_ops;          /* fp32: record each block's PREE operations (render_block_ops); the
                              * update then runs photon-major on one thread */
    int one_rank;            /* 1: render the whole frame on this rank alone, even under MPI (each
                              * rank of the co-simulation under mpirun runs the whole engine) */
    /* The photon-map estimator (--estimator pm, model/pm/): the k nearest photons of each hit
     * point within max_radius, found by knn_search; photons traced in task units. */
    estimator_t estimator;   /* ESTIMATOR_PPM (default) or ESTIMATOR_PM: the caller's choice, which
                              * the statistics name (render_run itself is the PPM estimator) */
    int knn_k;               /* 0: 50 */
    double max_radius;       /* 0: the PPM initial radius */
    knn_search_t knn_search; /* KNN_CLUSTERED (default), KNN_KDTREE (single pass) or KNN_NAIVE (the oracle) */
    int knn_kernel;          /* the clustered search's prefilter path (knn_kernel_id_t; 0: the widest) */
    int knn_bench;           /* > 0: run every search this many times, interleaved, on the same trees */
    int knn_bench_oracle;    /* ... the oracle only this many (0: as many; -1: none) */
    int cluster_bundle;      /* 0: 2000 shading points a bundle */
    int task_photons;        /* photons per tracing task unit (0: 1000) */
    int task_static;         /* 1: static shares instead of the shared task queue */
} render_options_t;

typedef struct {
    unsigned long long hit_points, hit_points_zero_weight, eye_rays, glass_splits;
    unsigned long long emitter_hits;   /* eye ray segments that met an area light's front face */
    unsigned long long photons_emitted, photon_segments, photon_hits, photon_hits_no_cell;
    update_stats_t upd;
    unsigned long long radiance_skipped;
    unsigned long long hit_points_saturated; /* stable datapath: w or T stopped at WIDE_MAX */
    double r0, r_safe;
    double hp_coord_max;     /* the largest |coordinate| of a hit point (binary32 resolves about 2^-24 of it) */
    size_t grid_entries;
    size_t grid_entries_final;        /* after the last re-filter against the current radii */
    unsigned long long grid_refilters;
    double peak_bytes_per_hit_point;  /* peak resident memory over hit points */
    size_t hit_point_bytes;           /* bytes of the hit-point arrays per hit point */
    size_t grid_entry_bytes;          /* bytes per grid entry */
    double sec_bvh, sec_eye, sec_grid, sec_trace, sec_update, sec_refilter, sec_radiance, sec_total;
    double sec_cpu;          /* the process's CPU seconds (all threads) since the render began */
    long peak_rss_kb;
    int threads;
    /* What the scene holds (the engine builds only what it needs). */
    unsigned long long scene_spheres, scene_triangles, scene_lights;
    int scene_mirror, scene_glass;
    int max_bounces;         /* the photon paths' cap (scene_t's max_bounces; 0: none) */
    uint64_t image_hash;     /* FNV-1a over the pixels' double bits */
    uint64_t state_hash;     /* FNV-1a over the final hit-point state (r2, count, flux or PREU words;
                              * the photon-map estimator: each hit point's radiance) */
    pm_stats_t pm;           /* the photon-map estimator's figures */
    unsigned long long photons_resumed; /* photons done in the checkpoint the render resumed from */
    int time_limited;        /* the time limit stopped the photon pass early */
    /* Under MPI with more than one rank (docs/scale_out.md): the ranks, the bytes all ranks sent
     * to others, and, of the candidates that screening kept from each rank's own traced blocks,
     * those whose hit point another rank owns (the crossing candidates). */
    int mpi_ranks;
    unsigned long long mpi_bytes_sent, mpi_kept, mpi_kept_foreign;
} render_stats_t;

struct render_result {
    int width, height;
    double *rgb;             /* linear radiance, 3 per pixel, top row first */
    double *emitted;         /* the area lights' radiance the eye paths meet, 3 per pixel, which rgb
                              * includes (radiance_add_emitted); NULL when they meet none or
                              * opt.hide_lights */
    hitpoints_t hp;          /* final hit-point state */
    render_stats_t stats;
};

int render_run(const scene_t *scene, const render_options_t *opt, render_result_t *res,
               char *err, size_t errlen);
/* What both estimators fill in alike (render_result.c): the process's peak resident memory so
 * far (KiB), its CPU seconds so far (every thread's), and the scene-content figures of the
 * statistics. */
long render_peak_rss_kb(void);
double render_cpu_seconds(void);
void render_stats_scene(render_stats_t *st, const scene_t *scene);

/* The same render driven phase by phase by its caller, who may look at each block's operations:
 *   render_open       the session's own set-up (options, threads, memory, image); NULL with err
 *                     on failure
 *   render_eye_pass   BVH, eye pass, initial state, grid, a resume: 0, or -1 with err (res is
 *                     then to be freed by render_result_free). res->hp holds the hit points in
 *                     the photon pass's order from here until render_radiance.
 *   render_hp_address photon-pass index -> hit-point address (the order of res->hp before
 *                     render_eye_pass reordered it and after render_radiance restores it)
 *   render_step       trace and apply the next photon block: 1 (a block done), 0 (no block
 *                     left, or interrupted), -1 with err
 *   render_block_ops  with opt->record_ops: the last block's operations, in photon order
 *   render_refilter_due  with opt->record_ops: the engine does not re-filter its grid itself (it
 *                     would read the radii from its own state); this says that a point of its
 *                     schedule (after blocks 1, 2, 4, ...) has passed and a block is left
 *   render_refilter_from  re-filter the grid against radii the caller supplies: r2_bits[i], the
 *                     binary32 radius squared of hit point i in the photon pass's order (a
 *                     NaN: not known, kept); with the stable datapath preu_stable_screen_r2 of
 *                     its w. 0, or -1 with err
 *   render_radiance   radiance, hashes: 0, or -1 with err (nothing done after a failed phase)
 *   render_close      releases the session; returns as render_run (-1 after a failed phase) */
typedef struct render_session render_session_t;
render_session_t *render_open(const scene_t *scene, const render_options_t *opt, render_result_t *res,
                              char *err, size_t errlen);
int render_eye_pass(render_session_t *s, char *err, size_t errlen);
const uint32_t *render_hp_address(const render_session_t *s);
int render_step(render_session_t *s, char *err, size_t errlen);
const update_ops_t *render_block_ops(const render_session_t *s);
int render_refilter_due(const render_session_t *s);
int render_refilter_from(render_session_t *s, const uint32_t *r2_bits, char *err, size_t errlen);
int render_radiance(render_session_t *s, char *err, size_t errlen);
int render_close(render_session_t *s);
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
