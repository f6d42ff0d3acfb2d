// SPDX-License-Identifier: Apache-2.0
/* hitpoints.c: growable storage for hit points, and the arrays each mode's state adds. */
#include <stdlib.h>
#include <string.h>
#include "hitpoints.h"

/* Resize one array to cap elements of size sz (a NULL array stays NULL). 0 or -1. */
static int resize(void **arr, size_t sz, size_t cap)
{
    if (!*arr) return 0;
    void *p = realloc(*arr, (cap ? cap : 1) * sz);
    if (!p) return -1;
    *arr = p;
    return 0;
}

static int reserve(hitpoints_t *h, size_t need)
{
    if (need <= h->cap) return 0;
    size_t cap = h->cap ? h->cap : 256;
    while (cap < need) cap *= 2;
    if (!h->hot) {   /* the first reserve: the eye pass's arrays */
        h->hot = malloc(sizeof *h->hot);
        h->weight = malloc(sizeof *h->weight);
        h->pixel = malloc(sizeof *h->pixel);
        h->object = h->with_object ? malloc(sizeof *h->object) : NULL;
        if (!h->hot || !h->weight || !h->pixel || (h->with_object && !h->object)) return -1;
    }
    if (resize((void **)&h->hot, sizeof *h->hot, cap) || resize((void **)&h->weight, sizeof *h->weight, cap) ||
        resize((void **)&h->pixel, sizeof *h->pixel, cap) || resize((void **)&h->object, sizeof *h->object, cap))
        return -1;
    h->cap = cap;
    return 0;
}

int hitpoints_push(hitpoints_t *h, vec3 pos, vec3 nrm, vec3 weight, int32_t pixel, uint32_t object)
{
    if (reserve(h, h->n + 1)) return -1;
    hp_hot_t hot = {pos.x, pos.y, pos.z, nrm.x, nrm.y, nrm.z};
    h->hot[h->n] = hot;
    h->weight[h->n] = weight;
    h->pixel[h->n] = pixel;
    if (h->object) h->object[h->n] = object;
    h->n++;
    return 0;
}

int hitpoints_append(hitpoints_t *dst, const hitpoints_t *src)
{
    if (src->n == 0) return 0;   /* an empty row: its arrays may be NULL (memcpy's contract) */
    if (reserve(dst, dst->n + src->n)) return -1;
    memcpy(dst->hot + dst->n, src->hot, src->n * sizeof *src->hot);
    memcpy(dst->weight + dst->n, src->weight, src->n * sizeof *src->weight);
    memcpy(dst->pixel + dst->n, src->pixel, src->n * sizeof *src->pixel);
    if (dst->object) memcpy(dst->object + dst->n, src->object, src->n * sizeof *src->object);
    dst->n += src->n;
    return 0;
}

int hitpoints_trim(hitpoints_t *h)
{
    if (resize((void **)&h->hot, sizeof *h->hot, h->n) || resize((void **)&h->weight, sizeof *h->weight, h->n) ||
        resize((void **)&h->pixel, sizeof *h->pixel, h->n) || resize((void **)&h->object, sizeof *h->object, h->n))
        return -1;
    h->cap = h->n;
    return 0;
}

int hitpoints_init_double(hitpoints_t *h, double r0)
{
    const size_t n = h->n ? h->n : 1;
    free(h->r2);
    free(h->acc);
    h->r2 = malloc(n * sizeof *h->r2);
    h->acc = aligned_alloc(sizeof *h->acc, n * sizeof *h->acc);
    if (!h->r2 || !h->acc) return -1;
    for (size_t i = 0; i < h->n; i++) {
        h->r2[i] = r0 * r0;
        h->acc[i] = (hp_acc_t){v3(0, 0, 0), 0, 0};
    }
    return 0;
}

int hitpoints_drop_weight(hitpoints_t *h)
{
    uint8_t *dark = malloc(h->n ? h->n : 1);
    if (!dark) return -1;
    for (size_t i = 0; i < h->n; i++) dark[i] = hitpoints_zero_weight(h, i);
    free(h->weight);
    h->weight = NULL;
    free(h->dark);
    h->dark = dark;
    return 0;
}

size_t hitpoints_bytes_each(const hitpoints_t *h)
{
    return sizeof *h->hot + sizeof *h->pixel + (h->weight ? sizeof *h->weight : 0) + (h->dark ? sizeof *h->dark : 0) +
           (h->object ? sizeof *h->object : 0) + (h->acc ? sizeof *h->acc : 0) + (h->r2 ? sizeof *h->r2 : 0) + (h->r2_f32 ? sizeof *h->r2_f32 : 0) +
           (h->fp32 ? sizeof *h->fp32 : 0) + (h->stable ? sizeof *h->stable : 0);
}

void hitpoints_free(hitpoints_t *h)
{
    free(h->hot);
    free(h->weight);
    free(h->dark);
    free(h->acc);
    free(h->pixel);
    free(h->object);
    free(h->fp32);
    free(h->stable);
    free(h->r2);
    free(h->r2_f32);
    memset(h, 0, sizeof *h);
}
