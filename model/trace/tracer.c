// SPDX-License-Identifier: Apache-2.0
/* tracer.c: Embree 3 scene of user-geometry spheres (intersected in double) and triangles. */
#include <embree3/rtcore.h>
#include <stdbool.h>
#include <float.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pree_env.h"
#include "sphere_group.h"
#include "tracer.h"

/* Scenes with at most this many spheres keep them all in one Embree primitive whose callback
 * tests each in index order: with so few, the BVH culls little and every extra primitive
 * costs a callback. Larger sets get one primitive per sphere. The result is the same either
 * way: the closest hit is chosen by exact (t, index).
 *
 * A scene of such a group and nothing else (the reference program's scenes) needs no Embree at
 * all: the group is tested directly, without a device, a BVH of one leaf or a callback. The
 * hit is the callback's: Embree calls it whenever the ray meets the group's padded box, which
 * holds every sphere hit (sphere_bounds), and it then picks from the same t by the same rule
 * against the empty starting state. The environment variable PREE_TRACER_EMBREE keeps Embree
 * for such scenes too (the check that both paths give the same bits). */

struct tracer {
    RTCDevice device;
    RTCScene scene;
    const scene_t *src;
    unsigned sphere_geom;     /* Embree geometry id of the sphere set, or RTC_INVALID_GEOMETRY_ID */
    int spheres_per_prim;     /* num_spheres when grouped, else 1 */
    int direct;               /* the group is the whole scene: no Embree device or scene */
    sphere_group_t group;     /* the grouped spheres, tested together */
    unsigned *mesh_of_geom;   /* geometry id -> mesh index */
    unsigned num_geoms;
    double build_seconds;
};

/* The extended intersect context: Embree's context first, then the double ray and the
 * closest sphere hit found so far (exact double t, ties to the lower sphere index). */
typedef struct {
    struct RTCIntersectContext base;
    vec3 o, d;
    double best_t;
    int best_sphere;
} dray_context_t;

static void embree_error(void *user, enum RTCError code, const char *msg)
{
    (void)user;
    if (code == RTC_ERROR_CANCELLED) return;   /* a stop request: tracer_create reports it */
    fprintf(stderr, "pree: embree error %d: %s\n", (int)code, msg ? msg : "");
}

/* The reference program's ray-sphere test (sphere_group.h): returns t, or 0 for a miss. */
static inline double sphere_hit_t(const sphere_t *s, vec3 o, vec3 d, double eps)
{
    return sphere_group_t_scalar(s->centre.x, s->centre.y, s->centre.z, s->radius * s->radius, o, d, eps);
}

static void sphere_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const tracer_t *tr = args->geometryUserPtr;
    const int first = (int)args->primID * tr->spheres_per_prim;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = first; i < first + tr->spheres_per_prim; i++) {
        const sphere_t *s = &tr->src->spheres[i];
        /* Pad by a relative margin so that float traversal never culls a double hit. */
        double r = s->radius * (1.0 + 1e-5) + 1e-3;
        const double c[3] = {s->centre.x, s->centre.y, s->centre.z};
        for (int a = 0; a < 3; a++) { lo[a] = fmin(lo[a], c[a] - r); hi[a] = fmax(hi[a], c[a] + r); }
    }
    args->bounds_o->lower_x = (float)lo[0]; args->bounds_o->lower_y = (float)lo[1]; args->bounds_o->lower_z = (float)lo[2];
    args->bounds_o->upper_x = (float)hi[0]; args->bounds_o->upper_y = (float)hi[1]; args->bounds_o->upper_z = (float)hi[2];
}

static void sphere_intersect(const struct RTCIntersectFunctionNArguments *args)
{
    if (!args->valid[0]) return;
    dray_context_t *ctx = (dray_context_t *)args->context;
    const tracer_t *tr = args->geometryUserPtr;
    struct RTCRayHit *rh = (struct RTCRayHit *)args->rayhit;   /* N == 1: rtcIntersect1 */
    const int first = (int)args->primID * tr->spheres_per_prim;
    double tg[SPHERE_GROUP_MAX];
    const int grouped = tr->spheres_per_prim > 1;
    if (grouped) sphere_group_t_all(&tr->group, ctx->o, ctx->d, tr->src->epsilon, tg);
    /* The nearest sphere that may replace the current hit: t beats the best so far (ties to the
     * lower index) and, while a triangle holds the hit, is not beyond it. Choosing the minimum
     * of these at once is what accepting them one by one in index order ends with: every sphere
     * accepted in that order passes these tests against the starting state, and t only falls. */
    const double best0 = ctx->best_t, tfar0 = (double)rh->ray.tfar;
    const int best_id0 = ctx->best_sphere, triangle_holds = rh->hit.geomID != args->geomID;
    int pick = -1;
    double pick_t = INFINITY;
    if (grouped) {
        const int i = sphere_group_pick(&tr->group, tg, first, best0, best_id0, triangle_holds, tfar0);
        if (i >= 0) { pick = first + i; pick_t = tg[i]; }
    } else {
        const double t = sphere_hit_t(&tr->src->spheres[first], ctx->o, ctx->d, tr->src->epsilon);
        if (sphere_may_replace(t, first, best0, best_id0, triangle_holds, tfar0)) {
            pick = first;
            pick_t = t;
        }
    }
    if (pick < 0) return;
    ctx->best_t = pick_t;
    ctx->best_sphere = pick;
    float tf = (float)pick_t;
    if ((double)tf < pick_t && tf < FLT_MAX) {
        /* The next float up (t > 0): nextafterf(tf, FLT_MAX) without the call. */
        uint32_t bits;
        memcpy(&bits, &tf, sizeof bits);
        bits++;
        memcpy(&tf, &bits, sizeof tf);
    }
    rh->ray.tfar = tf;
    rh->hit.geomID = args->geomID;
    rh->hit.primID = args->primID;
}

