// SPDX-License-Identifier: Apache-2.0
/* pree_wqueue.h: the word queue of pree_drv's back ends (drv/pree_be_verilated.c,
 * drv/pree_be_uart.c): submitted stream words wait in it until the hardware takes them.
 *   pree_wq_push(&q, w, n)   append n words (grows, compacts); 0, or -1 out of memory
 *   pree_wq_avail(&q)        words waiting, from q.w[q.head]; a consumer advances q.head
 *   pree_wq_free(&q) */
#ifndef PREE_WQUEUE_H
#define PREE_WQUEUE_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    uint32_t *w;
    size_t head, tail, cap;   /* words [head, tail) wait */
} pree_wq_t;

static inline size_t pree_wq_avail(const pree_wq_t *q) { return q->tail - q->head; }
int pree_wq_push(pree_wq_t *q, const uint32_t *w, size_t n);
void pree_wq_free(pree_wq_t *q);

#endif
