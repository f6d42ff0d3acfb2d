/* update.c: the candidate loop of the photon pass: grid look-up, tests, update. */
#include "update.h"

void update_part(hitpoints_t *h, const grid_t *g, int p, precision_t prec, int skip_radius,
                 const photon_hit_t *hits, size_t n, update_stats_t *st)
{
    update_stats_t s = *st;
    const double rs2 = g->r_safe * g->r_safe;
    for (size_t k = 0; k < n; k++) {
        const photon_hit_t *ph = &hits[k];
        size_t count;
        const uint32_t *cand = grid_lookup(g, p, ph->x, &count);
        s.candidates += count;
        preu_photon_t ph32;
        if (prec == PRECISION_FP32 && count) ph32 = update_photon_fp32(ph);
        for (size_t c = 0; c < count; c++) {
            const uint32_t e = cand[c];
            hp_hot_t *hp = &h->hot[e];
            double vx = hp->px - ph->x.x, vy = hp->py - ph->x.y, vz = hp->pz - ph->x.z;
            double v2 = vx * vx + vy * vy + vz * vz;
            /* Radii only shrink: a candidate beyond the safe initial radius never accepts. */
            if (skip_radius && v2 > rs2) { s.skipped_radius++; continue; }
            if (!(hp->nx * ph->n.x + hp->ny * ph->n.y + hp->nz * ph->n.z > UPDATE_NORMAL_COS)) continue;
            s.normal_passed++;
            if (prec == PRECISION_DOUBLE) {
                if (v2 <= hp->r2) { update_accept_double(h, e, ph->flux); s.accepted++; }
            } else {
                s.accepted += (unsigned long long)preu_update_inline(&h->fp32[e], &ph32);
            }
        }
    }
    *st = s;
}
