// SPDX-License-Identifier: Apache-2.0
/* test_image.c: image buffers, smallppm's tone map, the exact PPM bytes, PNG/EXR round trips,
 * and atomic writes that leave nothing behind when they fail. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image.h"

/* A fresh scratch directory per test, removed with its contents afterwards. */
static int make_dir(void **state)
{
    char *dir = strdup("/tmp/pree-test-image-XXXXXX");
    assert_non_null(mkdtemp(dir));
    *state = dir;
    return 0;
}

static int remove_dir(void **state)
{
    char *dir = *state, cmd[256];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    int rc = system(cmd);
    free(dir);
    return rc;
}

/* Number of directory entries other than . and .. */
static int count_entries(const char *dir)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
    closedir(d);
    return n;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    char *buf = malloc(1 << 16);
    *len = fread(buf, 1, 1 << 16, f);
    fclose(f);
    return buf;
}

/* The file at path holds exactly the text want. */
static void expect_file(const char *path, const char *want)
{
    size_t len;
    char *got = slurp(path, &len);
    assert_int_equal(len, strlen(want));
    assert_memory_equal(got, want, len);
    free(got);
}

/* Values worked out by hand from int(pow(1-exp(-L), 1/2.2)*255 + .5). */
static void test_tonemap_known_values(void **state)
{
    (void)state;
    assert_int_equal(pree_tonemap8(0.0), 0);
    assert_int_equal(pree_tonemap8(1e-6), 0);      /* 0.00189^... * 255 = 0.48 -> 0 */
    assert_int_equal(pree_tonemap8(1e-3), 11);
    assert_int_equal(pree_tonemap8(0.5), 167);
    assert_int_equal(pree_tonemap8(1.0), 207);     /* 0.63212^(1/2.2) = 0.81182 -> 207.5 -> 207 */
    assert_int_equal(pree_tonemap8(2.0), 239);
    assert_int_equal(pree_tonemap8(100.0), 255);
    assert_int_equal(pree_tonemap8(INFINITY), 255);
    assert_int_equal(pree_tonemap8(-1.0), 0);      /* outside smallppm's domain: guarded */
    assert_int_equal(pree_tonemap8(NAN), 0);
    /* Monotone over a sweep, and always 0..255. */
    int prev = 0;
    for (double L = 0.0; L < 20.0; L += 1e-3) {
        int v = pree_tonemap8(L);
        assert_true(v >= prev && v <= 255);
        prev = v;
    }
}

/* smallppm's ASCII layout, byte for byte, for a 2x1 image. */
static void test_ppm_exact_bytes(void **state)
{
    char path[256];
    snprintf(path, sizeof path, "%s/two.ppm", (char *)*state);
    const double rgb[6] = {0.0, INFINITY, 1.0, 0.5, 2.0, 1e-3};
    char err[512] = "";
    assert_int_equal(pree_image_write(path, 2, 1, rgb, err, sizeof err), 0);
    expect_file(path, "P3\n2 1\n255\n0 255 207 167 239 11 ");
    assert_int_equal(count_entries(*state), 1);   /* the temporary file is gone */
}

static void test_ppm_u8_bytes(void **state)
{
    char path[256];
    snprintf(path, sizeof path, "%s/u8.ppm", (char *)*state);
    const unsigned char rgb[6] = {0, 9, 10, 99, 100, 255};
    char err[512] = "";
    assert_int_equal(pree_image_write_u8(path, 1, 2, rgb, err, sizeof err), 0);
    expect_file(path, "P3\n1 2\n255\n0 9 10 99 100 255 ");
}

/* A 13x7 gradient written as .ppm, .png and .exr reads back as tone-mapped bytes / floats. */
static void test_round_trips(void **state)
{
    enum { W = 13, H = 7 };
    double rgb[W * H * 3];
    for (int i = 0; i < W * H * 3; i++) rgb[i] = 0.037 * i + (i % 3) * 0.5;   /* >= 0 */
    const char *exts[] = {"ppm", "png", "PNG", "exr"};
    for (int e = 0; e < 4; e++) {
        char path[256], err[512] = "";
        snprintf(path, sizeof path, "%s/rt.%s", (char *)*state, exts[e]);
        assert_int_equal(pree_image_write(path, W, H, rgb, err, sizeof err), 0);
        pree_image_t img = {0};
        assert_int_equal(pree_image_read(path, &img, err, sizeof err), 0);
        assert_int_equal(img.width, W);
        assert_int_equal(img.height, H);
        int is_exr = e == 3;
        assert_int_equal(img.samples, is_exr ? PREE_SAMPLES_FLOAT : PREE_SAMPLES_U8);
        for (int i = 0; i < W * H * 3; i++) {
            float want = is_exr ? (float)rgb[i] : (float)pree_tonemap8(rgb[i]);
            assert_true(img.rgb[i] == want);
        }
        pree_image_free(&img);
        assert_null(img.rgb);
    }
    assert_int_equal(count_entries(*state), 4);   /* rt.ppm rt.png rt.PNG rt.exr, no temporaries */
}

