// SPDX-License-Identifier: Apache-2.0
/* adiso_order.c: the PREE radiance pass's issue order (see adiso_order.h). Written from
 * paper 000 Eq. 10-13 and the header of rtl/pree_adiso_rec.v, one step of all groups at a time. */
#include "adiso_order.h"

#define ADISO_ORDER_MAX 64

int adiso_order(uint32_t n, int npreu, int pipe, uint32_t *out)
{
    if (npreu < 1 || npreu > ADISO_ORDER_MAX || (npreu & (npreu - 1)) || pipe < 1) return -1;
    int shift = 0;
    while ((1L << shift) < (long)npreu * pipe) shift++;
    uint32_t lv = n >> shift;
    if (lv == 0) lv = 1;
    const uint32_t size = n / (uint32_t)npreu;
    uint32_t start[ADISO_ORDER_MAX], leap[ADISO_ORDER_MAX], end[ADISO_ORDER_MAX], rem[ADISO_ORDER_MAX];
    for (int i = 0; i < npreu; i++) {
        start[i] = leap[i] = size * (uint32_t)i;
        end[i] = i == npreu - 1 ? n : size * (uint32_t)(i + 1);
        rem[i] = end[i] - start[i];
    }
    /* One step: every group with addresses left emits its current one (lane order), then moves. */
    uint32_t k = 0;
    while (k < n) {
        for (int i = 0; i < npreu; i++) {
            if (!rem[i]) continue;
            out[k++] = leap[i];
            rem[i]--;
            uint64_t next = (uint64_t)leap[i] + lv;
            if (next >= end[i]) leap[i] = ++start[i];   /* Eq. 12/13: next residue class */
            else leap[i] = (uint32_t)next;
        }
    }
    return 0;
}
