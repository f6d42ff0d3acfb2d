// SPDX-License-Identifier: Apache-2.0
/* test_mesh_load.c: the "mesh" directive: OBJ/MTL loading (plain and gzip), transforms,
 * normals modes, overrides and exclusion, emissive triangles as area lights, the
 * "light triangle" directive, and one-line errors (file:line) that leave no scene behind. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#include "mesh_load.h"
#include "scene.h"

static char dir[64];

static void put(const char *name, const char *text)
{
    char p[256];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    FILE *f = fopen(p, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void put_gz(const char *name, const char *text)
{
    char p[256];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    gzFile f = gzopen(p, "wb9");
    assert_non_null(f);
    assert_int_equal(gzwrite(f, text, (unsigned)strlen(text)), (int)strlen(text));
    gzclose(f);
}

static const char *HEAD = "camera position 0 0 5 lookat 0 0 0 up 0 1 0 fov 60\n"
                          "material w diffuse .5 .5 .5\n"
                          "light point 0 0 3 intensity 1 1 1\n";

/* Write a scene file "s" (HEAD + body) and load it; returns scene_load's result. */
static int load(const char *body, scene_t *s, char *err)
{
    char text[2048], p[256];
    snprintf(text, sizeof text, "%s%s", HEAD, body);
    put("s", text);
    snprintf(p, sizeof p, "%s/s", dir);
    return scene_load(p, s, err, 512);
}

static const char *QUAD_OBJ = "mtllib q.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                              "usemtl red\nf 1//1 2//1 3//1 4//1\n";
static const char *QUAD_MTL = "newmtl red\n  Kd 0.8 0.1 0.1 # comment\n";

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/pree-test-mesh-XXXXXX");
    assert_non_null(mkdtemp(dir));
    put("q.obj", QUAD_OBJ);
    put("q.mtl", QUAD_MTL);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd);
}

static void test_quad_and_mtl(void **state)
{
    (void)state;
    scene_t s;
    char err[512] = "";
    assert_int_equal(load("mesh q.obj\n", &s, err), 0);
    assert_int_equal(s.num_meshes, 1);
    assert_int_equal(s.meshes[0].num_triangles, 2);
    assert_non_null(s.meshes[0].normals);
    int id = scene_find_material(&s, "q.obj:red");
    assert_true(id >= 0);
    assert_int_equal(s.materials[id].kind, MAT_DIFFUSE);
    assert_true(fabs(s.materials[id].colour.x - 0.8) < 1e-6 && fabs(s.materials[id].colour.y - 0.1) < 1e-6);
    assert_int_equal(s.meshes[0].tri_material[0], id);
    assert_int_equal(s.meshes[0].tri_material[1], id);
    scene_free(&s);
}

