// SPDX-License-Identifier: Apache-2.0
/* cosim_refilter.c: the host's re-filter with radii read back from the PREE (cosim_refilter.h). */
#include <stdio.h>
#include <stdlib.h>
#include "cosim_compare.h"
#include "cosim_refilter.h"

#define UNKNOWN_R2 0x7FC00000u   /* a NaN: the engine keeps such a hit point's entries */

int cosim_refilter(cosim_drv_t *drv, render_session_t *rs, const hitpoints_t *hp, const cosim_part_t *part, int dp,
                   int model_only, cosim_refilter_stats_t *st, char *err, size_t errlen)
{
    if (!render_refilter_due(rs)) return 0;
    if (cosim_drv_barrier(drv)) {
        snprintf(err, errlen, "%s", cosim_drv_error(drv));
        return -1;
    }
    uint32_t *r2 = malloc((hp->n ? hp->n : 1) * sizeof *r2);
    if (!r2) { snprintf(err, errlen, "out of memory"); return -1; }
    for (size_t j = 0; j < hp->n; j++) {
        preu_hpw_t w;
        uint32_t pixel;
        if (part->addr[j] == OTHER_RANK) { r2[j] = UNKNOWN_R2; continue; }
        if (model_only) cosim_model_words(hp, j, &w);
        else cosim_drv_read_hp(drv, part->addr[j], &w, &pixel);
        r2[j] = preu_hpw_screen_r2(&w, dp);
        st->hit_points_read++;
    }
    const int rc = render_refilter_from(rs, r2, err, errlen);
    free(r2);
    st->refilters += rc == 0;
    return rc;
}
