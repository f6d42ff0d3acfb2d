// SPDX-License-Identifier: Apache-2.0
/* cosim_layout.c: a rank's hit-point addresses in its PREE (cosim_layout.h). */
#include <stdlib.h>
#include "cosim_layout.h"
#include "render_dist.h"

int cosim_part_open(cosim_part_t *p, size_t n, const uint32_t *perm)
{
    p->lo = malloc((size_t)(p->nranks + 1) * sizeof *p->lo);
    p->addr = malloc((n ? n : 1) * sizeof *p->addr);
    p->model = malloc((n ? n : 1) * sizeof *p->model);
    if (!p->lo || !p->addr || !p->model) return -1;
    for (int r = 0; r <= p->nranks; r++) p->lo[r] = render_dist_lo(n, r, p->nranks);
    const size_t lo = p->lo[p->rank], hi = p->lo[p->rank + 1];
    for (size_t i = 0; i < n; i++) {
        p->model[i] = perm[i];
        p->addr[i] = !p->spatial ? perm[i] : i >= lo && i < hi ? (uint32_t)(i - lo) : OTHER_RANK;
    }
    p->n_local = hi - lo;
    return 0;
}

void cosim_part_free(cosim_part_t *p)
{
    free(p->lo);
    free(p->addr);
    free(p->model);
}

