/* cli_check.c: `pree check SCENE [options]`: parse the scene, load its meshes, validate it
 * (values, camera rays for the image size) and report what a render would need (hit points,
 * memory, triangles, lights) without building the BVH or tracing a ray. Exit 0 when a render
 * could start, 1 when it could not (the one-line reason on stderr), 2 on a usage error. */
#include <stdio.h>
#include "cli.h"
#include "cli_options.h"
#include "eye_pass.h"
#include "mem_check.h"
#include "scene.h"

static void check_usage(FILE *f)
{
    fprintf(f,
        "usage: pree check SCENE [--width W] [--height H] [--max-memory SIZE] [render options]\n"
        "Parse SCENE, load its meshes and validate it as `pree render` would, then print what a\n"
        "render would need, one 'key value' line each, without rendering. The render options\n"
        "(--photons, --grid, ...) are accepted and checked; see 'pree render --help'.\n");
}

static void report(const char *path, const scene_t *s, const render_options_t *opt, uint64_t mem)
{
    unsigned long long tris = 0, area = 0;
    for (int m = 0; m < s->num_meshes; m++) tris += (unsigned long long)s->meshes[m].num_triangles;
    for (int l = 0; l < s->num_lights; l++) area += s->lights[l].kind == LIGHT_AREA;
    const unsigned long long pix = (unsigned long long)opt->width * (unsigned long long)opt->height;
    printf("scene %s\nmaterials %d\nspheres %d\nmeshes %d\ntriangles %llu\nlights %d\n", path,
           s->num_materials, s->num_spheres, s->num_meshes, tris, s->num_lights);
    printf("point_lights %llu\narea_lights %llu\nmax_depth %d\nimage %dx%d\n", (unsigned long long)s->num_lights - area,
           area, s->max_depth, opt->width, opt->height);
    printf("hit_points_estimate %llu (one a pixel; mirrors and glass may add more)\n", pix);
    printf("memory_estimate_bytes %llu (%.2f GiB)\n", (unsigned long long)mem, (double)mem / (1u << 30));
}

enum { OPT_MAX_MEMORY = CLI_OWN };

static const struct option check_longopts[] = {
    CLI_RENDER_LONGOPTS,
    {"max-memory", required_argument, NULL, OPT_MAX_MEMORY},
    {NULL, 0, NULL, 0}
};

int pree_cmd_check(int argc, char **argv)
{
    render_options_t opt = {.width = 320, .height = 240, .photons = 768000, .precision = PRECISION_DOUBLE,
                            .grid = GRID_CELLS, .preu = 4, .progress = 1};
    const char *scene_path;
    cli_args_t a;
    cli_begin(&a, argc, argv, "check", check_longopts, &opt, 1);
    for (int id; (id = cli_next(&a)) != 0;) {
        if (id < 0) return 2;
        if (id == CLI_HELP) { check_usage(stdout); return 0; }
        if (id == OPT_MAX_MEMORY && cli_size(&a, &opt.max_memory)) return 2;
    }
    if (!(scene_path = cli_scene(&a))) return 2;
    scene_t scene;
    char err[1024];
    if (scene_load(scene_path, &scene, err, sizeof err)) {
        fprintf(stderr, "pree check: %s\n", err);
        return 1;
    }
    unsigned long long tris = 0;
    for (int m = 0; m < scene.num_meshes; m++) tris += (unsigned long long)scene.meshes[m].num_triangles;
    uint64_t mem = mem_estimate_start(tris, (uint64_t)opt.width * (uint64_t)opt.height);
    int rc = 0;
    if (eye_camera_check(&scene.camera, opt.width, opt.height, err, sizeof err) ||
        mem_check(mem, opt.max_memory, MEM_START_WHAT, err, sizeof err)) {
        fprintf(stderr, "pree check: %s: %s\n", scene_path, err);
        rc = 1;
    } else {
        report(scene_path, &scene, &opt, mem);
    }
    scene_free(&scene);
    return rc;
}
