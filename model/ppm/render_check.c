// SPDX-License-Identifier: Apache-2.0
/* render_check.c: the render's result checks: the image and state hashes, and the fp32
 * mode's range checks at the PREE boundary and on the final image. */
#include <math.h>
#include <stdio.h>
#include "fnv1a.h"
#include "render_check.h"

/* Hashes of the image and of the final hit-point state, for determinism checks. */
void render_hash_results(render_result_t *res, precision_t prec)
{
    const uint64_t basis = FNV1A_BASIS;
    const hitpoints_t *h = &res->hp;
    res->stats.image_hash = fnv1a(basis, res->rgb, (size_t)res->width * res->height * 3 * sizeof *res->rgb);
    uint64_t s = basis;
    if (prec == PRECISION_FP32 && h->stable) s = fnv1a(s, h->stable, h->n * sizeof *h->stable);
    else if (prec == PRECISION_FP32) s = fnv1a(s, h->fp32, h->n * sizeof *h->fp32);
    else {
        s = fnv1a(s, h->r2, h->n * sizeof *h->r2);
        /* The bytes of the flux array, then of the counts, as when each was an array of its own. */
        for (size_t i = 0; i < h->n; i++) s = fnv1a(s, &h->acc[i].flux, sizeof h->acc[i].flux);
        for (size_t i = 0; i < h->n; i++) s = fnv1a(s, &h->acc[i].count, sizeof h->acc[i].count);
    }
    res->stats.state_hash = s;
}

/* fp32 mode: every photon hit crosses into the PREE as binary32 (update_photon_fp32); a flux or
 * position beyond binary32's range there is an error naming the photon. */
int render_fp32_check_hits(const photon_hits_t *chunk, unsigned nchunks, char *err, size_t errlen)
{
    for (unsigned c = 0; c < nchunks; c++)
        for (size_t i = 0; i < chunk[c].n; i++) {
            const photon_hit_t *h = &chunk[c].hits[i];
            const double v[6] = {h->flux.x, h->flux.y, h->flux.z, h->x.x, h->x.y, h->x.z};
            for (int k = 0; k < 6; k++)
                if (!isfinite((float)v[k])) {
                    snprintf(err, errlen, "fp32: photon %llu's %s (%g, %g, %g) is beyond binary32's range at the "
                             "PREE boundary: scale the light or the scene down, or use --precision double",
                             (unsigned long long)h->photon, k < 3 ? "flux" : "hit position",
                             v[k < 3 ? 0 : 3], v[k < 3 ? 1 : 4], v[k < 3 ? 2 : 5]);
                    return -1;
                }
        }
    return 0;
}

/* fp32 mode: count the stable datapath's saturated hit points, and refuse an image with an
 * infinite or NaN pixel (docs/numerics.md: what overflows where). */
int render_fp32_result_check(render_result_t *res, char *err, size_t errlen)
{
    const hitpoints_t *h = &res->hp;
    unsigned long long sat = 0;
    for (size_t i = 0; h->stable && i < h->n; i++) {
        const preu_shp_t *s = &h->stable[i];
        sat += s->w == WIDE_MAX || s->T[0] == WIDE_MAX || s->T[1] == WIDE_MAX || s->T[2] == WIDE_MAX;
    }
    res->stats.hit_points_saturated = sat;
    const size_t n = (size_t)res->width * (size_t)res->height * 3;
    size_t bad = 0, first = 0;
    for (size_t j = 0; j < n; j++)
        if (!isfinite(res->rgb[j]) && !bad++) first = j / 3;
    if (!bad) return 0;
    snprintf(err, errlen, "fp32: %zu pixel values are infinite or NaN (first at pixel %zu, %zu): a value left "
             "binary32's range (light flux above 3.4e38, or the %s datapath's radius collapsed); "
             "try --precision double%s", bad, first % (size_t)res->width, first / (size_t)res->width,
             h->stable ? "stable" : "paper", h->stable ? "" : " or --datapath stable");
    return -1;
}
