// SPDX-License-Identifier: Apache-2.0
/* render_result.c: what both estimators' renders (render.h, model/pm/pm_render.h) fill in alike:
 * the scene's figures, the process's peak memory and CPU time, and the result's release. */
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include "render.h"

long render_peak_rss_kb(void)
{
    struct rusage ru;
    return getrusage(RUSAGE_SELF, &ru) == 0 ? ru.ru_maxrss : -1;
}

double render_cpu_seconds(void)
{
    struct timespec t;
    return clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) ? 0.0 : (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void render_stats_scene(render_stats_t *st, const scene_t *scene)
{
    st->scene_spheres = (unsigned long long)scene->num_spheres;
    for (int m = 0; m < scene->num_meshes; m++) st->scene_triangles += scene->meshes[m].num_triangles;
    st->scene_lights = (unsigned long long)scene->num_lights;
    st->scene_mirror = scene->has_mirror;
    st->scene_glass = scene->has_glass;
    st->max_bounces = scene->max_bounces;
}

void render_result_free(render_result_t *res)
{
    free(res->rgb);
    free(res->emitted);
    hitpoints_free(&res->hp);
    memset(res, 0, sizeof *res);
}
