// SPDX-License-Identifier: Apache-2.0
/* grow.h: the one growth rule for the engine's arrays.
 *
 * grow_array(&p, &cap, need, size): make *p hold at least need elements of size bytes,
 * doubling *cap from at least 1024; *p and *cap change only on success. 0, or -1 when out of
 * memory (the old array is kept, as realloc keeps it). */
#ifndef PREE_GROW_H
#define PREE_GROW_H

#include <stddef.h>
#include <stdlib.h>

static inline int grow_array(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap) return 0;
    size_t c = *cap ? *cap : 1024;
    while (c < need) c *= 2;
    void *q = realloc(*p, c * size);
    if (!q) return -1;
    *p = q;
    *cap = c;
    return 0;
}

#endif
