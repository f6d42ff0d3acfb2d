// SPDX-License-Identifier: Apache-2.0
/* scene_lights.c: photon emission by light power (scene.h, scene_light_power). */
#include <stdio.h>
#include <stdlib.h>
#include "scene.h"

int scene_light_power(scene_t *s, char *err, size_t errlen)
{
    double total = 0;
    for (int l = 0; l < s->num_lights; l++) total += s->lights[l].flux.x + s->lights[l].flux.y + s->lights[l].flux.z;
    if (!(total > 0) || total > 1e300) {
        snprintf(err, errlen, "%s: --light-sampling power: the lights' total flux is %g", s->path, total);
        return -1;
    }
    double *cdf = malloc((size_t)s->num_lights * sizeof *cdf), run = 0;
    if (!cdf) { snprintf(err, errlen, "out of memory"); return -1; }
    for (int l = 0; l < s->num_lights; l++) {
        run += s->lights[l].flux.x + s->lights[l].flux.y + s->lights[l].flux.z;
        cdf[l] = run / total;
    }
    cdf[s->num_lights - 1] = 1.0;
    free(s->light_cdf);
    s->light_cdf = cdf;
    return 0;
}
