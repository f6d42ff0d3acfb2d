// SPDX-License-Identifier: Apache-2.0
/* cosim_sched.h: the co-simulation host's photon scheduler. It holds a window of pending photons
 * (in the engine's photon order) and decides the order in which they, and each photon's
 * candidates, are streamed to pree_top, so that the RTL issues NumPreu operations a cycle
 * without stalls where the window allows it.
 *
 * What keeps the result bit-identical: per hit point, updates happen in photon order. A photon
 * is eligible only when no older pending photon shares a hit point with it (a FIFO of pending
 * photons per hit point); photons that share none may be swapped, and the order of one
 * photon's candidates never matters (they are distinct hit points).
 *
 * How it chooses: a cycle model of the top's issue path (cosim_shadow.h) runs ahead of the RTL
 * on the scheduled stream. In each cycle in which it takes photons (ph_ready_o; up to
 * PhotonsPerCycle, each chosen behind the ones already chosen for that cycle), the scheduler
 * predicts where the operations of a candidate photon would issue (behind the operations
 * AFTSO-HpUOC still holds, NumPreu a cycle) and scores it: stall cycles from hazards (the same
 * hit point issued or predicted within the last win cycles: 11 or 13, 49 or 53 with PipeFast 1),
 * hit-point bank clashes within an issue cycle and lanes left empty (starvation). The photon's
 * candidates are ordered greedily
 * against the same costs (ties: the candidate whose bank more of the photon's candidates share
 * goes first). The oldest eligible photon with no cost is taken, else the cheapest of the first
 * few eligible ones. A cycle's group holds at most GROUP_OPS candidates (half the index table), so
 * that the host can always place a whole group before offering it.
 * Everything is integer arithmetic: deterministic.
 *
 * API
 *   cosim_sched_new(opt, emit, user)  emit(user, ph, hps, n, first, cycle, &p) sends one photon
 *                            (hps in the chosen order; first: it starts the group of photons
 *                            the model took in one cycle, cycle, which the host must offer
 *                            together, in one cycle; the group ends where the next one starts
 *                            or at the flush) and returns 0 with its first index entry in p,
 *                            or -1
 *   cosim_sched_free(s)
 *   cosim_sched_add(s, ph, hps, n)  one photon hit (n >= 1) in photon order; emits as the window
 *                            fills. Returns 0 or -1 (out of memory, or emit failed).
 *   cosim_sched_flush(s)     emit everything pending
 *   cosim_sched_stats(s, st) photons moved (sent while an older one waited) and the model's
 *                            predicted counters */
#ifndef PREE_COSIM_SCHED_H
#define PREE_COSIM_SCHED_H

#include <stddef.h>
#include <stdint.h>
#include "cosim_rtl.h"

typedef struct {
    int preu, hp_bank_w;
    int win;           /* the top's update hazard window (cosim_rtl_update_window) */
    int reg_flow;      /* the top's registered flow: A's offer register, B's queue (PipeFast 1) */
    int reorder;       /* 1: order each photon's candidates too */
    int window;        /* pending photons held (>= 1) */
    int ppc;           /* the top's PhotonsPerCycle (1 .. COSIM_MAX_PPC) */
} cosim_sched_opts_t;

typedef struct {
    uint64_t photons, moved;
    uint64_t cnt[COSIM_NCNT];   /* the cycle model's counters (cosim_rtl.h CNT_*) */
    /* Filled by the host that drives the RTL (lag_known 1), not by cosim_sched_stats: groups
     * the RTL took in another cycle than the model (after the first group's constant offset),
     * and the most cycles one was late. Non-zero means the model's counts are not the RTL's. */
    int lag_known;
    uint64_t groups_late, max_lag;
} cosim_sched_stats_t;

typedef int (*cosim_sched_emit_fn)(void *user, const preu_photon_t *ph, const uint32_t *hps,
                                   uint32_t n, int first, uint64_t cycle, uint32_t *p);
typedef struct cosim_sched cosim_sched_t;

/* The default window (pending photons) for NumPreu PREUs: 128, and COSIM_SCHED_WINDOW_16 with 16.
 * Whole frame of cornell3 (320x240 / 768k), cycle model, 16 PREUs, pixel layout: windows 128,
 * 96, 64, 32 left 482, 362, 176, 65 hazard cycles (99.806% to 99.874% utilization,
 * docs/cosim.md): with four photons taken a cycle a large window moves more photons ahead of
 * older ones, which then become eligible together and meet their neighbours' operations still
 * in flight. With the spatial layout (the default) windows 32 and 128 give the same 658,965
 * cycles. */
#define COSIM_SCHED_WINDOW_16 32
static inline int cosim_sched_default_window(int preu)
{
    return preu >= 16 ? COSIM_SCHED_WINDOW_16 : 128;
}

cosim_sched_t *cosim_sched_new(const cosim_sched_opts_t *opt, cosim_sched_emit_fn emit, void *user);
void cosim_sched_free(cosim_sched_t *s);
int cosim_sched_add(cosim_sched_t *s, const preu_photon_t *ph, const uint32_t *hps, uint32_t n);

/* A driver's own way to send a photon with n <= max_cand candidates (no scheduler): 0, or -1
 * when the RTL hung (the driver's error says why). */
typedef int (*cosim_direct_fn)(void *user, const preu_photon_t *ph, const uint32_t *hps, size_t n);

/* A photon offered to a driver (cosim_drv.c, cosim_axi.c), with its n candidates, to the
 * scheduler s, or with s NULL to direct(user, ...). A photon with more than max_cand candidates
 * (what the PREE's index table takes for one photon) goes as several photons of the same record,
 * each with the next max_cand or fewer of them: they share no hit point, so each hit point's
 * updates keep their photon order and the final state is the same bits. 0 when taken (or it has
 * no candidates), -1 when not: no memory (err says why), or the RTL hung (hung, or direct's -1:
 * the driver's error says why). */
int cosim_sched_offer(cosim_sched_t *s, int hung, size_t max_cand, const preu_photon_t *ph, const uint32_t *hps,
                      size_t n, cosim_direct_fn direct, void *user, char *err, size_t errlen);
int cosim_sched_flush(cosim_sched_t *s);
void cosim_sched_stats(const cosim_sched_t *s, cosim_sched_stats_t *st);

#endif
