// SPDX-License-Identifier: Apache-2.0
/* cosim_reorder.h: the order of one photon's candidates in the unscheduled stream (--no-schedule):
 * each next one, where possible, in a hit-point bank that none of the last NumPreu-1 operations
 * used, so that NumPreu consecutive operations read distinct banks where the candidates allow it.
 * The order inside one photon changes no result (its candidates are distinct hit points).
 *
 * API
 *   cosim_reorder_t r = {.np, .bank_w, .on}   NumPreu, log2 of the hit-point banks, 0: keep the
 *                                             engine's order (the banks are still remembered)
 *   cosim_reorder(&r, cand, hps, n)           hps[0..n) into cand[0..n) in stream order */
#ifndef PREE_COSIM_REORDER_H
#define PREE_COSIM_REORDER_H

#include <stddef.h>
#include <stdint.h>
#include "cosim_rtl.h"

typedef struct {
    int np, bank_w, on;
    int recent[COSIM_MAX_PREU];   /* hit-point banks of the last NumPreu-1 operations */
    int nrecent;
} cosim_reorder_t;

void cosim_reorder(cosim_reorder_t *r, uint32_t *cand, const uint32_t *hps, size_t n);

#endif
