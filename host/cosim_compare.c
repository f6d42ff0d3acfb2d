// SPDX-License-Identifier: Apache-2.0
/* cosim_compare.c: the comparisons of cosim_compare.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cosim_compare.h"
#include "cosim_shadow.h"
#include "pree_env.h"
#include "radiance.h"

void cosim_model_words(const hitpoints_t *hp, size_t i, preu_hpw_t *w)
{
    if (hp->stable) preu_hpw_from_stable(w, &hp->stable[i]);
    else preu_hpw_from_paper(w, &hp->fp32[i]);
}


static int hp_words_differ(const preu_hpw_t *a, uint32_t pa, const preu_hpw_t *b, uint32_t pb, int datapath)
{
    int d = pa != pb;
    for (int k = 0; k < 3; k++) d += (a->pos[k] != b->pos[k]) + (a->f[k] != b->f[k]);
    for (int k = 0; k < preu_state_words(datapath); k++) d += a->st[k] != b->st[k];
    return d;
}

unsigned long long cosim_compare_hit_points(const hp_read_t *got, const cosim_part_t *part, const hitpoints_t *hp,
                                            int dp, unsigned long long *points, size_t *first)
{
    const uint32_t *model = part ? part->model : NULL;
    const char *env = pree_env(PREE_ENV_TEST_CORRUPT_HP);
    const size_t corrupt = env ? (size_t)strtoull(env, NULL, 10) : SIZE_MAX;
    unsigned long long words = 0;
    *points = 0;
    *first = SIZE_MAX;
    for (size_t i = 0; i < hp->n; i++) {
        const size_t j = model ? model[i] : i;
        preu_hpw_t m;
        cosim_model_words(hp, j, &m);
        if (j == corrupt) m.st[0] ^= 1;
        int dw = hp_words_differ(&got[i].w, got[i].px, &m, (uint32_t)hp->pixel[j], dp);
        if (!dw) continue;
        if (*points < 5) {
            fprintf(stderr, "pree cosim: hit point %zu differs", j);
            for (int r = 0; part && part->nranks > 1 && r < part->nranks; r++)
                if (i >= part->lo[r] && i < part->lo[r + 1])
                    fprintf(stderr, " (rank %d's PREE, address %zu)", r, i - part->lo[r]);
            fprintf(stderr, ": state words RTL/model");
            for (int k = 0; k < preu_state_words(dp); k++) fprintf(stderr, " %08x/%08x", got[i].w.st[k], m.st[k]);
            fputc('\n', stderr);
        }
        if (*first == SIZE_MAX) *first = i;
        words += (unsigned long long)dw;
        ++*points;
    }
    return words;
}

unsigned long long cosim_image_words_differ(const uint32_t *Lr, const uint32_t *Lm, size_t npix, int print)
{
    unsigned long long diff = 0;
    for (size_t j = 0; j < npix * 3; j++) {
        if (Lr[j] != Lm[j] && diff < 5 && print)
            fprintf(stderr, "pree cosim: pixel %zu channel %zu differs: RTL %08x model %08x\n", j / 3, j % 3, Lr[j], Lm[j]);
        diff += Lr[j] != Lm[j];
    }
    return diff;
}

int cosim_model_radiance(const render_result_t *res, const uint32_t *order, size_t n, int preu, int pipefast,
                         size_t npix, uint32_t *L)
{
    const radiance_pree_t pree = {.preu = preu, .stages = cosim_radiance_depth(pipefast), .at = order,
                                  .n = order ? n : res->hp.n};
    unsigned long long skipped;
    memset(L, 0, npix * 3 * sizeof *L);
    return radiance_fp32_words(&res->hp, &pree, res->stats.photons_emitted, 0, L, &skipped);
}

long long cosim_compare_image(cosim_drv_t *drv, const render_result_t *res, const uint32_t *order, int preu,
                              int pipefast, size_t npix, uint32_t *Lr, uint32_t *Lm)
{
    const uint32_t ne = preu_n_emitted(res->stats.photons_emitted);
    if (cosim_drv_radiance(drv, (uint32_t)res->hp.n, ne, npix, Lr)) {
        fprintf(stderr, "pree cosim: radiance pass: %s\n", cosim_drv_error(drv));
        return -1;
    }
    if (cosim_model_radiance(res, order, res->hp.n, preu, pipefast, npix, Lm)) {
        fprintf(stderr, "pree cosim: out of memory\n");
        return -1;
    }
    return (long long)cosim_image_words_differ(Lr, Lm, npix, 1);
}

