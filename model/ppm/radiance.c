/* radiance.c: pixel radiance from the hit points' flux and radius. */
#include <stdlib.h>
#include <string.h>
#include "radiance.h"
#include "adiso_order.h"

/* fp32: the PREE's radiance pass, hit points in ADISO-REC issue order (model/pree/adiso_order.h). */
int radiance_fp32_words(const hitpoints_t *h, uint64_t emitted, int skip_zero, int preu, int stages,
                        uint32_t *L, unsigned long long *skipped)
{
    unsigned long long sk = 0;
    if (stages < 1) return -1;
    uint32_t *order = malloc((h->n ? h->n : 1) * sizeof *order);
    if (!order) return -1;
    if (adiso_order((uint32_t)h->n, preu, stages, order)) { free(order); return -1; }
    const uint32_t ne = preu_n_emitted(emitted);
    for (size_t k = 0; k < h->n; k++) {
        const uint32_t i = order[k];
        if (skip_zero && hitpoints_zero_weight(h, i)) { sk++; continue; }
        if (h->stable) preu_stable_radiance(L + 3 * (size_t)h->pixel[i], &h->stable[i], ne);
        else preu_radiance(L + 3 * (size_t)h->pixel[i], &h->fp32[i], ne);
    }
    free(order);
    *skipped = sk;
    return 0;
}

int radiance_evaluate_preu(const hitpoints_t *h, precision_t prec, uint64_t emitted, int skip_zero,
                           int preu, double *rgb, size_t num_pixels, unsigned long long *skipped)
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
        if (radiance_fp32_words(h, emitted, skip_zero, preu, RADIANCE_PREU_STAGES, L, &sk)) { free(L); return -1; }
        for (size_t j = 0; j < num_pixels * 3; j++) rgb[j] = (double)fp32_from_bits(L[j]);
        free(L);
    }
    *skipped = sk;
    return 0;
}
