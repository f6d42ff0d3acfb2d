/* update_batch.h: a block's update in two phases, bucket-major screening then photon-order
 * apply (see update_batch.c); the same result as update_part's photon-major scan. */
#ifndef PREE_UPDATE_BATCH_H
#define PREE_UPDATE_BATCH_H

#include "update.h"

/* A hit's position and normal, copied in bucket order so that screening reads in sequence. */
typedef struct {
    double x, y, z, nx, ny, nz;
    uint32_t hit, bucket;
} batch_hit_t;

/* The block's hits in photon order, and their keys grouped by bucket (shared by all parts). */
typedef struct {
    const photon_hit_t **hit;   /* hit index -> hit */
    uint64_t *key, *tmp;        /* bucket << 32 | hit index, sorted by bucket (stable) */
    batch_hit_t *sorted;        /* the keyed hits in key order */
    size_t n, n_keyed, hit_cap, key_cap, tmp_cap, sorted_cap;
} update_batch_t;

/* One part's working memory, reused from block to block. */
typedef struct {
    void *kept, *sorted;
    uint32_t *start;
    size_t n_kept, kept_cap, sorted_cap, start_cap;
} update_scratch_t;

/* Collect chunks[0..nchunks) (in photon order) and group them by bucket. 0 or -1 (memory). */
int update_batch_prepare(update_batch_t *b, const photon_hits_t *chunks, unsigned nchunks, size_t num_buckets);
void update_batch_free(update_batch_t *b);
void update_batch_scratch_free(update_scratch_t *s);

/* Apply the block to the hit points of part p. 0 or -1 (memory). */
int update_batch_part(hitpoints_t *h, const grid_t *g, int p, precision_t prec, int skip_radius,
                      const update_batch_t *b, update_stats_t *st, update_scratch_t *s);

#endif
