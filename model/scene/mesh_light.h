// SPDX-License-Identifier: Apache-2.0
/* mesh_light.h: area lights made of emitting triangles (docs/scene_format.md, "Lights").
 *
 * mesh_light_add() appends one area light to the scene from n triangles (3 corners each,
 * front face on the counter-clockwise side). power is the emitted radiance (is_flux 0:
 * flux = radiance * pi * total area, a one-sided Lambertian emitter) or the total flux
 * (is_flux 1). Zero-area triangles are skipped; a light with no area is an error.
 * Returns 0, or -1 with a one-line message in err and the scene unchanged.
 *
 * mesh_light_sample() maps three numbers in [0, 1) to a point and a cosine-weighted
 * direction about the front normal of the light's triangles (triangle chosen by area). */
#ifndef PREE_MESH_LIGHT_H
#define PREE_MESH_LIGHT_H

#include <stddef.h>
#include "scene.h"

int mesh_light_add(scene_t *scene, const vec3 *corners, size_t n, vec3 power, int is_flux,
                   char *err, size_t errlen);

/* u_tri picks the triangle (and, rescaled, the first barycentric warp), u_pos the second;
 * u_phi, u_cos the direction: phi = 2 pi u_phi, cos(theta) = sqrt(1 - u_cos). */
void mesh_light_sample(const light_t *light, double u_tri, double u_pos, double u_phi, double u_cos,
                       vec3 *origin, vec3 *dir);

#endif
