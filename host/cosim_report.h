// SPDX-License-Identifier: Apache-2.0
/* cosim_report.h: the co-simulation's figures (`pree cosim --stats FILE.json`): what was run,
 * words that differ between RTL and model, cycles, utilization, stall causes and speed. The
 * caller fills the inputs; cosim_report_figures derives the rest once for the report and
 * for the summary line. */
#ifndef PREE_COSIM_REPORT_H
#define PREE_COSIM_REPORT_H

#include <stddef.h>
#include <stdint.h>
#include "compare.h"
#include "cosim_refilter.h"
#include "cosim_rtl.h"
#include "cosim_sched.h"

/* One rank's PREE under mpirun (pree cosim with more than one rank); photons_other: photons
 * with candidates, none of them on this PREE (not sent to it). */
typedef struct {
    uint64_t hit_points, photons_sent, photons_other, ops_sent, ops, cycles, radiance_ops, radiance_cycles, image_words_differing;
    double utilization;
} cosim_rank_t;

typedef struct {
    /* What was run. */
    const char *scene;
    int width, height, datapath, preu, axi, reorder, window;
    int pipe_fast, update_window;   /* the RTL's PipeFast and its update hazard window */
    int pixel_layout;               /* hit-point addresses in the eye pass's order (--layout pixel) */
    int ppc;                        /* the RTL's PhotonsPerCycle */
    int model_only;                 /* 1: the counters are the scheduler's cycle model's, no
                                       RTL ran and nothing was compared (pass is false) */
    uint64_t photons_emitted;
    double alpha, gap;
    size_t hit_points;
    int have_sched;                 /* 1: sched holds the host scheduler's cycle model */
    cosim_sched_stats_t sched;
    /* What came out. */
    unsigned long long photons_sent, photons_empty;
    unsigned long long hp_diff, hp_diff_points, img_diff;
    uint64_t ops_sent;              /* update operations the driver sent */
    cosim_refilter_stats_t refilter; /* the host's re-filters with radii read back */
    int have_metrics;               /* 1: m holds the RTL image against the double render */
    pree_metrics_t m;
    uint64_t cnt_upd[COSIM_NCNT];   /* the RTL's counters after the update pass */
    uint64_t cnt_all[COSIM_NCNT];   /* ... and after the radiance pass */
    double sec_engine, sec_update_rtl, cpu_update_rtl, sec_rad_rtl, cpu_process;
    /* Derived by cosim_report_figures. */
    uint64_t ops_upd, ops_rad, cyc_upd, cyc_rad;
    double ops_per_cycle, util_upd, util_rad, sim_ops_per_cpu_s, sim_cycles_per_cpu_s;
    int pass;                       /* 0 differing words, and every operation counted */
    /* Under mpirun with mpi_ranks > 1 (host/cosim_main.c): the PREEs of the ranks, rank r's at
     * ranks[r]; the figures above are rank 0's PREE's but for hit_points, the comparison and
     * pass, which are the combined memory's and image's. Derived: the load imbalance (max / mean
     * of the ranks' update-pass cycles) and the utilization of the PREEs over the longest. */
    int mpi_ranks;
    const cosim_rank_t *ranks;
    unsigned long long img_diff_one_pree;   /* the combined image against one PREE's radiance order: */
    unsigned long long img_max_ulp_one_pree;   /* its words that differ, and by how many ulps at most */
    double imbalance, util_all;
} cosim_report_t;

void cosim_report_figures(cosim_report_t *r);
/* Write the report to path (JSON); 0, or -1 with a one-line message in err. */
int cosim_report_write(const char *path, const cosim_report_t *r, char *err, size_t errlen);

#endif
