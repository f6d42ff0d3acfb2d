/* knn_select.h: the exact selection both k-NN searches end with, and the tie rule they share:
 * neighbours ordered by (squared distance, photon index), the k first kept. */
#ifndef PREE_KNN_SELECT_H
#define PREE_KNN_SELECT_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    double d2;
    uint32_t photon;   /* index into the photon map */
} knn_cand_t;

#ifdef __cplusplus
extern "C" {
#endif
/* Sort c[0..n) by (d2, photon); returns min(n, k), the count of the k nearest. */
size_t knn_select(knn_cand_t *c, size_t n, size_t k);
#ifdef __cplusplus
}
#endif

#endif
