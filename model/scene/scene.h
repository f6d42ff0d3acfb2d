/* scene.h: the scene description: camera, materials, analytic spheres, triangle meshes and
 * lights, as read from a PREE scene file (format: docs/scene_format.md).
 *
 * API: scene_load() parses a file; on error it returns -1 with a one-line message
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
} light_t;

typedef struct {
    vec3 origin, dir;   /* dir as written; normalised by the camera code */
    double scale;       /* height of the image plane at unit distance (2 tan(fov/2)) */
    double near;        /* rays start at origin + d * near, d the unnormalised pixel vector */
    int has_up;         /* 0: image x axis is world +x (the reference program's camera) */
    vec3 up;
} camera_t;

typedef struct {
    char path[512];
    camera_t camera;
    material_t *materials; int num_materials;
    sphere_t *spheres;     int num_spheres;
    mesh_t *meshes;        int num_meshes;
    light_t *lights;       int num_lights;
    int max_depth;         /* path length limit (default 20) */
    double epsilon;        /* ray offset and nearest sphere hit, scene units (default TRACER_EPSILON
                            * = 1e-4, smallppm's; scale it with the scene, `epsilon E`) */
    /* What the scene contains, so that the engine can skip what it does not need. */
    int has_mirror, has_glass, has_diffuse;
} scene_t;

int scene_load(const char *path, scene_t *out, char *err, size_t errlen);
void scene_free(scene_t *scene);

/* Add a material, returning its index, or -1 if the name exists (err filled). */
int scene_add_material(scene_t *scene, const material_t *m, char *err, size_t errlen);
int scene_find_material(const scene_t *scene, const char *name);

#endif
