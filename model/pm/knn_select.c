/* knn_select.c: the shared exact selection of the k nearest (see knn_select.h). */
#include <stdlib.h>
#include "knn_select.h"

static int cand_cmp(const void *a, const void *b)
{
    const knn_cand_t *x = a, *y = b;
    if (x->d2 != y->d2) return x->d2 < y->d2 ? -1 : 1;
    return x->photon < y->photon ? -1 : x->photon > y->photon;
}

size_t knn_select(knn_cand_t *c, size_t n, size_t k)
{
    if (n > 1) qsort(c, n, sizeof *c, cand_cmp);   /* c may be NULL when n is 0 (qsort's contract) */
    return n < k ? n : k;
}
