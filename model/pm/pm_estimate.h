/* pm_estimate.h: each hit point's radiance from its k nearest photons (see pm_render.h),
 * through the clustered search (knn_clustered.h) or the naive oracle (knn_naive.h). */
#ifndef PREE_PM_ESTIMATE_H
#define PREE_PM_ESTIMATE_H

#include "hitpoints.h"
#include "photon_map.h"
#include "pm_stats.h"
#include "render.h"

typedef struct {
    size_t k;
    double r0;              /* maximum radius */
    knn_search_t search;
    size_t bundle;          /* clustered: shading points a bundle */
    int threads;
} pm_estimate_opts_t;

/* CPU seconds of the whole process so far (every thread). */
double pm_cpu_now(void);

/* L[3 i .. 3 i + 2]: hit point i's radiance. 0, or -1 with err (out of memory). */
int pm_estimate(const hitpoints_t *h, const photon_map_t *map, const pm_estimate_opts_t *o, double *L,
                pm_stats_t *st, char *err, size_t errlen);

#endif
