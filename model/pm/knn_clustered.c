// SPDX-License-Identifier: Apache-2.0
/* knn_clustered.c: the clustered k-NN search of one cluster (see knn_clustered.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "knn_clustered.h"

/* The prefilter's squared bound in float: b widened past the error of the float positions
 * (each coordinate within extent 2^-24 of its double, the float arithmetic within a few ulps),
 * so that every photon within b in double passes it. */
static float prefilter_bound2(double b, double extent, const double q[3])
{
    for (int a = 0; a < 3; a++) extent = fmax(extent, fabs(q[a]));
    const double wide = b + 8 * extent * 0x1p-24 + 16 * b * 0x1p-24;
    return nextafterf((float)(wide * wide * (1 + 0x1p-20)), INFINITY);
}

/* Member q's candidates in the scope: those the kernel passes within b and the normal test, into
 * s->hits. Returns their count. */
static size_t member_candidates(const photon_tree_t *t, knn_kernel_fn kernel, const double q[3], const double n[3],
                                double b, double cos_min, knn_scratch_t *s, size_t scope, knn_work_t *w)
{
    const knn_probe_t p = {{q[0], q[1], q[2]}, {n[0], n[1], n[2]}, b * b, cos_min,
                           {(float)q[0], (float)q[1], (float)q[2]}, prefilter_bound2(b, t->extent, q)};
    const size_t nc = kernel(t, s->runs, s->runs_n, &p, &s->hits, &w->distance_tests);
    w->kernel_tests += scope;
    w->selection += nc;
    return nc;
}

/* Members q[0..m) (normals n) within far of c, searched in one scope: the runs within b + far of
 * c. 0, or -1 when out of memory. */
static int scope_search(const photon_tree_t *t, knn_kernel_fn kernel, const double (*q)[3], const double (*n)[3],
                        int m, const double c[3], double far, double b, double r0, size_t k, double cos_min,
                        knn_scratch_t *s, knn_cand_t *out, size_t *counts, knn_cluster_stats_t *st)
{
    /* b + far holds every photon within b of a member (the triangle inequality); widened by far
     * more than the rounding of these sums, so that it does in floating point too. */
    if (kdtree_runs(&t->kd, c, (b + far) * (1 + 0x1p-40), &s->runs, &s->runs_n, &s->runs_cap)) return -1;
    size_t scope = 0;
    for (size_t r = 0; r < s->runs_n; r++) scope += s->runs[r].hi - s->runs[r].lo;
    if (grow_array((void **)&s->hits.pos, &s->pos_cap, scope + 16, sizeof *s->hits.pos) ||
        grow_array((void **)&s->hits.d2, &s->d2_cap, scope + 16, sizeof *s->hits.d2))
        return -1;
    st->scope_photons += scope;
    for (int l = 0; l < m; l++) {
        /* The member's own bound first: the last member's k-th distance with a margin. */
        double bl = s->lane_guess > 0 && s->lane_guess < b ? s->lane_guess : b;
        size_t nc = member_candidates(t, kernel, q[l], n[l], bl, cos_min, s, scope, &st->work);
        if (nc < k && bl < b) {   /* not certain within bl: again within b, the scope's */
            st->widened++;
            nc = member_candidates(t, kernel, q[l], n[l], bl = b, cos_min, s, scope, &st->work);
        }
        knn_cand_t *o = out + (size_t)l * k;
        if (nc < k && b < r0) {   /* not certain within b: this member alone, within r0 */
            st->fallback++;
            counts[l] = knn_kdtree_query(t, q[l], n[l], cos_min, k, r0 * r0, o, &s->buckets, &st->work);
        } else {
            counts[l] = knn_select_arrays(s->hits.d2, s->hits.pos, t->kd.index, nc, k, bl * bl, &s->buckets, o);
        }
        if (counts[l] == (size_t)-1) return -1;
        s->lane_guess = counts[l] == k ? KNN_LANE_MARGIN * sqrt(o[k - 1].d2) : 0;
    }
    return 0;
}

int knn_cluster(const photon_tree_t *t, knn_kernel_fn kernel, const hitpoints_t *h, const uint32_t *members, int m,
                double r0, size_t k, double cos_min, knn_scratch_t *s, knn_cand_t *out, size_t *counts,
                knn_cluster_stats_t *st)
{
    double q[KNN_LANES][3], n[KNN_LANES][3], c[3] = {0, 0, 0}, far2 = 0;
    for (int l = 0; l < m; l++) {
        const hp_hot_t *p = &h->hot[members[l]];
        q[l][0] = p->px; q[l][1] = p->py; q[l][2] = p->pz;
        n[l][0] = p->nx; n[l][1] = p->ny; n[l][2] = p->nz;
        for (int a = 0; a < 3; a++) c[a] += q[l][a];
    }
    for (int a = 0; a < 3; a++) c[a] /= m;
    for (int l = 0; l < m; l++) {
        const double dx = q[l][0] - c[0], dy = q[l][1] - c[1], dz = q[l][2] - c[2], d2 = dx * dx + dy * dy + dz * dz;
        far2 = d2 > far2 ? d2 : far2;
    }
    const double far = sqrt(far2), b = s->guess > 0 && s->guess < r0 ? s->guess : r0;
    st->clusters++;
    if (far <= KNN_SPREAD_MAX * b) {
        if (scope_search(t, kernel, (const double (*)[3])q, (const double (*)[3])n, m, c, far, b, r0, k, cos_min, s,
                         out, counts, st))
            return -1;
    } else {   /* too spread for one scope: each member in a scope of its own */
        st->per_point++;
        for (int l = 0; l < m; l++)
            if (scope_search(t, kernel, (const double (*)[3])q + l, (const double (*)[3])n + l, 1, q[l], 0, b, r0, k,
                             cos_min, s, out + (size_t)l * k, counts + l, st))
                return -1;
    }
    /* The next cluster's bound: this one's largest k-th distance with a margin (r0 when a
     * member has fewer than k within r0). */
    double kth2 = 0;
    for (int l = 0; l < m; l++) {
        const double v = counts[l] == k ? out[(size_t)l * k + k - 1].d2 : r0 * r0;
        kth2 = v > kth2 ? v : kth2;
    }
    s->guess = KNN_MARGIN * sqrt(kth2);
    return 0;
}

void knn_scratch_free(knn_scratch_t *s)
{
    free(s->runs);
    free(s->hits.pos);
    free(s->hits.d2);
    knn_buckets_free(&s->buckets);
    memset(s, 0, sizeof *s);
}
