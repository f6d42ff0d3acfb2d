// SPDX-License-Identifier: Apache-2.0
/* cli_check.c: `pree check SCENE [options]`: parse the scene, load its meshes, validate it
 * (values, camera rays for the image size) and report what a render would need (hit points,
 * memory, triangles, lights) without rendering: the hit points are estimated from the eye rays
 * of a sample of the pixels (the BVH is built for them). Exit 0 when a render could start, 1
 * when it could not (the one-line reason on stderr), 2 on a usage error. */
#include <math.h>
#include <stdio.h>
#include "cli.h"
#include "cli_options.h"
#include "eye_pass.h"
#include "mem_check.h"
#include "scene.h"
#include "tracer.h"

/* The pixels a hit-point estimate traces at most (EYE_RAYS_MAX times as many rays at most). */
#define CHECK_SAMPLE_PIXELS 4800

typedef struct {
    int stride;                 /* every stride-th pixel across and down (eye_pass.h) */
    unsigned long long pixels;  /* the pixels traced */
    unsigned long long hit_points;   /* their hit points */
} hp_sample_t;

/* The eye pass over a sample of the pixels (the smallest stride that traces at most
 * CHECK_SAMPLE_PIXELS), the same rays as the render's for those pixels: 0, or -1 with err. */
static int sample_hit_points(const scene_t *scene, const render_options_t *opt, hp_sample_t *hs, char *err,
                             size_t errlen)
{
    const unsigned long long w = (unsigned long long)opt->width, h = (unsigned long long)opt->height;
    int s = 1;
    while ((w / s) * (h / s) > CHECK_SAMPLE_PIXELS) s++;
    const unsigned long long nx = w > (unsigned long long)(s / 2) ? (w - s / 2 + s - 1) / s : 0;
    const unsigned long long ny = h > (unsigned long long)(s / 2) ? (h - s / 2 + s - 1) / s : 0;
    *hs = (hp_sample_t){s, nx * ny, 0};
    tracer_t *tr = tracer_create(scene, NULL, err, errlen);
    if (!tr) return -1;
    const eye_pass_opts_t eo = {opt->width, opt->height, opt->eye_rays, 0, s};
    hitpoints_t hp = {0};
    double *emitted = NULL;
    eye_stats_t es;
    const int rc = eye_pass(scene, tr, &eo, &hp, &emitted, &es, NULL, err, errlen);
    hs->hit_points = hp.n;
    hitpoints_free(&hp);
    tracer_destroy(tr);
    return rc;
}

static void check_usage(FILE *f)
{
    fprintf(f,
        "usage: pree check SCENE [--width W] [--height H] [--max-memory SIZE] [render options]\n"
        "Parse SCENE, load its meshes and validate it as `pree render` would, then print what a\n"
        "render would need, one 'key value' line each, without rendering. The render options\n"
        "(--photons, --grid, ...) are accepted and checked; see 'pree render --help'.\n");
}

