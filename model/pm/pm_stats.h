/* pm_stats.h: the photon-map estimator's figures in the render statistics ("pm" in the JSON). */
#ifndef PREE_PM_STATS_H
#define PREE_PM_STATS_H

typedef struct {
    unsigned long long photons_stored;   /* diffuse photon hits in the map */
    unsigned long long k;                /* neighbours asked for */
    double max_radius;                   /* r0 */
    unsigned long long clusters;         /* clustered search: clusters of <= 16 shading points */
    unsigned long long clusters_sparse;  /* ... whose scope held fewer than K_c photons (hybrid) */
    unsigned long long clusters_widened; /* ... searched again with the full scope (guess too small) */
    unsigned long long scope_photons;    /* photons in the clusters' scopes, summed */
    unsigned long long distance_tests;   /* photon-to-shading-point distances computed */
    unsigned long long neighbours;       /* neighbours found, summed over hit points */
    unsigned long long short_of_k;       /* hit points with fewer than k neighbours */
    double coherent_fraction;            /* paper 002's coherence test */
    double sec_map, sec_cluster, sec_search;   /* wall seconds */
    double cpu_map, cpu_cluster, cpu_search;   /* CPU seconds of the process (all threads): the
                                                * figures to compare on a shared machine */
} pm_stats_t;

#endif
