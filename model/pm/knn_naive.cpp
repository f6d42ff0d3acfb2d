// SPDX-License-Identifier: Apache-2.0
// knn_naive.cpp: the oracle k-NN through nanoflann (see knn_naive.h).
#include <nanoflann.hpp>
#include <new>
#include <vector>
#include "knn_naive.h"

namespace {
// The calling thread's coordinate reads (three a distance) and candidates sorted.
thread_local unsigned long long coords_read, sorted;

// nanoflann's dataset interface over the photon map.
struct map_source {
    const photon_map_t *map;
    size_t kdtree_get_point_count() const { return map->n; }
    double kdtree_get_pt(size_t i, size_t dim) const { coords_read++; return map->p[i].x[dim]; }
    template <class B> bool kdtree_get_bbox(B &) const { return false; }
};
using tree_t = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, map_source>, map_source, 3, size_t>;
}

struct knn_naive {
    map_source src;
    tree_t tree;
    explicit knn_naive(const photon_map_t *m) : src{m}, tree(3, src, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
};

extern "C" knn_naive_t *knn_naive_new(const photon_map_t *map)
{
    try {
        knn_naive *s = new knn_naive(map);
        if (map->n) s->tree.buildIndex();
        coords_read = 0;   // the build's reads are not the queries'
        return s;
    } catch (const std::bad_alloc &) {
        return nullptr;
    }
}

extern "C" void knn_naive_free(knn_naive_t *s) { delete s; }

extern "C" void knn_naive_work(unsigned long long *distance_tests, unsigned long long *selection)
{
    *distance_tests += coords_read / 3;
    *selection += sorted;
    coords_read = sorted = 0;
}

extern "C" size_t knn_naive_query(const knn_naive_t *s, const double q[3], const double n[3], double cos_min,
                                  size_t k, double r2max, knn_cand_t *out)
{
    const photon_map_t *m = s->src.map;
    if (m->n == 0 || k == 0) return 0;
    try {
        // Ask for k' nearest, doubling k' until the k nearest that pass are certain: all points
        // returned, or the k'-th lies beyond both the radius and the k-th passing candidate
        // (strictly, so that a tie at the boundary is never cut by nanoflann's order).
        std::vector<size_t> idx;
        std::vector<double> d2;
        std::vector<knn_cand_t> pass;
        for (size_t want = k;; want *= 2) {
            if (want > m->n) want = m->n;
            idx.resize(want);
            d2.resize(want);
            size_t got = s->tree.knnSearch(q, want, idx.data(), d2.data());
            pass.clear();
            for (size_t i = 0; i < got; i++) {
                if (d2[i] > r2max) continue;
                const float *pn = m->p[idx[i]].n;
                if (!(n[0] * pn[0] + n[1] * pn[1] + n[2] * pn[2] > cos_min)) continue;
                pass.push_back(knn_cand_t{d2[i], (uint32_t)idx[i], 0});
            }
            size_t c = knn_select(pass.data(), pass.size(), k);
            sorted += pass.size();
            double last = got ? d2[got - 1] : 0;
            if (got < want || want == m->n || last > r2max || (c == k && last > pass[k - 1].d2)) {
                for (size_t i = 0; i < c; i++) out[i] = pass[i];
                return c;
            }
        }
    } catch (const std::bad_alloc &) {
        return (size_t)-1;
    }
}
