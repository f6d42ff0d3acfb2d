/* hitpoints.c: growable storage for hit points. */
#include <stdlib.h>
#include <string.h>
#include "hitpoints.h"

static int reserve(hitpoints_t *h, size_t need)
{
    if (need <= h->cap) return 0;
    size_t cap = h->cap ? h->cap : 256;
    while (cap < need) cap *= 2;
    hp_hot_t *hot = realloc(h->hot, cap * sizeof *hot);
    if (hot) h->hot = hot;
    vec3 *w = realloc(h->weight, cap * sizeof *w);
    if (w) h->weight = w;
    vec3 *f = realloc(h->flux, cap * sizeof *f);
    if (f) h->flux = f;
    int32_t *p = realloc(h->pixel, cap * sizeof *p);
    if (p) h->pixel = p;
    double *r2 = realloc(h->r2, cap * sizeof *r2);
    if (r2) h->r2 = r2;
    if (!hot || !w || !f || !p || !r2) return -1;
    h->cap = cap;
    return 0;
}

int hitpoints_push(hitpoints_t *h, vec3 pos, vec3 nrm, vec3 weight, int32_t pixel, uint32_t object)
{
    if (reserve(h, h->n + 1)) return -1;
    hp_hot_t hot = {pos.x, pos.y, pos.z, nrm.x, nrm.y, nrm.z, 0, object};
    h->r2[h->n] = 0.0;
    h->hot[h->n] = hot;
    h->weight[h->n] = weight;
    h->flux[h->n] = v3(0, 0, 0);
    h->pixel[h->n] = pixel;
    h->n++;
    return 0;
}

int hitpoints_append(hitpoints_t *dst, const hitpoints_t *src)
{
    if (src->n == 0) return 0;   /* an empty row: its arrays may be NULL (memcpy's contract) */
    if (reserve(dst, dst->n + src->n)) return -1;
    memcpy(dst->hot + dst->n, src->hot, src->n * sizeof *src->hot);
    memcpy(dst->weight + dst->n, src->weight, src->n * sizeof *src->weight);
    memcpy(dst->flux + dst->n, src->flux, src->n * sizeof *src->flux);
    memcpy(dst->pixel + dst->n, src->pixel, src->n * sizeof *src->pixel);
    memcpy(dst->r2 + dst->n, src->r2, src->n * sizeof *src->r2);
    dst->n += src->n;
    return 0;
}

size_t hitpoints_bytes_each(const hitpoints_t *h)
{
    return sizeof *h->hot + sizeof *h->weight + sizeof *h->flux + sizeof *h->pixel + sizeof *h->r2 +
           (h->r2_f32 ? sizeof *h->r2_f32 : 0) + (h->fp32 ? sizeof *h->fp32 : 0) + (h->stable ? sizeof *h->stable : 0);
}

void hitpoints_free(hitpoints_t *h)
{
    free(h->hot);
    free(h->weight);
    free(h->flux);
    free(h->pixel);
    free(h->fp32);
    free(h->stable);
    free(h->r2);
    free(h->r2_f32);
    memset(h, 0, sizeof *h);
}
