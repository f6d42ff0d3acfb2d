/* aftso_model.h: cycle-level C model of the AFTSO-HpUOC dispatcher (rtl/pree_aftso_hpuoc.v).
 *
 * API:
 *   aftso_init(m, num_preu, buf_depth, data_words, early_ready)
 *                            reset state (num_preu <= AFTSO_MAX_PREU, buf_depth <= AFTSO_MAX_BUF,
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

#ifdef __cplusplus
extern "C" {
#endif

#define AFTSO_MAX_PREU  64
#define AFTSO_MAX_BUF   16
#define AFTSO_MAX_WORDS 8

typedef struct {
  uint32_t data[AFTSO_MAX_WORDS]; /* photon data, word 0 = bits 31:0 */
  uint32_t id;                    /* photon id, carried to every lane */
  uint32_t p_addr;                /* first index-table entry of the photon's candidate list */
  uint32_t rem;                   /* hit points not yet dispatched (>= 1 while the entry is valid) */
} aftso_entry;

typedef struct {
  int num_preu, buf_depth, data_words, early_ready;
  int count;                      /* valid entries, always entries 0..count-1 */
  aftso_entry buf[AFTSO_MAX_BUF];
} aftso_model;

typedef struct {
  int valid;
  uint32_t n;                     /* N^P: number of affected hit points */
  uint32_t p_addr, id;
  uint32_t data[AFTSO_MAX_WORDS];
} aftso_in;

typedef struct {
  int ready;                      /* = !busy: a free entry now, or (early_ready) one freed this cycle */
  int empty;                      /* no photon in the buffer */
  int nvalid;                     /* lanes 0..nvalid-1 are valid, the rest are not */
  uint32_t ref_addr[AFTSO_MAX_PREU];
  uint32_t id[AFTSO_MAX_PREU];
  uint32_t data[AFTSO_MAX_PREU][AFTSO_MAX_WORDS];
  int last[AFTSO_MAX_PREU];       /* the lane carries its photon's final hit point */
} aftso_out;

void aftso_init(aftso_model *m, int num_preu, int buf_depth, int data_words, int early_ready);
void aftso_eval(const aftso_model *m, int stall, aftso_out *out);
void aftso_step(aftso_model *m, const aftso_in *in, int stall);

#ifdef __cplusplus
}
#endif

#endif
