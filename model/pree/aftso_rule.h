// SPDX-License-Identifier: Apache-2.0
/* aftso_rule.h: the AFTSO-HpUOC accumulate-and-dispatch rule (rtl/pree_aftso_hpuoc.v, paper 000
 * Sec. IV.B widened to PhotonsPerCycle photons a cycle; docs/controllers.md), once in C. The
 * controller bench's model (tb/ctrl/aftso_model.c) and the co-simulation host's cycle model
 * (the shadow in host/) both call it; the RTL is its own copy, checked against it cycle by
 * cycle (tb/ctrl/aftso_bench.cpp) and through the host's exact stall predictions.
 *
 * State: a buffer of buf_depth entries, valid ones 0..count-1 in photon order, each {first
 * index entry p_addr, hit points not yet dispatched rem >= 1, seq: the caller's tag (the
 * photon's arrival number, for its payload)}.
 * Rule, each cycle (accuHP_i = rem_0 + ... + rem_i):
 *   lanes   lane l < min(accuHP_last, num_preu) carries hit point number l in photon order:
 *           entry e with accuHP_(e-1) <= l < accuHP_e, ref = p_addr + rem - 1 - (l - accuHP_(e-1));
 *   leave   not stalled: entries with accuHP_i <= num_preu leave whole, the next one (if any)
 *           loses its first num_preu - accuHP_(i-1) hit points and becomes entry 0;
 *   ready   the buffer has ppc free entries after this cycle's whole departures (these count
 *           only with early_ready and not stalled): with ppc = 1, a free entry or entry 0
 *           leaving whole, the rule of the paper's 4-entry buffer with EarlyReady;
 *   intake  when taken (valid and ready), the ppc photon slots append in slot order behind the
 *           remaining entries; a slot with N^P = 0 is dropped (no entry).
 *
 * API
 *   aftso_rule_init(b, num_preu, buf_depth, ppc, early_ready)   empty buffer
 *   aftso_rule_offer(b, o)          the lanes of the current state (independent of stall)
 *   aftso_rule_ready(b, o, stall)   the intake's ready in this cycle
 *   aftso_rule_edge(b, stall, take, n, p_addr)  one rising edge; take: the ppc slots n[], p_addr[]
 *                                   are taken. Returns the number of entries appended. */
#ifndef PREE_AFTSO_RULE_H
#define PREE_AFTSO_RULE_H

#include <stdint.h>

#define AFTSO_MAX_PREU 64
#define AFTSO_MAX_BUF  32
#define AFTSO_MAX_PPC  8

typedef struct {
    uint32_t p_addr, rem, seq;
} aftso_rule_ent_t;

typedef struct {
    int num_preu, buf_depth, ppc, early_ready;
    int count;                       /* valid entries 0..count-1 */
    uint32_t seq_next;               /* seq of the next appended entry */
    aftso_rule_ent_t e[AFTSO_MAX_BUF];
} aftso_rule_t;

typedef struct {
    uint64_t accu[AFTSO_MAX_BUF];    /* accuHP_i (entries beyond count repeat the total) */
    uint64_t total;                  /* hit points in the buffer */
    int nvalid;                      /* lanes 0..nvalid-1 valid */
    int nwhole;                      /* entries that leave whole when not stalled */
    int ent[AFTSO_MAX_PREU];         /* lane l's entry */
    uint32_t ref[AFTSO_MAX_PREU];    /* lane l's index-table address (modulo 2^32) */
    int last[AFTSO_MAX_PREU];        /* lane l carries its photon's final hit point */
} aftso_rule_offer_t;

void aftso_rule_init(aftso_rule_t *b, int num_preu, int buf_depth, int ppc, int early_ready);
void aftso_rule_offer(const aftso_rule_t *b, aftso_rule_offer_t *o);
int aftso_rule_ready(const aftso_rule_t *b, const aftso_rule_offer_t *o, int stall);
int aftso_rule_edge(aftso_rule_t *b, const aftso_rule_offer_t *o, int stall, int take,
                    const uint32_t *n, const uint32_t *p_addr);

#endif
