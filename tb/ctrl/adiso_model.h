// SPDX-License-Identifier: Apache-2.0
/* adiso_model.h: C model of the ADISO-REC leaping-address generator (rtl/pree_adiso_rec.v),
 * paper 000 Sec. IV.C, Eq. 10-13.
 *
 * API:
 *   adiso_shift(nset, npip)            ceil(log2(nset * npip)), the shift of Eq. 10
 *   adiso_leaping_value(n, nset, npip) Eq. 10: floor(n / 2^shift) (may be 0)
 *   adiso_init(m, nset, npip)          reset: no group active (nset a power of two <= ADISO_MAX_SET)
 *   adiso_eval(m, out)                 the registered outputs of the current state
 *   adiso_step(m, start, n, stall)     one rising clock edge; start (re)loads for n hit points
 *   adiso_eq11_start(m, i, j)          the closed form of Eq. 11 (for comparison only)
 * Groups: size = floor(n / nset); group i covers [size*i, end_i) with end_i = size*(i+1), except
 * the last group, which ends at n (it also takes the n mod nset left-over addresses).
 * Leaping value 0 (n < 2^shift) is replaced by 1: each group is then walked sequentially.
 */
#ifndef ADISO_MODEL_H
#define ADISO_MODEL_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define ADISO_MAX_SET 64

typedef struct {
  int nset, npip;
  uint32_t n, lv, size;                 /* hit points, effective leaping value, group size */
  uint32_t start[ADISO_MAX_SET];        /* start_addr_i,j (Reg_start) */
  uint32_t leap[ADISO_MAX_SET];         /* leaping_addr_i,j (Reg_leaping_addr), the output */
  uint32_t end[ADISO_MAX_SET];          /* end address of group i, exclusive (Reg_end) */
  uint32_t rem[ADISO_MAX_SET];          /* addresses of group i still to be produced */
} adiso_model;

typedef struct {
  int valid[ADISO_MAX_SET];
  uint32_t addr[ADISO_MAX_SET];
  int busy;
} adiso_out;

int adiso_shift(int nset, int npip);
uint32_t adiso_leaping_value(uint32_t n, int nset, int npip);
void adiso_init(adiso_model *m, int nset, int npip);
void adiso_eval(const adiso_model *m, adiso_out *out);
void adiso_step(adiso_model *m, int start, uint32_t n, int stall);
uint32_t adiso_eq11_start(const adiso_model *m, int i, uint32_t j);

#ifdef __cplusplus
}
#endif

#endif
