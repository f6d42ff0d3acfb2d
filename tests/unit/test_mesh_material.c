// SPDX-License-Identifier: Apache-2.0
/* test_mesh_material.c: the MTL -> engine material rule (mesh_material.h) on the McGuire,
 * Sibenik and gold-rings cases, and area-light photon sampling (points on the triangles in
 * proportion to area, cosine-weighted directions about the front normal). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "halton.h"
#include "mesh_light.h"
#include "mesh_material.h"

static mtl_props_t props(void)
{
    mtl_props_t p;
    memset(&p, 0, sizeof p);
    p.tf = v3(1, 1, 1);
    p.ni = 1;
    p.d = 1;
    p.illum = 2;
    return p;
}

static material_t rule(const mtl_props_t *p)
{
    material_t m;
    memset(&m, 0, sizeof m);
    mesh_material_from_mtl(p, &m);
    return m;
}

static void test_rule(void **state)
{
    (void)state;
    /* McGuire wall: diffuse Kd. */
    mtl_props_t p = props();
    p.kd = v3(0.63, 0.065, 0.05);
    material_t m = rule(&p);
    assert_int_equal(m.kind, MAT_DIFFUSE);
    assert_true(m.colour.x == 0.63 && m.colour.z == 0.05);
    /* McGuire light: Ke -> emissive, its surface diffuse Kd (even with Ni 1.5, Tf 1). */
    p = props();
    p.kd = v3(0.78, 0.78, 0.78); p.ke = v3(17, 12, 4); p.ni = 1.5;
    assert_true(mesh_material_is_emissive(&p));
    assert_int_equal(rule(&p).kind, MAT_DIFFUSE);
    assert_false(mesh_material_is_emissive(&(mtl_props_t){.tf = {1, 1, 1}}));
    /* McGuire glass sphere: illum 7, Ni 2.5, Tf 0.1 grey -> clear glass, ior 2.5. */
    p = props();
    p.kd = v3(0.01, 0.01, 0.01); p.ks = v3(0.3, 0.3, 0.3); p.tf = v3(0.1, 0.1, 0.1); p.ni = 2.5; p.illum = 7;
    m = rule(&p);
    assert_int_equal(m.kind, MAT_GLASS);
    assert_true(m.ior == 2.5 && m.colour.x == 1 && m.colour.y == 1 && m.colour.z == 1);
    /* Sibenik staklo: illum 2 but d 0.1 -> glass; Ni 1 -> default ior 1.5. */
    p = props();
    p.kd = v3(0.78, 0.78, 0.78); p.ks = v3(0.78, 0.78, 0.78); p.d = 0.1;
    m = rule(&p);
    assert_int_equal(m.kind, MAT_GLASS);
    assert_true(m.ior == 1.5);
    /* Sibenik staklo_zeleno: illum 4, green Tf -> glass tinted Tf / max(Tf). */
    p = props();
    p.tf = v3(0.066667, 0.631373, 0.07451); p.illum = 4;
    m = rule(&p);
    assert_int_equal(m.kind, MAT_GLASS);
    assert_true(m.colour.y == 1.0 && fabs(m.colour.x - 0.066667 / 0.631373) < 1e-12);
    /* McGuire mirror sphere: illum 5 -> mirror tinted Ks. */
    p = props();
    p.kd = v3(0.01, 0.01, 0.01); p.ks = v3(0.95, 0.95, 0.95); p.illum = 5;
    m = rule(&p);
    assert_int_equal(m.kind, MAT_MIRROR);
    assert_true(m.colour.x == 0.95);
    /* Gold rings: no illum, Ks 1 .8 .5 above Kd -> mirror; illum 3 with Ks 0 -> white mirror. */
    p = props();
    p.kd = v3(0.6, 0.6, 0.6); p.ks = v3(1, 0.8, 0.5); p.illum = -1;
    m = rule(&p);
    assert_int_equal(m.kind, MAT_MIRROR);
    assert_true(m.colour.y == 0.8);
    p = props();
    p.illum = 3;
    m = rule(&p);
    assert_true(m.kind == MAT_MIRROR && m.colour.x == 1);
    /* Teapot.mtl (Kd 1, Ks .33): diffuse. Colours clamp to [0, 1]. */
    p = props();
    p.kd = v3(1.5, 1, -0.5); p.ks = v3(0.33, 0.33, 0.33);
    m = rule(&p);
    assert_int_equal(m.kind, MAT_DIFFUSE);
    assert_true(m.colour.x == 1 && m.colour.z == 0);
}

static void test_area_sampling(void **state)
{
    (void)state;
    scene_t s;
    memset(&s, 0, sizeof s);
    /* Two triangles: areas 0.5 (z = 0, normal +z) and 1.5 (z = 5, normal -z). */
    vec3 c[6] = {v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 5), v3(0, 1, 5), v3(3, 0, 5)};
    char err[128];
    assert_int_equal(mesh_light_add(&s, c, 2, v3(1, 1, 1), 0, err, sizeof err), 0);
    const light_t *l = &s.lights[0];
    assert_true(fabs(l->area - 2.0) < 1e-12 && fabs(l->flux.x - 2.0 * PREE_PI) < 1e-12);
    assert_true(fabs(l->tris[0].cdf - 0.25) < 1e-12 && l->tris[1].cdf == 1.0);
    const int N = 200000;
    int on_second = 0;
    double sum_cos = 0, sum_x0 = 0;
    for (int i = 0; i < N; i++) {
        vec3 o, d;
        mesh_light_sample(l, halton(59, i), halton(60, i), halton(0, i), halton(1, i), &o, &d);
        assert_true(fabs(v3_dot(d, d) - 1) < 1e-12);
        if (o.z > 2.5) {
            on_second++;
            assert_true(o.z == 5 && o.x >= -1e-12 && o.y >= -1e-12 && o.x / 3 + o.y <= 1 + 1e-12);
            assert_true(d.z < 0);
            sum_cos += -d.z;
        } else {
            assert_true(o.z == 0 && o.x >= -1e-12 && o.y >= -1e-12 && o.x + o.y <= 1 + 1e-12);
            assert_true(d.z > 0);
            sum_cos += d.z;
            sum_x0 += o.x;
        }
    }
    /* Share by area 0.75; mean cos of a cosine-weighted hemisphere 2/3; mean x on the unit
     * right triangle 1/3 (uniform over the area). */
    assert_true(fabs((double)on_second / N - 0.75) < 0.002);
    assert_true(fabs(sum_cos / N - 2.0 / 3.0) < 0.002);
    assert_true(fabs(sum_x0 / (N - on_second) - 1.0 / 3.0) < 0.003);
    free(s.lights[0].tris);
    free(s.lights);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rule),
        cmocka_unit_test(test_area_sampling),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
