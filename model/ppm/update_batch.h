// SPDX-License-Identifier: Apache-2.0
/* update_batch.h: a block's update in two phases, bucket-major screening then photon-order
 * apply (see update_batch.c); the same result as update_part's photon-major scan. */
#ifndef PREE_UPDATE_BATCH_H
#define PREE_UPDATE_BATCH_H

#include "update.h"
#include "update_prefilter.h"

/* A hit's position and normal, copied in bucket order so that screening reads in sequence. */
typedef struct {
    double x, y, z, nx, ny, nz;
    uint32_t hit, bucket;
} batch_hit_t;

/* The block's hits in photon order, and their keys grouped by bucket (shared by all threads). */
typedef struct {
    const photon_hit_t **hit;   /* hit index -> hit */
    uint64_t *key, *tmp;        /* bucket << 32 | hit index, sorted by bucket (stable) */
    batch_hit_t *sorted;        /* the keyed hits in key order */
    uint32_t *group;            /* group g (one bucket) is sorted[group[g] .. group[g+1]) */
    uint32_t *hist;             /* the radix sort's per-thread digit counts */
    size_t n, n_keyed, n_groups, hit_cap, key_cap, tmp_cap, sorted_cap, group_cap, hist_cap;
    const uint16_t *owner;      /* set by the caller: owning part of each hit point (NULL: all 0) */
    const uint32_t *owner_end;  /* or (not NULL) as ranges: part p owns [owner_end[p-1], owner_end[p]) */
    int parts;                  /* with owner_end: the parts */
    const update_prefilter_t *prefilter;  /* set by the caller: the binary32 prefilter (NULL or none
                                           * built: the exact tests alone) */
    int avx2;                   /* screen in AVX2 lanes */
} update_batch_t;

/* Bytes a batch holds per hit besides the hit itself (its pointer, its key and the sort's
 * scratch key, its sorted copy), and per kept candidate (its list entry and its copy grouped by
 * hit): what a batch of more photons costs (render_step.c). */
#define UPDATE_BATCH_HIT_BYTES (sizeof(const photon_hit_t *) + 2 * sizeof(uint64_t) + sizeof(batch_hit_t))
size_t update_batch_kept_bytes(void);

/* A part's kept candidates from one screening thread. */
typedef struct { void *v; size_t n, cap; } kept_list_t;

/* The prefilter's lists of one bucket group (update_batch.c): hit k of the group keeps the
 * entries hp[at[k] .. at[k + 1]) of its bucket's count; with direct, each hit is prefiltered
 * into hp when screened (a group too large to hold every list). */
typedef struct {
    uint32_t *hp, *at;
    size_t hp_cap, at_cap, count;
    int direct;
} screen_stage_t;

/* One thread's working memory, reused from block to block: what it kept while screening (a list
 * per owning part), and, as the applier of part p, that part's candidates grouped by hit. */
typedef struct {
    kept_list_t *list;
    int num_lists;
    void *sorted;
    uint32_t *start;
    screen_stage_t stage[2];    /* the prefilter's lists of the group screened and of the next */
    size_t n_sorted, sorted_cap, start_cap;
} update_scratch_t;

/* Collect chunks[0..nchunks) (in photon order, nchunks <= UPDATE_BATCH_MAX_CHUNKS) and group
 * them by bucket. 0 or -1 (memory). */
#define UPDATE_BATCH_MAX_CHUNKS 256
int update_batch_prepare(update_batch_t *b, const photon_hits_t *chunks, unsigned nchunks, size_t num_buckets);
void update_batch_free(update_batch_t *b);

/* The candidates kept by the last screening, over the nthreads threads' scratch all[]. */
size_t update_batch_kept(const update_scratch_t *all, int nthreads);

/* Empty a thread's kept lists, one per part. 0 or -1 (memory). */
int update_batch_scratch_reset(update_scratch_t *s, int num_parts);
void update_batch_scratch_free(update_scratch_t *s);

/* Phase 1 for bucket groups [first, last) (any thread; g has one part holding every hit point):
 * counts into st, kept candidates into s's lists. 0 or -1 (memory). */
int update_batch_screen(const hitpoints_t *h, const grid_t *g, precision_t prec, int skip_radius,
                        const update_batch_t *b, size_t first, size_t last, update_stats_t *st, update_scratch_t *s);

/* Phase 2 for part p, after every group is screened: the candidates that all nthreads threads
 * kept for part p (all[0..nthreads)), in photon order; all[p] is p's working memory. */
int update_batch_apply(hitpoints_t *h, precision_t prec, const update_batch_t *b, int p,
                       update_scratch_t *all, int nthreads, update_stats_t *st);

/* For the distributed render (render_round.c): the candidates that all nthreads threads kept in
 * list q (all[0..nthreads)), grouped by hit in out (as the apply groups a part's); the i-th of
 * them; and a candidate put in list q of s directly (received from another rank). */
int update_batch_gather(update_scratch_t *out, update_scratch_t *all, int nthreads, int q, size_t n_hits);
void update_batch_sorted_at(const update_scratch_t *s, size_t i, uint32_t *hit, uint32_t *hp, double *v2);
int update_batch_keep_in(update_scratch_t *s, int q, uint32_t hit, uint32_t hp, double v2);

#endif
