// SPDX-License-Identifier: Apache-2.0
/* scene.h: the scene description: camera, materials, analytic spheres, triangle meshes and
 * lights, as read from a PREE scene file (format: docs/scene_format.md).
 *
 * API: scene_load() parses a file (a pbrt-v4 file when its name ends in .pbrt: scene_pbrt.h); on error it returns -1 with a one-line message
 * "FILE:LINE: what" in err and leaves *out untouched. scene_free() releases everything. */
#ifndef PREE_SCENE_H
#define PREE_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "vec3.h"

/* The reference program's truncated pi: every pi in the engine is this literal. */
#define PREE_PI 3.14159265358979

typedef enum { MAT_DIFFUSE = 0, MAT_MIRROR = 1, MAT_GLASS = 2 } material_kind_t;

typedef struct {
    char name[64];
    material_kind_t kind;
    vec3 colour;   /* reflectance (diffuse), tint (mirror, glass) */
    double ior;    /* glass index of refraction, outside medium 1 */
} material_t;

typedef struct { double radius; vec3 centre; int material; } sphere_t;

typedef struct {
    char source[256];       /* file it came from ("inline" for triangle lines) */
    float *vertices;        /* 3 floats per vertex */
    float *normals;         /* 3 floats per vertex, or NULL for flat shading */
    uint32_t *indices;      /* 3 per triangle */
    int *tri_material;      /* material per triangle */
    size_t num_vertices, num_triangles;
} mesh_t;

typedef enum { LIGHT_POINT = 0, LIGHT_AREA = 1 } light_kind_t;

/* One emitting triangle of an area light: corner p0, edges e1 = p1 - p0 and e2 = p2 - p0,
 * unit front normal n = normalize(e1 x e2) (counter-clockwise side), and the cumulative
 * share of the light's area up to and including this triangle (the last one is exactly 1). */
typedef struct { vec3 p0, e1, e2, n; double cdf; } light_tri_t;

/* A point light (position, flux), or an area light: Lambertian emitting triangles with
 * total flux 'flux' (radiance * pi * area), emitting from their front faces only. */
typedef struct {
    light_kind_t kind;
    vec3 position;      /* point lights */
    vec3 flux;
    light_tri_t *tris;  /* area lights */
    size_t num_tris;
    double area;
    vec3 radiance;      /* area lights: the radiance leaving each front face (flux / (pi * area)
                         * where the light was given by its flux), what the camera sees */
} light_t;

typedef struct {
    vec3 origin, dir;   /* dir as written; normalised by the camera code */
    double scale;       /* height of the image plane at unit distance (2 tan(fov/2)) */
    double near;        /* rays start at origin + d * near, d the unnormalised pixel vector */
    int has_up;         /* 0: image x axis is world +x (the reference program's camera) */
    vec3 up;
} camera_t;

/* The largest magnitude of a scene coordinate, radius or distance: Embree's rays hold origins
 * up to |x| = 1.8e18 (ray.valid()), and binary32 squared distances need |x| below ~1.8e19;
 * 1e15 leaves a margin for sums of coordinates and the camera's near offset. */
#define SCENE_COORD_MAX 1e15
/* The camera's scale (the image plane's height at distance 1) lies in [1e-6, 1e6]. */
#define SCENE_SCALE_MIN 1e-6
#define SCENE_SCALE_MAX 1e6

typedef struct {
    char path[512];
    camera_t camera;
    material_t *materials; int num_materials;
    int materials_cap;     /* scene_materials.c: the array's capacity and its index by name */
    int *mat_index;        /* open addressing: material id + 1, 0 empty */
    size_t mat_index_cap, mat_index_used;
    sphere_t *spheres;     int num_spheres;
    mesh_t *meshes;        int num_meshes;
    light_t *lights;       int num_lights;
    int max_depth;         /* path length limit (default 20) */
    int max_bounces;       /* photon paths stop at their hit after this many bounces (paper 001's
                            * W: `pree render --max-bounces`); 0: max_depth alone */
    double epsilon;        /* ray offset and nearest sphere hit, scene units (default TRACER_EPSILON
                            * = 1e-4, smallppm's; scale it with the scene, `epsilon E`) */
    /* What the scene contains, so that the engine can skip what it does not need. */
    int has_mirror, has_glass, has_diffuse;
    /* A pbrt-v4 file's Film resolution and sppm photon count (0: none), the render's defaults. */
    int film_width, film_height;
    uint64_t film_photons;
    double film_radius;    /* and sppm's initial radius "radius" (0: none: the hit points' bounds give it) */
    /* Photon emission: NULL, photon i from light i mod L (uniform: every light the same share);
     * else by power, the lights' cumulative shares of the total flux (scene_light_power). */
    double *light_cdf;
} scene_t;

int scene_load(const char *path, scene_t *out, char *err, size_t errlen);
void scene_free(scene_t *scene);

/* Add a material, returning its index, or -1 if the name exists (err filled). */
int scene_add_material(scene_t *scene, const material_t *m, char *err, size_t errlen);
int scene_find_material(const scene_t *scene, const char *name);
/* Emit photons by light power (light_cdf, docs/scene_format.md "Photon emission"): 0, or -1
 * with err when the lights carry no flux. */
int scene_light_power(scene_t *s, char *err, size_t errlen);

/* Free the materials and their index (scene_free calls it). */
void scene_materials_free(scene_t *scene);

#endif
