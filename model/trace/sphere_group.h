// SPDX-License-Identifier: Apache-2.0
/* sphere_group.h: the reference program's ray-sphere test for a small set of spheres at once.
 * Every sphere's t (or 0 for a miss) is computed with exactly the operations of the scalar test
 * (sphere_group_t_scalar), in AVX2 lanes where the processor has them: the same bits. */
#ifndef PREE_SPHERE_GROUP_H
#define PREE_SPHERE_GROUP_H

#include "scene.h"

#define SPHERE_GROUP_MAX 16

typedef struct {
    int n;                                   /* spheres */
    double cx[SPHERE_GROUP_MAX], cy[SPHERE_GROUP_MAX], cz[SPHERE_GROUP_MAX];
    double rr[SPHERE_GROUP_MAX];             /* radius * radius; -inf pads to a multiple of 4 */
    int avx2;                                /* use the AVX2 path */
} sphere_group_t;

/* Fill g from spheres[0..n), n <= SPHERE_GROUP_MAX. */
void sphere_group_init(sphere_group_t *g, const sphere_t *spheres, int n);

/* t[i] for every sphere i of the group: the nearest intersection beyond eps, or 0. */
void sphere_group_t_all(const sphere_group_t *g, vec3 o, vec3 d, double eps, double t[SPHERE_GROUP_MAX]);

/* Whether a sphere hit at t (0: a miss) may replace the current hit: t beats best_t (ties to the
 * lower index than best_id) and, while a triangle holds the hit, is not beyond its (float) tfar. */
static inline int sphere_may_replace(double t, int id, double best_t, int best_id, int triangle_holds, double tfar)
{
    return t != 0 && (t < best_t || (t == best_t && id < best_id)) && !(triangle_holds && tfar < t);
}

/* The sphere that may replace the current hit, from the group's t (sphere_group_t_all; sphere i
 * has index first + i): t != 0, t beats best_t (ties to the lower index than best_id) and, while
 * a triangle holds the hit (triangle_holds), t is not beyond its tfar; of those the nearest,
 * ties to the lower index. Returns the group's sphere i, or -1. */
int sphere_group_pick(const sphere_group_t *g, const double t[SPHERE_GROUP_MAX], int first, double best_t, int best_id,
                      int triangle_holds, double tfar);

/* The group alone against a ray: sphere_group_pick of every sphere's t against the empty state
 * (nothing hit yet, no triangle). Returns the sphere with its t in *t_hit, or -1. */
int sphere_group_nearest(const sphere_group_t *g, vec3 o, vec3 d, double eps, double *t_hit);

/* The scalar test for one sphere (centre c, squared radius rr). */
static inline double sphere_group_t_scalar(double cx, double cy, double cz, double rr, vec3 o, vec3 d, double eps)
{
    const double opx = cx - o.x, opy = cy - o.y, opz = cz - o.z;
    const double b = opx * d.x + opy * d.y + opz * d.z;
    double det = b * b - (opx * opx + opy * opy + opz * opz) + rr;
    if (det < 0) return 0;
    det = sqrt(det);
    double t = b - det;
    if (t > eps) return t;
    t = b + det;
    return t > eps ? t : 0;
}

#endif