static void sphere_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    if (!args->valid[0]) return;
    dray_context_t *ctx = (dray_context_t *)args->context;
    const tracer_t *tr = args->geometryUserPtr;
    struct RTCRay *ray = (struct RTCRay *)args->ray;
    const int first = (int)args->primID * tr->spheres_per_prim;
    for (int id = first; id < first + tr->spheres_per_prim; id++) {
        double t = sphere_hit_t(&tr->src->spheres[id], ctx->o, ctx->d, tr->src->epsilon);
        if (t != 0 && t < (double)ray->tfar) { ray->tfar = -INFINITY; return; }
    }
}

static int add_spheres(tracer_t *tr, char *err, size_t errlen)
{
    RTCGeometry g = rtcNewGeometry(tr->device, RTC_GEOMETRY_TYPE_USER);
    if (!g) { snprintf(err, errlen, "embree: cannot create the sphere geometry"); return -1; }
    const int n = tr->src->num_spheres;
    tr->spheres_per_prim = n <= SPHERE_GROUP_MAX ? n : 1;
    if (tr->spheres_per_prim > 1) sphere_group_init(&tr->group, tr->src->spheres, n);
    rtcSetGeometryUserPrimitiveCount(g, (unsigned)(n / tr->spheres_per_prim));
    rtcSetGeometryUserData(g, tr);
    rtcSetGeometryBoundsFunction(g, sphere_bounds, NULL);
    rtcSetGeometryIntersectFunction(g, sphere_intersect);
    rtcSetGeometryOccludedFunction(g, sphere_occluded);
    rtcCommitGeometry(g);
    tr->sphere_geom = rtcAttachGeometry(tr->scene, g);
    rtcReleaseGeometry(g);
    return 0;
}

static int add_mesh(tracer_t *tr, unsigned mesh_index, char *err, size_t errlen)
{
    const mesh_t *m = &tr->src->meshes[mesh_index];
    RTCGeometry g = rtcNewGeometry(tr->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!g) { snprintf(err, errlen, "embree: cannot create a triangle geometry"); return -1; }
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), m->num_vertices);
    unsigned *ix = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                           3 * sizeof(unsigned), m->num_triangles);
    if (!v || !ix) { rtcReleaseGeometry(g); snprintf(err, errlen, "embree: out of memory for %s", m->source); return -1; }
    for (size_t i = 0; i < 3 * m->num_vertices; i++) v[i] = m->vertices[i];
    for (size_t i = 0; i < 3 * m->num_triangles; i++) ix[i] = m->indices[i];
    rtcCommitGeometry(g);
    unsigned id = rtcAttachGeometry(tr->scene, g);
    rtcReleaseGeometry(g);
    unsigned *map = realloc(tr->mesh_of_geom, (id + 1) * sizeof *map);
    if (!map) { snprintf(err, errlen, "out of memory"); return -1; }
    for (unsigned k = tr->num_geoms; k <= id; k++) map[k] = (unsigned)-1;
    map[id] = mesh_index;
    tr->mesh_of_geom = map;
    tr->num_geoms = id + 1;
    return 0;
}

/* Embree's build progress callback: returning false cancels the build. */
static bool build_monitor(void *stop, double done)
{
    (void)done;
    return !stop_requested(stop);
}

