// SPDX-License-Identifier: Apache-2.0
/* pm_search.h: the photon-map searches' shared set-up and their query loops, private to
 * model/pm: pm_estimate runs one of them, --knn-bench all of them on the same trees. */
#ifndef PREE_PM_SEARCH_H
#define PREE_PM_SEARCH_H

#include "cluster.h"
#include "knn_kernel.h"
#include "knn_naive.h"
#include "photon_tree.h"
#include "pm_estimate.h"

/* What the searches read, each built once: nanoflann's tree (the oracle's), the photon tree
 * (the single-pass and the clustered search's), the clusters and the prefilter path. */
typedef struct {
    knn_naive_t *nv;
    photon_tree_t tree;
    clusters_t cl;
    knn_kernel_fn kernel;
    int has_tree, has_clusters;
} pm_searches_t;

/* Build what method m reads (what is built already is kept): its tree timed into *sec_tree,
 * *cpu_tree, the clusters into st's sec_cluster and cpu_cluster; st->kernel the prefilter
 * path. 0, -1 (out of memory) or -2 (the path asked for is not on this processor). */
int pm_search_prepare(pm_searches_t *s, knn_search_t m, const hitpoints_t *h, const photon_map_t *map,
                      const pm_estimate_opts_t *o, pm_stats_t *st, double *sec_tree, double *cpu_tree);
/* Method m's queries and estimates: L and st's counters. 0, or -1 (out of memory). */
int pm_search_run(const pm_searches_t *s, knn_search_t m, const hitpoints_t *h, const photon_map_t *map,
                  const pm_estimate_opts_t *o, double *L, pm_stats_t *st);
void pm_search_release(pm_searches_t *s);

/* Wall and CPU seconds since *t, *c, which restart. */
void pm_lap(double *t, double *c, double *sec, double *cpu);

#endif
