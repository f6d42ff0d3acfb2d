// SPDX-License-Identifier: Apache-2.0
/* test_scene_parse.c: the scene format: the reference scene's exact constants, and errors
 * that name the file and line. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "scene.h"

#ifndef SCENES_DIR
#define SCENES_DIR "scenes"
#endif

static void test_cornell3(void **state)
{
    (void)state;
    scene_t s;
    char err[512] = "";
    int rc = scene_load(SCENES_DIR "/cornell3", &s, err, sizeof err);
    if (rc) fprintf(stderr, "%s\n", err);
    assert_int_equal(rc, 0);
    assert_int_equal(s.num_spheres, 9);
    assert_int_equal(s.num_lights, 1);
    assert_int_equal(s.num_meshes, 0);
    assert_int_equal(s.max_depth, 20);
    /* "A+B" numbers are summed in double exactly as the reference's source does. */
    volatile double a = -1e5, b = 81.6;
    assert_true(s.spheres[5].centre.y == a + b);
    assert_true(s.spheres[0].centre.x == 1e5 + 1);
    assert_true(s.lights[0].flux.x == 2500 * (PREE_PI * 4.0));
    assert_true(s.camera.scale == 0.5135 && s.camera.near == 140 && !s.camera.has_up);
    assert_int_equal(s.materials[s.spheres[7].material].kind, MAT_GLASS);
    assert_true(s.materials[s.spheres[7].material].ior == 1.5);
    assert_true(s.has_glass && s.has_mirror && s.has_diffuse);
    scene_free(&s);
}

static int load_text(const char *text, char *err, size_t errlen)
{
    char path[] = "/tmp/pree-scene-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
    close(fd);
    scene_t s;
    int rc = scene_load(path, &s, err, errlen);
    if (rc == 0) scene_free(&s);
    unlink(path);
    return rc;
}

static void test_errors_name_line(void **state)
{
    (void)state;
    char err[512];
    assert_int_equal(load_text("camera origin 0 0 0 dir 0 0 -1 scale .5 near 0\n\nsphere 1 0 0 0 x\n", err, sizeof err), -1);
    assert_non_null(strstr(err, ":3: unknown material 'x'"));
    assert_int_equal(load_text("material m diffuse 1 1 1\nmaterial n glass 1 1 1 ior 0.5\n", err, sizeof err), -1);
    assert_non_null(strstr(err, ":2: material 'n': ior 0.5"));
    assert_int_equal(load_text("material m diffuse 1 1 1e999\n", err, sizeof err), -1);
    assert_non_null(strstr(err, ":1: number '1e999' is not finite"));
    assert_int_equal(load_text("light point 0 0 0 intensity 1 1 1x\n", err, sizeof err), -1);
    assert_non_null(strstr(err, ":1: malformed number '1x'"));
    assert_int_equal(load_text("", err, sizeof err), -1);
    assert_non_null(strstr(err, "no camera"));
}

/* The materials' hash index: every name found at its id through growth, duplicates refused,
 * and entries left by a rollback (mesh_load.c trims num_materials) never returned. */
static void test_material_index(void **state)
{
    (void)state;
    scene_t s;
    memset(&s, 0, sizeof s);
    char err[256], name[32];
    material_t m;
    memset(&m, 0, sizeof m);
    for (int i = 0; i < 5000; i++) {
        snprintf(m.name, sizeof m.name, "m%d", i);
        assert_int_equal(scene_add_material(&s, &m, err, sizeof err), i);
    }
    for (int i = 0; i < 5000; i++) {
        snprintf(name, sizeof name, "m%d", i);
        assert_int_equal(scene_find_material(&s, name), i);
    }
    assert_int_equal(scene_find_material(&s, "m5000"), -1);
    snprintf(m.name, sizeof m.name, "m17");
    assert_int_equal(scene_add_material(&s, &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "material 'm17' is defined twice"));
    s.num_materials = 4000;   /* a rollback */
    assert_int_equal(scene_find_material(&s, "m4500"), -1);
    snprintf(m.name, sizeof m.name, "m4500");
    assert_int_equal(scene_add_material(&s, &m, err, sizeof err), 4000);
    assert_int_equal(scene_find_material(&s, "m4500"), 4000);
    assert_int_equal(scene_find_material(&s, "m4001"), -1);
    scene_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cornell3),
        cmocka_unit_test(test_errors_name_line),
        cmocka_unit_test(test_material_index),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
