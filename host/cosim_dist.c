// SPDX-License-Identifier: Apache-2.0
/* cosim_dist.c: the gather of cosim_dist.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cosim_dist.h"
#include "cosim_shadow.h"
#include "radiance.h"
#include "render_dist.h"

int cosim_dist_gather(cosim_drv_t *drv, const cosim_part_t *p, const render_result_t *res, int preu, int pipefast,
                      size_t npix, int fail, hp_read_t *got, uint32_t *Lr, uint32_t *Lm, cosim_rank_t *mine,
                      cosim_rank_t *figs)
{
    const size_t lo = p->lo[p->rank], words = npix * 3;
    if (!fail)
        for (size_t a = 0; a < p->n_local; a++) cosim_drv_read_hp(drv, (uint32_t)a, &got[lo + a].w, &got[lo + a].px);
    if (render_dist_max(fail)) return 1;
    render_dist_gather_ranges(got, sizeof *got, p->lo);
    uint32_t *part = malloc(2 * words * sizeof *part);   /* the RTL's pixel words, then the model's */
    if (!part) { fprintf(stderr, "pree cosim: out of memory\n"); fail = 1; }
    else if (cosim_drv_radiance(drv, (uint32_t)p->n_local, preu_n_emitted(res->stats.photons_emitted), npix, part)) {
        fprintf(stderr, "pree cosim: rank %d: radiance pass: %s\n", p->rank, cosim_drv_error(drv));
        fail = 1;
    } else if (cosim_model_radiance(res, p->model + lo, p->n_local, preu, pipefast, npix, part + words)) {
        fprintf(stderr, "pree cosim: out of memory\n");
        fail = 1;
    }
    if (!fail) {
        uint64_t cnt[COSIM_NCNT];
        cosim_drv_counters(drv, cnt);
        mine->radiance_cycles = cnt[CNT_CYC_RAD];
        mine->radiance_ops = 0;
        for (int l = 0; l < preu; l++) mine->radiance_ops += cnt[CNT_OPS0 + l];
        mine->radiance_ops -= mine->ops;
        mine->image_words_differing = 0;
        for (size_t j = 0; j < words; j++) mine->image_words_differing += part[j] != part[words + j];
    }
    void *recv = NULL, *rf = NULL;
    size_t cap = 0, fcap = 0, *counts = malloc((size_t)p->nranks * sizeof *counts);
    if (!counts) fail = 1;
    if (render_dist_max(fail) || render_dist_allgather(part, 2 * words * sizeof *part, &recv, &cap, counts) ||
        render_dist_allgather(mine, sizeof *mine, &rf, &fcap, counts)) {
        free(part);
        free(recv);
        free(rf);
        free(counts);
        return 1;
    }
    memcpy(figs, rf, (size_t)p->nranks * sizeof *figs);
    free(rf);
    const uint32_t *all = recv;
    for (int r = 0; r < p->nranks; r++) {   /* the board's image, the RTL's and the model's */
        const uint32_t *q = all + (size_t)r * 2 * words;
        radiance_board_add(Lr, q, words, r == 0);
        radiance_board_add(Lm, q + words, words, r == 0);
    }
    free(part);
    free(recv);
    free(counts);
    return 0;
}

