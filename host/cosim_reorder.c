// SPDX-License-Identifier: Apache-2.0
/* cosim_reorder.c: a photon's candidates in an order of distinct banks (cosim_reorder.h). */
#include <string.h>
#include "cosim_reorder.h"
#include "hp_bank.h"

void cosim_reorder(cosim_reorder_t *r, uint32_t *cand, const uint32_t *hps, size_t n)
{
    memcpy(cand, hps, n * sizeof *hps);
    for (size_t k = 0; k < n; k++) {
        size_t pick = k;
        if (r->on) {
            for (size_t c = k; c < n; c++) {
                const int bank = (int)pree_hp_bank(cand[c], r->bank_w);
                int clash = 0;
                for (int j = 0; j < r->nrecent; j++) clash |= r->recent[j] == bank;
                if (!clash) { pick = c; break; }
            }
            const uint32_t t = cand[k];
            cand[k] = cand[pick];
            cand[pick] = t;
        }
        /* Remember the bank in the window of the last NumPreu-1 operations. */
        if (r->np > 1) {
            if (r->nrecent == r->np - 1) {
                memmove(r->recent, r->recent + 1, (size_t)(r->np - 2) * sizeof *r->recent);
                r->nrecent--;
            }
            r->recent[r->nrecent++] = (int)pree_hp_bank(cand[k], r->bank_w);
        }
    }
}