/* The same pixels give the same file bytes: no time stamp in the EXR header. */
static void test_files_reproducible(void **state)
{
    const double rgb[3 * 6] = {0.1, 0.2, 0.3, 1.0, 2.0, 3.0, 0.0, 0.5, 7.0, 0.25, 0.125, 1e-4, 9.0, 0.0, 1.0, 0.3, 0.3, 0.3};
    const char *exts[] = {"png", "exr"};
    for (int e = 0; e < 2; e++) {
        char p1[256], p2[256], err[512] = "";
        snprintf(p1, sizeof p1, "%s/one.%s", (char *)*state, exts[e]);
        snprintf(p2, sizeof p2, "%s/two.%s", (char *)*state, exts[e]);
        assert_int_equal(pree_image_write(p1, 3, 2, rgb, err, sizeof err), 0);
        assert_int_equal(pree_image_write(p2, 3, 2, rgb, err, sizeof err), 0);
        size_t n1, n2;
        char *b1 = slurp(p1, &n1), *b2 = slurp(p2, &n2);
        assert_int_equal(n1, n2);
        assert_memory_equal(b1, b2, n1);
        assert_null(memmem(b1, n1, "DateTime", 8));
        free(b1);
        free(b2);
    }
}

/* Failing writes return -1, name the file, and leave no file and no temporary behind. */
static void test_atomic_failures(void **state)
{
    const char *dir = *state;
    const double rgb[3 * 12] = {0};
    char path[256], err[512];

    /* Directory missing: nothing can be created. */
    snprintf(path, sizeof path, "%s/missing/x.ppm", dir);
    err[0] = 0;
    assert_int_equal(pree_image_write(path, 2, 2, rgb, err, sizeof err), -1);
    assert_non_null(strstr(err, path));
    assert_null(strchr(err, '\n'));
    assert_int_equal(access(path, F_OK), -1);

    /* The destination is a directory: every format writes its temporary, the rename fails,
     * and the temporary is removed. */
    const char *exts[] = {"ppm", "png", "exr"};
    for (int e = 0; e < 3; e++) {
        snprintf(path, sizeof path, "%s/blocked.%s", dir, exts[e]);
        assert_int_equal(mkdir(path, 0755), 0);
        err[0] = 0;
        assert_int_equal(pree_image_write(path, 3, 4, rgb, err, sizeof err), -1);
        assert_non_null(strstr(err, path));
    }
    assert_int_equal(count_entries(dir), 3);   /* only the three blocking directories */

    /* Unknown extension, no extension, bad sizes: refused before anything is created. */
    snprintf(path, sizeof path, "%s/x.tiff", dir);
    assert_int_equal(pree_image_write(path, 2, 2, rgb, err, sizeof err), -1);
    assert_non_null(strstr(err, "x.tiff"));
    snprintf(path, sizeof path, "%s/noext", dir);
    assert_int_equal(pree_image_write(path, 2, 2, rgb, err, sizeof err), -1);
    snprintf(path, sizeof path, "%s/zero.png", dir);
    assert_int_equal(pree_image_write(path, 0, 2, rgb, err, sizeof err), -1);
    assert_int_equal(pree_image_write(path, 2, -1, rgb, err, sizeof err), -1);
    assert_int_equal(pree_image_write(path, 100000, 100000, rgb, err, sizeof err), -1);
    assert_int_equal(count_entries(dir), 3);
}

/* A failed write leaves an existing destination exactly as it was. */
static void test_failed_write_keeps_old_file(void **state)
{
    char path[256], err[512];
    snprintf(path, sizeof path, "%s/keep.ppm", (char *)*state);
    const double one[3] = {1.0, 1.0, 1.0};
    assert_int_equal(pree_image_write(path, 1, 1, one, err, sizeof err), 0);
    assert_int_equal(pree_image_write(path, 0, 1, one, err, sizeof err), -1);
    expect_file(path, "P3\n1 1\n255\n207 207 207 ");
}

/* Reading dir/name, with content written there first (NULL: no file), fails with a one-line
 * message that names the file and leaves no image. */
static void expect_read_error(const char *dir, const char *name, const char *content)
{
    char path[256], err[512] = "";
    pree_image_t img = {0};
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (content) {
        FILE *f = fopen(path, "wb");
        assert_non_null(f);
        fputs(content, f);
        fclose(f);
    }
    assert_int_equal(pree_image_read(path, &img, err, sizeof err), -1);
    assert_null(img.rgb);
    assert_non_null(strstr(err, path));
    assert_null(strchr(err, '\n'));
}

