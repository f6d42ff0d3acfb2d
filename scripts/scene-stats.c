// SPDX-License-Identifier: Apache-2.0
/* scene-stats.c: helper for the scene checks and the scene benchmark (built by
 * scripts/scene-lib.sh against build/libpree.a).
 *   scene-stats info SCENE    one line: triangles, meshes, spheres, point and area lights,
 *                             materials and which kinds occur, and scene_load's wall seconds
 *   scene-stats image FILE    one line: the mean of R, G, B and of all three, the smallest and
 *                             largest value, and the NaN and infinity counts of an image */
#include <math.h>
#include <time.h>
#include <stdio.h>
#include <string.h>
#include "image.h"
#include "scene.h"

static int info(const char *path)
{
    scene_t s;
    char err[1024];
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    if (scene_load(path, &s, err, sizeof err)) { fprintf(stderr, "scene-stats: %s\n", err); return 1; }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    size_t tris = 0;
    for (int i = 0; i < s.num_meshes; i++) tris += s.meshes[i].num_triangles;
    int point = 0, area = 0;
    for (int i = 0; i < s.num_lights; i++) {
        point += s.lights[i].kind == LIGHT_POINT;
        area += s.lights[i].kind == LIGHT_AREA;
    }
    printf("triangles=%zu meshes=%d spheres=%d point_lights=%d area_lights=%d materials=%d diffuse=%d mirror=%d glass=%d load_seconds=%.3f\n",
           tris, s.num_meshes, s.num_spheres, point, area, s.num_materials, s.has_diffuse, s.has_mirror, s.has_glass,
           (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    scene_free(&s);
    return 0;
}

static int image(const char *path)
{
    pree_image_t img;
    char err[1024];
    if (pree_image_read(path, &img, err, sizeof err)) { fprintf(stderr, "scene-stats: %s\n", err); return 1; }
    double sum[3] = {0, 0, 0}, lo = INFINITY, hi = -INFINITY;
    size_t nan = 0, inf = 0, n = (size_t)img.width * (size_t)img.height;
    for (size_t i = 0; i < 3 * n; i++) {
        double v = img.rgb[i];
        if (isnan(v)) { nan++; continue; }
        if (isinf(v)) { inf++; continue; }
        sum[i % 3] += v;
        if (v < lo) lo = v;
        if (v > hi) hi = v;
    }
    printf("mean_r=%.6g mean_g=%.6g mean_b=%.6g mean=%.6g min=%.6g max=%.6g nan=%zu inf=%zu\n", sum[0] / n,
           sum[1] / n, sum[2] / n, (sum[0] + sum[1] + sum[2]) / (3.0 * n), lo, hi, nan, inf);
    pree_image_free(&img);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 3 && !strcmp(argv[1], "info")) return info(argv[2]);
    if (argc == 3 && !strcmp(argv[1], "image")) return image(argv[2]);
    fprintf(stderr, "usage: scene-stats info SCENE | scene-stats image FILE\n");
    return 2;
}