static void report(const char *path, const scene_t *s, const render_options_t *opt, uint64_t mem,
                   const hp_sample_t *hs)
{
    unsigned long long tris = 0, area = 0;
    for (int m = 0; m < s->num_meshes; m++) tris += (unsigned long long)s->meshes[m].num_triangles;
    for (int l = 0; l < s->num_lights; l++) area += s->lights[l].kind == LIGHT_AREA;
    const unsigned long long pix = (unsigned long long)opt->width * (unsigned long long)opt->height;
    printf("scene %s\nmaterials %d\nspheres %d\nmeshes %d\ntriangles %llu\nlights %d\n", path,
           s->num_materials, s->num_spheres, s->num_meshes, tris, s->num_lights);
    printf("point_lights %llu\narea_lights %llu\nmax_depth %d\nimage %dx%d\n", (unsigned long long)s->num_lights - area,
           area, s->max_depth, opt->width, opt->height);
    const double per_pixel = hs->pixels ? (double)hs->hit_points / (double)hs->pixels : 0;
    printf("hit_points_estimate %.0f (the eye rays of %llu of the %llu pixels traced, 1 in %d across and down: "
           "%.4g hit points a pixel)\n", per_pixel * (double)pix, hs->pixels, pix, hs->stride, per_pixel);
    printf("memory_estimate_bytes %llu (%.2f GiB)\n", (unsigned long long)mem, (double)mem / (1u << 30));
    /* Each material as the engine takes it (an MTL material as the MTL rule classified it). */
    static const char *const kinds[] = {"diffuse", "mirror", "glass"};
    for (int i = 0; i < s->num_materials; i++) {
        const material_t *m = &s->materials[i];
        printf("material %s %s %.6g %.6g %.6g", m->name, kinds[m->kind], m->colour.x, m->colour.y, m->colour.z);
        if (m->kind == MAT_GLASS) printf(" ior %.6g", m->ior);
        putchar('\n');
    }
    /* Each light: where, which way an area light faces (its triangles' area-weighted normal;
     * "mixed" when they do not agree), its flux and its share of the photons (photon i comes
     * from light i mod L) and of the total flux. */
    double total = 0;
    for (int l = 0; l < s->num_lights; l++) total += s->lights[l].flux.x + s->lights[l].flux.y + s->lights[l].flux.z;
    for (int l = 0; l < s->num_lights; l++) {
        const light_t *L = &s->lights[l];
        const double f = L->flux.x + L->flux.y + L->flux.z;
        if (L->kind == LIGHT_POINT) {
            printf("light %d point at %.6g %.6g %.6g", l, L->position.x, L->position.y, L->position.z);
        } else {
            vec3 n = v3(0, 0, 0);
            for (size_t t = 0; t < L->num_tris; t++) {
                const double a = 0.5 * sqrt(v3_dot(v3_cross(L->tris[t].e1, L->tris[t].e2), v3_cross(L->tris[t].e1, L->tris[t].e2)));
                n = v3_add(n, v3_scale(L->tris[t].n, a));
            }
            const double len = sqrt(v3_dot(n, n));
            printf("light %d area %zu triangle%s area %.6g ", l, L->num_tris, L->num_tris == 1 ? "" : "s", L->area);
            if (len > 0.99 * L->area) printf("facing %.4g %.4g %.4g", n.x / len, n.y / len, n.z / len);
            else printf("facing mixed");
        }
        printf(" flux %.6g %.6g %.6g photons 1/%d flux_share %.4g\n", L->flux.x, L->flux.y, L->flux.z, s->num_lights,
               total > 0 ? f / total : 0.0);
    }
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
    int size_given = 0;
    cli_begin(&a, argc, argv, "check", check_longopts, NULL, 1);
    for (int id; (id = cli_next(&a)) != 0;) {
        if (id < 0) return 2;
        if (id == CLI_HELP) { check_usage(stdout); return 0; }
        if (id == OPT_MAX_MEMORY) {
            if (cli_size(&a, &opt.max_memory)) return 2;
        } else if (cli_render_option(&a, id, &opt, 1)) {
            return 2;
        }
        size_given |= id == CLI_WIDTH ? 1 : id == CLI_HEIGHT ? 2 : 0;
    }
    if (!(scene_path = cli_scene(&a))) return 2;
    scene_t scene;
    char err[1024];
    if (scene_load(scene_path, &scene, err, sizeof err)) {
        fprintf(stderr, "pree check: %s\n", err);
        return 1;
    }
    /* A pbrt file's Film resolution, as pree render takes it. */
    if (scene.film_width && !(size_given & 1)) opt.width = scene.film_width;
    if (scene.film_height && !(size_given & 2)) opt.height = scene.film_height;
    unsigned long long tris = 0;
    for (int m = 0; m < scene.num_meshes; m++) tris += (unsigned long long)scene.meshes[m].num_triangles;
    uint64_t mem = mem_estimate_start(tris, (uint64_t)opt.width * (uint64_t)opt.height,
                                      opt.eye_rays > 1 ? (uint64_t)opt.eye_rays : 1);
    int rc = 0;
    hp_sample_t hs;
    if (eye_camera_check(&scene.camera, opt.width, opt.height, err, sizeof err) ||
        mem_check(mem, opt.max_memory, MEM_START_WHAT, err, sizeof err) ||
        sample_hit_points(&scene, &opt, &hs, err, sizeof err)) {
        fprintf(stderr, "pree check: %s: %s\n", scene_path, err);
        rc = 1;
    } else {
        report(scene_path, &scene, &opt, mem, &hs);
    }
    scene_free(&scene);
    return rc;
}