static void test_read_errors(void **state)
{
    expect_read_error(*state, "absent.png", NULL);
    expect_read_error(*state, "junk.png", "this is not a png\n");          /* not an image at all */
    expect_read_error(*state, "short.ppm", "P3\n4 4\n255\n1 2 3 4 5 6 ");   /* pixels stop early */
}

static void put_file(const char *dir, const char *name, const void *data, size_t len, char *path)
{
    sprintf(path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, len, f), len);
    fclose(f);
}

/* PNM files read in C: ASCII and binary, colour and grey, 8 and 16 bits, comments. */
static void test_read_pnm(void **state)
{
    char path[256], err[512] = "";
    pree_image_t img = {0};
    const float want[6] = {0, 9, 10, 99, 100, 255};

    const char p3[] = "P3 # comment\n# another\n 1 2\n255\n0 9 10\n99 100 255";
    put_file(*state, "a.ppm", p3, sizeof p3 - 1, path);
    assert_int_equal(pree_image_read(path, &img, err, sizeof err), 0);
    assert_int_equal(img.width, 1);
    assert_int_equal(img.height, 2);
    assert_int_equal(img.samples, PREE_SAMPLES_U8);
    assert_memory_equal(img.rgb, want, sizeof want);
    pree_image_free(&img);

    const unsigned char p6[] = {'P', '6', '\n', '2', ' ', '1', '\n', '2', '5', '5', '\n', 0, 9, 10, 99, 100, 255};
    put_file(*state, "b.ppm", p6, sizeof p6, path);
    assert_int_equal(pree_image_read(path, &img, err, sizeof err), 0);
    assert_int_equal(img.width, 2);
    assert_int_equal(img.samples, PREE_SAMPLES_U8);
    assert_memory_equal(img.rgb, want, sizeof want);
    pree_image_free(&img);

    const unsigned char p5[] = {'P', '5', ' ', '2', ' ', '1', ' ', '6', '5', '5', '3', '5', '\n', 0x01, 0x02, 0xff, 0xff};
    put_file(*state, "c.pgm", p5, sizeof p5, path);
    assert_int_equal(pree_image_read(path, &img, err, sizeof err), 0);
    assert_int_equal(img.samples, PREE_SAMPLES_U16);
    const float grey[6] = {258, 258, 258, 65535, 65535, 65535};
    assert_memory_equal(img.rgb, grey, sizeof grey);
    pree_image_free(&img);

    const char p2[] = "P2\n1 1\n255\n7\n";
    put_file(*state, "d.pgm", p2, sizeof p2 - 1, path);
    assert_int_equal(pree_image_read(path, &img, err, sizeof err), 0);
    assert_true(img.rgb[0] == 7.0f && img.rgb[1] == 7.0f && img.rgb[2] == 7.0f);
    pree_image_free(&img);

    /* Refused: truncated binary, a sample above maxval, another maxval, a bad header. */
    const char *bad[] = {"P6\n2 1\n255\nabcde", "P3\n1 1\n255\n1 2 256", "P3\n1 1\n100\n1 2 3",
                         "P3\n1 x\n255\n1 2 3", "P3\n0 1\n255\n", "P3\n1 1\n255\n1 2"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        put_file(*state, "bad.ppm", bad[k], strlen(bad[k]), path);
        err[0] = 0;
        assert_int_equal(pree_image_read(path, &img, err, sizeof err), -1);
        assert_null(img.rgb);
        assert_non_null(strstr(err, path));
    }
}

static void test_alloc(void **state)
{
    (void)state;
    pree_image_t img;
    char err[256];
    assert_int_equal(pree_image_alloc(&img, 4, 3, err, sizeof err), 0);
    for (int i = 0; i < 36; i++) assert_true(img.rgb[i] == 0.0f);
    pree_image_free(&img);
    assert_int_equal(pree_image_alloc(&img, 0, 3, err, sizeof err), -1);
    assert_null(img.rgb);
    pree_accum_t acc;
    assert_int_equal(pree_accum_alloc(&acc, 2, 2, err, sizeof err), 0);
    assert_true(acc.rgb[11] == 0.0);
    pree_accum_free(&acc);
    assert_int_equal(pree_accum_alloc(&acc, 70000, 70000, err, sizeof err), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tonemap_known_values),
        cmocka_unit_test_setup_teardown(test_ppm_exact_bytes, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(test_ppm_u8_bytes, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(test_round_trips, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(test_files_reproducible, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(test_atomic_failures, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(test_failed_write_keeps_old_file, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(test_read_errors, make_dir, remove_dir),
        cmocka_unit_test_setup_teardown(test_read_pnm, make_dir, remove_dir),
        cmocka_unit_test(test_alloc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
