// SPDX-License-Identifier: Apache-2.0
/* pree_wqueue.c: the back ends' word queue (see pree_wqueue.h). */
#include "pree_wqueue.h"

#include <stdlib.h>
#include <string.h>

int pree_wq_push(pree_wq_t *q, const uint32_t *w, size_t n)
{
    if (q->head == q->tail) q->head = q->tail = 0;
    if (q->tail + n > q->cap) {
        if (q->head) {   /* compact */
            memmove(q->w, q->w + q->head, pree_wq_avail(q) * sizeof *q->w);
            q->tail -= q->head;
            q->head = 0;
        }
        if (q->tail + n > q->cap) {
            size_t cap = q->cap ? q->cap : 4096;
            while (cap < q->tail + n) cap *= 2;
            uint32_t *nw = realloc(q->w, cap * sizeof *nw);
            if (!nw) return -1;
            q->w = nw;
            q->cap = cap;
        }
    }
    memcpy(q->w + q->tail, w, n * sizeof *w);
    q->tail += n;
    return 0;
}

void pree_wq_free(pree_wq_t *q)
{
    free(q->w);
    *q = (pree_wq_t){0};
}