tracer_t *tracer_create(const scene_t *scene, const stop_flag_t *stop, char *err, size_t errlen)
{
    tracer_t *tr = calloc(1, sizeof *tr);
    if (!tr) { snprintf(err, errlen, "out of memory"); return NULL; }
    tr->src = scene;
    tr->sphere_geom = RTC_INVALID_GEOMETRY_ID;
    double t0 = omp_get_wtime();
    if (scene->num_meshes == 0 && scene->num_spheres > 1 && scene->num_spheres <= SPHERE_GROUP_MAX &&
        !pree_env(PREE_ENV_TRACER_EMBREE)) {
        tr->direct = 1;
        sphere_group_init(&tr->group, scene->spheres, scene->num_spheres);
        if (stop_requested(stop)) {
            snprintf(err, errlen, "%s", STOP_MESSAGE);
            tracer_destroy(tr);
            return NULL;
        }
        tr->build_seconds = omp_get_wtime() - t0;
        return tr;
    }
    /* Embree builds with as many threads as the render may use (--threads): with its own pool of one
     * per core, a one-thread render's allocations would depend on which thread stole which build
     * task, and so would the heap the later passes grow their arrays in. */
    char config[32];
    snprintf(config, sizeof config, "threads=%d", omp_get_max_threads());
    tr->device = rtcNewDevice(config);
    if (!tr->device) { snprintf(err, errlen, "embree: cannot create a device"); free(tr); return NULL; }
    rtcSetDeviceErrorFunction(tr->device, embree_error, NULL);
    tr->scene = rtcNewScene(tr->device);
    rtcSetSceneFlags(tr->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(tr->scene, RTC_BUILD_QUALITY_HIGH);
    if (stop) rtcSetSceneProgressMonitorFunction(tr->scene, build_monitor, (void *)stop);
    int rc = 0;
    if (scene->num_spheres > 0) rc = add_spheres(tr, err, errlen);
    for (int i = 0; rc == 0 && i < scene->num_meshes; i++) rc = add_mesh(tr, (unsigned)i, err, errlen);
    if (rc == 0) {
        rtcCommitScene(tr->scene);
        if (rtcGetDeviceError(tr->device) != RTC_ERROR_NONE || stop_requested(stop)) {
            snprintf(err, errlen, "%s", stop_requested(stop) ? STOP_MESSAGE : "embree: scene build failed");
            rc = -1;
        }
    }
    if (rc) { tracer_destroy(tr); return NULL; }
    tr->build_seconds = omp_get_wtime() - t0;
    return tr;
}

void tracer_destroy(tracer_t *tr)
{
    if (!tr) return;
    if (tr->scene) rtcReleaseScene(tr->scene);
    if (tr->device) rtcReleaseDevice(tr->device);
    free(tr->mesh_of_geom);
    free(tr);
}

double tracer_build_seconds(const tracer_t *tr) { return tr->build_seconds; }

/* The hit on sphere s at t, as both paths report it. */
static int sphere_hit(const tracer_t *tr, int s, double t, vec3 o, vec3 d, hit_t *hit)
{
    const sphere_t *sp = &tr->src->spheres[s];
    hit->t = t;
    hit->x = v3_add(o, v3_scale(d, t));
    hit->n = v3_norm(v3_sub(hit->x, sp->centre));
    hit->material = sp->material;
    hit->object = s;
    return 1;
}

int tracer_intersect(const tracer_t *tr, vec3 o, vec3 d, hit_t *hit)
{
    if (tr->direct) {
        double t;
        const int i = sphere_group_nearest(&tr->group, o, d, tr->src->epsilon, &t);
        return i < 0 ? 0 : sphere_hit(tr, i, t, o, d, hit);
    }
    dray_context_t ctx;
    rtcInitIntersectContext(&ctx.base);
    ctx.o = o;
    ctx.d = d;
    ctx.best_t = INFINITY;
    ctx.best_sphere = -1;
    struct RTCRayHit rh;
    rh.ray.org_x = (float)o.x; rh.ray.org_y = (float)o.y; rh.ray.org_z = (float)o.z;
    rh.ray.dir_x = (float)d.x; rh.ray.dir_y = (float)d.y; rh.ray.dir_z = (float)d.z;
    rh.ray.tnear = (float)tr->src->epsilon;
    rh.ray.tfar = INFINITY;
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.Ng_x = rh.hit.Ng_y = rh.hit.Ng_z = 0.0f;
    rh.hit.u = rh.hit.v = 0.0f;
    rtcIntersect1(tr->scene, &ctx.base, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return 0;
    if (rh.hit.geomID == tr->sphere_geom) return sphere_hit(tr, ctx.best_sphere, ctx.best_t, o, d, hit);
    const mesh_t *m = &tr->src->meshes[tr->mesh_of_geom[rh.hit.geomID]];
    hit->t = (double)rh.ray.tfar;
    hit->x = v3_add(o, v3_scale(d, hit->t));
    vec3 n = v3_norm(v3((double)rh.hit.Ng_x, (double)rh.hit.Ng_y, (double)rh.hit.Ng_z));
    if (m->normals) {
        const uint32_t *tri = m->indices + 3 * rh.hit.primID;
        double u = rh.hit.u, v = rh.hit.v, w = 1.0 - u - v;
        const float *n0 = m->normals + 3 * tri[0], *n1 = m->normals + 3 * tri[1], *n2 = m->normals + 3 * tri[2];
        vec3 ns = v3(w * n0[0] + u * n1[0] + v * n2[0], w * n0[1] + u * n1[1] + v * n2[1],
                     w * n0[2] + u * n1[2] + v * n2[2]);
        if (v3_dot(ns, ns) > 0) {
            ns = v3_norm(ns);
            if (v3_dot(ns, n) < 0) ns = v3_scale(ns, -1.0);
            n = ns;
        }
    }
    /* Triangles have no outside: their normal faces the incoming ray. */
    hit->n = v3_dot(n, d) < 0 ? n : v3_scale(n, -1.0);
    hit->material = m->tri_material[rh.hit.primID];
    hit->object = tr->src->num_spheres + (int)tr->mesh_of_geom[rh.hit.geomID];
    return 1;
}