static void test_gzip_and_transform(void **state)
{
    (void)state;
    put_gz("z.obj.gz", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    scene_t s;
    char err[512] = "";
    /* scale 2, then 90 degrees about z (x -> y), then translate. */
    assert_int_equal(load("mesh z.obj.gz material w scale 2 rotate z 90 translate 10 0 0 normals flat\n", &s, err), 0);
    const mesh_t *m = &s.meshes[0];
    assert_int_equal(m->num_triangles, 1);
    assert_null(m->normals);
    int found = 0;
    for (size_t v = 0; v < m->num_vertices; v++) {
        const float *p = m->vertices + 3 * v;
        if (fabsf(p[0] - 10.0f) < 1e-5f && fabsf(p[1] - 2.0f) < 1e-5f && fabsf(p[2]) < 1e-6f) found++;
    }
    assert_int_equal(found, 1);   /* (1, 0, 0) -> (2, 0, 0) -> (0, 2, 0) -> (10, 2, 0) */
    assert_int_equal(m->tri_material[0], scene_find_material(&s, "w"));
    scene_free(&s);
    /* The same file named without ".gz" is found as FILE.gz. */
    assert_int_equal(load("mesh z.obj material w\n", &s, err), 0);
    scene_free(&s);
}

static void test_overrides(void **state)
{
    (void)state;
    scene_t s;
    char err[512] = "";
    assert_int_equal(load("material g glass 1 1 1 ior 1.33\nmesh q.obj map red g\n", &s, err), 0);
    assert_int_equal(s.meshes[0].tri_material[0], scene_find_material(&s, "g"));
    assert_int_equal(s.has_glass, 1);
    scene_free(&s);
    assert_int_equal(load("mesh q.obj normals smooth\n", &s, err), 0);
    assert_non_null(s.meshes[0].normals);
    scene_free(&s);
    assert_int_equal(load("mesh q.obj exclude red\n", &s, err), -1);
    assert_non_null(strstr(err, "no triangles"));
}

static void test_emissive_area_light(void **state)
{
    (void)state;
    put("e.obj", "mtllib e.mtl\nv 0 1 0\nv 0 1 2\nv 2 1 2\nv 2 1 0\nusemtl lamp\nf 1 2 3 4\n");
    put("e.mtl", "newmtl lamp\nKd 0.5 0.5 0.5\nKe 2 3 4\n");
    scene_t s;
    char err[512] = "";
    assert_int_equal(load("mesh e.obj emission 0.5\n", &s, err), 0);
    assert_int_equal(s.num_lights, 2);
    const light_t *l = &s.lights[1];
    assert_int_equal(l->kind, LIGHT_AREA);
    assert_int_equal(l->num_tris, 2);
    assert_true(fabs(l->area - 4.0) < 1e-9);
    /* flux = emission * Ke * pi * area */
    assert_true(fabs(l->flux.x - 0.5 * 2 * PREE_PI * 4) < 1e-9 && fabs(l->flux.z - 0.5 * 4 * PREE_PI * 4) < 1e-9);
    assert_true(l->tris[1].cdf == 1.0);
    /* Counter-clockwise from below: (0,0,2) x (2,0,2) = (0, 4, 0), front normal +y. */
    assert_true(fabs(l->tris[0].n.y - 1.0) < 1e-12);
    int id = scene_find_material(&s, "e.obj:lamp");
    assert_int_equal(s.materials[id].kind, MAT_DIFFUSE);
    scene_free(&s);
    assert_int_equal(load("mesh e.obj emission 0\n", &s, err), 0);
    assert_int_equal(s.num_lights, 1);
    scene_free(&s);
}

static void test_light_triangle(void **state)
{
    (void)state;
    scene_t s;
    char err[512] = "";
    assert_int_equal(load("triangle 0 0 0 1 0 0 0 1 0 w\nlight triangle 0 0 1 1 0 1 0 1 1 radiance 1 1 1\n", &s, err), 0);
    assert_int_equal(s.num_lights, 2);
    assert_true(fabs(s.lights[1].flux.x - PREE_PI * 0.5) < 1e-12);
    scene_free(&s);
    assert_int_equal(load("triangle 0 0 0 1 0 0 0 1 0 w\nlight triangle 0 0 1 1 0 1 0 1 1 flux 7 7 7\n", &s, err), 0);
    assert_true(s.lights[1].flux.y == 7.0);
    scene_free(&s);
    assert_int_equal(load("triangle 0 0 0 1 0 0 0 1 0 w\nlight triangle 0 0 1 1 0 1 2 0 1 radiance 1 1 1\n", &s, err), -1);
    assert_non_null(strstr(err, "s:5: area light has no area"));
}

/* Each bad input: scene_load fails with one line naming the file (and line). */
static void expect_error(const char *body, const char *want)
{
    scene_t s;
    char err[512] = "";
    memset(&s, 0x5a, sizeof s);
    assert_int_equal(load(body, &s, err), -1);
    if (!strstr(err, want)) fail_msg("error '%s' does not contain '%s'", err, want);
    assert_null(strchr(err, '\n'));
}

static void test_bad_inputs(void **state)
{
    (void)state;
    put("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
    put("inf.obj", "v 0 0 0\nv 1 0 0\nv 1 -inf 0\nf 1 2 3\n");
    put("idx.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 -4\n");
    put("num.obj", "v 0 0 0\nv 1 0 0\nv 1 1e 0\nf 1 2 3\n");
    put("short.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2\n");
    put("nomtl.obj", "mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
    put("badmtl.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl a\nf 1 2 3\n");
    put("bad.mtl", "newmtl a\nKd 0.5 0.5 0.5 0.5\nKs 1 1 1\nNi x\n");
    put("usemtl.obj", "mtllib q.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl blue\nf 1 2 3\n");
    put("degen.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    put("empty.obj", "# nothing\nv 0 0 0\n");
    {
        char p[256];
        snprintf(p, sizeof p, "%s/bin.obj", dir);
        FILE *f = fopen(p, "wb");
        assert_non_null(f);
        assert_int_equal(fwrite("v 0 0 0\n\001\002\000\003", 1, 12, f), 12);
        fclose(f);
    }
    put("bad.ply", "this is no ply file\n");
    expect_error("mesh missing.obj\n", "s:4: ");
    expect_error("mesh missing.obj\n", "missing.obj: No such file");
    expect_error("mesh nan.obj\n", "nan.obj:3: coordinate 'nan' is not finite");
    expect_error("mesh inf.obj\n", "inf.obj:3: coordinate '-inf' is not finite");
    expect_error("mesh idx.obj\n", "idx.obj:4: face refers to vertex -4, but 3 are defined");
    expect_error("mesh num.obj\n", "num.obj:3: malformed number '1e'");
    expect_error("mesh short.obj\n", "short.obj:4: a face needs at least 3 vertices");
    expect_error("mesh nomtl.obj\n", "nomtl.obj:1: material library: ");
    expect_error("mesh badmtl.obj\n", "bad.mtl:2: 'Kd' needs 1 to 3 values, found 4");
    expect_error("mesh usemtl.obj\n", "usemtl.obj:5: material 'blue' is not defined");
    expect_error("mesh degen.obj material w\n", "degen.obj: no triangles (1 degenerate dropped");
    expect_error("mesh empty.obj material w\n", "empty.obj: no faces");
    expect_error("mesh bin.obj material w\n", "bin.obj:1: binary data");
    expect_error("mesh bad.ply material w\n", "bad.ply: ");
    expect_error("mesh q.obj material nope\n", "unknown material 'nope'");
    expect_error("mesh q.obj rotate w 90\n", "axis must be x, y or z");
    expect_error("mesh q.obj scale 0\n", "scale must not be zero");
    expect_error("mesh q.obj scale 1e300 translate 0 0 0\n", "not finite after the transform");
    expect_error("mesh q.obj frobnicate\n", "unexpected 'frobnicate'");
}

/* A bad mesh after a good one: the error leaves no half-built scene (scene_load frees all). */
static void test_error_after_good_mesh(void **state)
{
    (void)state;
    expect_error("mesh q.obj\nmesh nan.obj\n", "s:5: ");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quad_and_mtl),
        cmocka_unit_test(test_gzip_and_transform),
        cmocka_unit_test(test_overrides),
        cmocka_unit_test(test_emissive_area_light),
        cmocka_unit_test(test_light_triangle),
        cmocka_unit_test(test_bad_inputs),
        cmocka_unit_test(test_error_after_good_mesh),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
