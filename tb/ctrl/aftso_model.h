// SPDX-License-Identifier: Apache-2.0
/* aftso_model.h: cycle-level C model of the AFTSO-HpUOC dispatcher (rtl/pree_aftso_hpuoc.v).
 * The dispatch rule itself is model/pree/aftso_rule.h (shared with the co-simulation host); this
 * file adds the photons' payload (data words, id) and the RTL's port shapes.
 *
 * API:
 *   aftso_init(m, num_preu, buf_depth, ppc, data_words, early_ready)
 *                            reset state (num_preu <= AFTSO_MAX_PREU, buf_depth <= AFTSO_MAX_BUF,
 *                            ppc <= AFTSO_MAX_PPC photons a cycle (the RTL's PhotonsPerCycle),
 *                            data_words <= AFTSO_MAX_WORDS; early_ready = the RTL's EarlyReady)
 *   aftso_eval(m, stall, out) combinational outputs of the current state (lanes, ready, empty);
 *                            ready depends on stall when early_ready is set
 *   aftso_step(m, in, stall) one rising clock edge with the given input and stall
 * The model mirrors the RTL register for register: aftso_eval() is what the RTL drives between
 * two edges, aftso_step() is what the edge does. All widths are 32 bits (the RTL defaults).
 */
#ifndef AFTSO_MODEL_H
#define AFTSO_MODEL_H

#include <stdint.h>
#include "aftso_rule.h"

#ifdef __cplusplus
extern "C" {
#endif

#define AFTSO_MAX_WORDS 8

typedef struct {
  int data_words;
  aftso_rule_t rule;                             /* the buffer: p_addr, rem, seq per entry */
  uint32_t id[AFTSO_MAX_BUF];                    /* payload by seq mod AFTSO_MAX_BUF */
  uint32_t data[AFTSO_MAX_BUF][AFTSO_MAX_WORDS];
} aftso_model;

typedef struct {
  uint32_t n;                     /* N^P: number of affected hit points (0: an empty slot) */
  uint32_t p_addr, id;
  uint32_t data[AFTSO_MAX_WORDS];
} aftso_photon;

typedef struct {
  int valid;                      /* the ppc slots are offered (one valid for all) */
  aftso_photon ph[AFTSO_MAX_PPC]; /* slot 0 is the oldest photon */
} aftso_in;

typedef struct {
  int ready;                      /* = !busy: ppc entries free after this cycle's departures */
  int empty;                      /* no photon in the buffer */
  int nvalid;                     /* lanes 0..nvalid-1 are valid, the rest are not */
  uint32_t ref_addr[AFTSO_MAX_PREU];
  uint32_t id[AFTSO_MAX_PREU];
  uint32_t data[AFTSO_MAX_PREU][AFTSO_MAX_WORDS];
  int last[AFTSO_MAX_PREU];       /* the lane carries its photon's final hit point */
} aftso_out;

void aftso_init(aftso_model *m, int num_preu, int buf_depth, int ppc, int data_words, int early_ready);
void aftso_eval(const aftso_model *m, int stall, aftso_out *out);
void aftso_step(aftso_model *m, const aftso_in *in, int stall);

#ifdef __cplusplus
}
#endif

#endif
