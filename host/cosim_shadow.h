// SPDX-License-Identifier: Apache-2.0
/* cosim_shadow.h: a cycle model of pree_top's update-mode issue path (rtl/pree_top.v), for the
 * co-simulation host's photon scheduler (cosim_sched.h): AFTSO-HpUOC (4 x PhotonsPerCycle
 * entries, EarlyReady, PhotonsPerCycle photons a cycle: the rule of model/pree/aftso_rule.h),
 * stage A (index-table reads in lane order, one per bank), stage B (issue a prefix of the pending
 * lanes: hazard in flight over the last win cycles (11 or 13; 49 or 53 with PipeFast 1), same
 * key, hit-point bank), with PipeFast 1's registered flow (A reads the controllers' offers from
 * a two-offer buffer, which takes one whenever its second slot is free; B issues from a two-slot
 * queue that R's lanes move into, and A reads while R is empty or moves), and the RTL's
 * short-cycle counters. Given the same photon
 * stream offered whenever ph_ready_o is high, it issues the same lanes in the same cycles as the
 * RTL, so its counters are the RTL's (up to the cycles before the first photon and after the
 * last issue), which `pree cosim --stats` reports beside the RTL's.
 *
 * API (one cycle = cosim_shadow_eval, then cosim_shadow_edge)
 *   cosim_shadow_new(preu, hp_bank_w, win, ppc, reg_flow)  a model in reset state (NULL when
 *                              out of memory or win > SHADOW_WIN_MAX); win: the update hazard
 *                              window (cosim_rtl_update_window, or cosim_update_window without a
 *                              model); ppc: pree_top's PhotonsPerCycle; reg_flow: its REG_FLOW
 *                              (cosim_rtl_reg_flow, or cosim_reg_flow without a model)
 *   cosim_shadow_free(s)
 *   cosim_shadow_eval(s)       the combinational part of the current cycle; returns ph_ready_o
 *   cosim_shadow_write_idx(s, p, hps, n)  the index entries of a photon placed at p (the k-th
 *                              operation reads entry p + n - 1 - k, as the host writes them)
 *   cosim_shadow_edge(s, take, n, p)  the rising edge; take: the ppc photon slots, slot k with
 *                              n[k] operations (0: empty) and first index entry p[k], are
 *                              taken (only when eval returned 1)
 *   cosim_shadow_leftover(s)   after eval: operations left in AFTSO-HpUOC after this cycle's
 *                              dispatch (what a photon taken now queues behind)
 *   cosim_shadow_idle(s)       nothing buffered, pending or in flight
 * Fields read by the scheduler: t (cycle), stall (after eval: the controller's offer is not
 * taken in this cycle), iss_hp[0..n_iss) (the hit points
 * issued by the last edge), cnt[] (counters, numbered as cosim_rtl.h's CNT_*). */
#ifndef PREE_COSIM_SHADOW_H
#define PREE_COSIM_SHADOW_H

#include <stdint.h>
#include "aftso_rule.h"
#include "cosim_rtl.h"
#include "hp_bank.h"
#include "radiance.h"

#define SHADOW_WIN_MAX 64 /* update hazard window, cycles (WIN_UPD): 11 / 13, PipeFast 1 49 / 53 */

/* Lanes of stage B: the pending ones, their hit points (index entries), and whether stage A left
 * lanes of their offer for a bank conflict (the counters' abank). */
typedef struct {
    uint32_t pend, hp[COSIM_MAX_PREU];
    int a_short;
} shadow_lanes_t;

typedef struct {
    int preu, hp_bank_w;
    int win;                                   /* the update hazard window (WIN_UPD) */
    uint64_t t;                                /* cycles stepped */
    /* AFTSO-HpUOC buffer (entries {first index entry, operations left}) and its offer. */
    aftso_rule_t buf;
    aftso_rule_offer_t off;
    /* reg_flow (PipeFast 1): the offer buffer's o_n offers (slot 0 the one A reads), their
     * lanes and index addresses. */
    int reg_flow, o_n;
    uint32_t o_valid[2], o_ref[2][COSIM_MAX_PREU];
    /* Stage A: lanes of the offer it reads already read; stage B: R, the lanes A read, and with
     * reg_flow the queue's two slots, of which B issues from the head. */
    uint32_t a_done;
    shadow_lanes_t r, q[2];
    int head;
    /* In flight: the keys issued in each of the last win cycles, and a count per key. */
    uint32_t inf_hp[SHADOW_WIN_MAX][COSIM_MAX_PREU];
    int inf_n[SHADOW_WIN_MAX], inf_pos;
    uint8_t *inf_cnt;                          /* 2^COSIM_HPAW */
    uint32_t idx[1u << COSIM_IDXAW];           /* the index table as the host wrote it */
    /* Combinational values of the current cycle (eval). */
    uint32_t ref[COSIM_MAX_PREU], iss, a_rd, a_valid;
    int nvalid, a_go, a_all, stall, ready, cause;
    uint64_t total;
    /* Results of the last edge and counters. */
    uint32_t iss_hp[COSIM_MAX_PREU];
    int n_iss;
    uint64_t cnt[COSIM_NCNT];
} cosim_shadow_t;

cosim_shadow_t *cosim_shadow_new(int preu, int hp_bank_w, int win, int ppc, int reg_flow);
/* The update hazard window of pree_top (its WIN_UPD) for a datapath (0 paper, 1 stable) and
 * PipeFast, for runs without a Verilated model (--model-only); a run with one takes the model's
 * (cosim_rtl_update_window) and checks it against this. */
static inline int cosim_update_window(int datapath, int pipe_fast)
{
    return PREE_UPDATE_WINDOW(datapath, pipe_fast);
}
/* ADISO-REC's pipeline depth in pree_top (its RAD_LAT, the PREU's radiance latency: the same for
 * both datapaths), which sets the radiance pass's issue order and so the image's rounding: the
 * model's (radiance_depth, model/ppm/radiance.h). */
static inline int cosim_radiance_depth(int pipe_fast)
{
    return radiance_depth(pipe_fast);
}
/* Whether pree_top has the registered flow, A's offer register and B's queue (its REG_FLOW):
 * with PipeFast 1. */
static inline int cosim_reg_flow(int pipe_fast)
{
    return pipe_fast != 0;
}
void cosim_shadow_free(cosim_shadow_t *s);
int cosim_shadow_eval(cosim_shadow_t *s);
void cosim_shadow_write_idx(cosim_shadow_t *s, uint32_t p, const uint32_t *hps, uint32_t n);
void cosim_shadow_edge(cosim_shadow_t *s, int take, const uint32_t *n, const uint32_t *p);
uint64_t cosim_shadow_leftover(const cosim_shadow_t *s);
int cosim_shadow_idle(const cosim_shadow_t *s);

#endif
