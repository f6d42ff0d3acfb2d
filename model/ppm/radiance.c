// SPDX-License-Identifier: Apache-2.0
/* radiance.c: pixel radiance from the hit points' flux and radius. */
#include <stdlib.h>
#include <string.h>
#include "radiance.h"
#include "adiso_order.h"
#include "fp32_ops.h"
#include "render_dist.h"

/* fp32: the PREE's radiance pass, its addresses in ADISO-REC issue order (model/pree/adiso_order.h). */
int radiance_fp32_words(const hitpoints_t *h, const radiance_pree_t *pree, uint64_t emitted, int skip_zero,
                        uint32_t *L, unsigned long long *skipped)
{
    unsigned long long sk = 0;
    const size_t n = pree->n;
    if (pree->stages < 1 || n > h->n) return -1;
    uint32_t *order = malloc((n ? n : 1) * sizeof *order);
    if (!order) return -1;
    if (adiso_order((uint32_t)n, pree->preu, pree->stages, order)) { free(order); return -1; }
    const uint32_t ne = preu_n_emitted(emitted);
    for (size_t k = 0; k < n; k++) {
        const uint32_t i = pree->at ? pree->at[order[k]] : order[k];
        if (skip_zero && hitpoints_zero_weight(h, i)) { sk++; continue; }
        if (h->stable) preu_stable_radiance(L + 3 * (size_t)h->pixel[i], &h->stable[i], ne);
        else preu_radiance(L + 3 * (size_t)h->pixel[i], &h->fp32[i], ne);
    }
    free(order);
    *skipped = sk;
    return 0;
}

void radiance_board_add(uint32_t *L, const uint32_t *part, size_t words, int first)
{
    for (size_t j = 0; j < words; j++) L[j] = first ? part[j] : fp32_add(L[j], part[j]);
}

/* fp32: the pixel words of a PREE or a board of them (radiance.h) into L (zeroed, `words` long). */
static int board_words(const hitpoints_t *h, const radiance_pree_t *pree, uint64_t emitted, int skip_zero,
                       size_t words, uint32_t *L, unsigned long long *skipped)
{
    if (pree->prees <= 1) return radiance_fp32_words(h, pree, emitted, skip_zero, L, skipped);
    uint32_t *part = pree->at ? malloc((words ? words : 1) * sizeof *part) : NULL;
    if (!part) return -1;
    int rc = 0;
    *skipped = 0;
    for (int r = 0; r < pree->prees && rc == 0; r++) {
        const size_t lo = render_dist_lo(pree->n, r, pree->prees), hi = render_dist_lo(pree->n, r + 1, pree->prees);
        radiance_pree_t one = *pree;
        one.at = pree->at + lo;
        one.n = hi - lo;
        unsigned long long sk = 0;
        memset(part, 0, words * sizeof *part);
        rc = radiance_fp32_words(h, &one, emitted, skip_zero, part, &sk);
        *skipped += sk;
        radiance_board_add(L, part, words, r == 0);
    }
    free(part);
    return rc;
}

void radiance_add_emitted(double *rgb, const double *emitted, size_t num_pixels, precision_t prec)
{
    if (!emitted) return;
    for (size_t j = 0; j < num_pixels * 3; j++) {
        if (emitted[j] == 0) continue;
        rgb[j] = prec == PRECISION_FP32
               ? (double)fp32_from_bits(fp32_add(fp32_to_bits((float)rgb[j]), preu_f32(emitted[j])))
               : rgb[j] + emitted[j];
    }
}

int radiance_evaluate_preu(const hitpoints_t *h, precision_t prec, const radiance_pree_t *pree, uint64_t emitted,
                           int skip_zero, double *rgb, size_t num_pixels, unsigned long long *skipped)
{
    unsigned long long sk = 0;
    memset(rgb, 0, num_pixels * 3 * sizeof *rgb);
    if (prec == PRECISION_DOUBLE) {
        const double batches = (double)(emitted / 1000);
        for (size_t i = h->n; i-- > 0;) {
            if (skip_zero && hitpoints_zero_weight(h, i)) { sk++; continue; }
            double *px = rgb + 3 * (size_t)h->pixel[i];
            double k = 1.0 / (((PREE_PI * h->r2[i]) * batches) * 1000.0);
            px[0] = px[0] + h->acc[i].flux.x * k;
            px[1] = px[1] + h->acc[i].flux.y * k;
            px[2] = px[2] + h->acc[i].flux.z * k;
        }
    } else {
        uint32_t *L = calloc(num_pixels * 3, sizeof *L);   /* +0.0f */
        if (!L) return -1;
        if (board_words(h, pree, emitted, skip_zero, num_pixels * 3, L, &sk)) { free(L); return -1; }
        for (size_t j = 0; j < num_pixels * 3; j++) rgb[j] = (double)fp32_from_bits(L[j]);
        free(L);
    }
    *skipped = sk;
    return 0;
}
