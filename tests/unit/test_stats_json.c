// SPDX-License-Identifier: Apache-2.0
/* test_stats_json.c: the statistics file written through jansson and read back with it: every
 * key and value survives, strings that need escaping (quotes, backslashes, control bytes, an
 * escape sequence, UTF-8) come back byte for byte, doubles round-trip exactly, and a write that
 * cannot happen reports the path and leaves no file behind. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "json_file.h"
#include "stats_json.h"

static char dir[64];

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/pree-test-json.XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd);
}

static void fill(render_options_t *opt, render_stats_t *st)
{
    memset(opt, 0, sizeof *opt);
    memset(st, 0, sizeof *st);
    opt->width = 320; opt->height = 240; opt->precision = PRECISION_FP32; opt->datapath = DATAPATH_STABLE;
    opt->grid = GRID_CELLS; opt->photon_offset = 123456789012ull;
    st->hit_points = 152046; st->upd.accepted = 3536147; st->upd.candidates = 1ull << 40;
    st->r0 = 0.1 / 3; st->sec_total = 1e-7;
    st->image_hash = 0x0123456789abcdefull; st->state_hash = 0xfedcba9876543210ull;
}

static void test_round_trip(void **state)
{
    (void)state;
    static const char scene[] = "we\"ird\\ \x01\x1b[31m name \xc3\xa9\t\n/x.scene";
    render_options_t opt;
    render_stats_t st;
    fill(&opt, &st);
    char path[128], err[256];
    snprintf(path, sizeof path, "%s/s.json", dir);
    assert_int_equal(stats_json_write(path, scene, &opt, &st, 1, err, sizeof err), 0);

    json_error_t jerr;
    json_t *o = json_load_file(path, 0, &jerr);
    if (!o) fail_msg("%s:%d: %s", path, jerr.line, jerr.text);
    assert_string_equal(json_string_value(json_object_get(o, "scene")), scene);
    assert_int_equal(json_integer_value(json_object_get(o, "hit_points")), 152046);
    assert_int_equal(json_integer_value(json_object_get(o, "hpuo_accepted")), 3536147);
    assert_int_equal(json_integer_value(json_object_get(o, "hpuo_candidates")), 1ll << 40);
    assert_int_equal(json_integer_value(json_object_get(o, "photon_offset")), 123456789012ll);
    assert_true(json_real_value(json_object_get(o, "initial_radius")) == 0.1 / 3);
    assert_true(json_real_value(json_object_get(json_object_get(o, "seconds"), "total")) == 1e-7);
    assert_string_equal(json_string_value(json_object_get(o, "image_hash")), "0123456789abcdef");
    assert_string_equal(json_string_value(json_object_get(o, "state_hash")), "fedcba9876543210");
    assert_string_equal(json_string_value(json_object_get(o, "datapath")), "stable");
    assert_true(json_is_true(json_object_get(o, "interrupted")));
    assert_true(json_is_true(json_object_get(o, "skips")));
    json_decref(o);

    /* The file itself is pure ASCII: the control bytes and the escape sequence are escaped. */
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    for (int c; (c = fgetc(f)) != EOF;)
        if (c != '\n' && (c < 0x20 || c > 0x7e)) fail_msg("byte 0x%02x in the JSON file", c);
    fclose(f);
}

static void test_unwritable(void **state)
{
    (void)state;
    render_options_t opt;
    render_stats_t st;
    fill(&opt, &st);
    char path[128], err[256] = "";
    snprintf(path, sizeof path, "%s/missing/s.json", dir);
    assert_int_equal(stats_json_write(path, "x", &opt, &st, 0, err, sizeof err), -1);
    assert_non_null(strstr(err, path));
    /* Nothing but the earlier test's file in the directory: no temporary left over. */
    DIR *d = opendir(dir);
    assert_non_null(d);
    for (struct dirent *e; (e = readdir(d));)
        if (strstr(e->d_name, ".tmp")) fail_msg("temporary file %s left behind", e->d_name);
    closedir(d);
    /* A NULL value (a failed allocation while building it) is an error, not a crash. */
    snprintf(path, sizeof path, "%s/n.json", dir);
    assert_int_equal(json_file_write(path, NULL, err, sizeof err), -1);
    assert_int_equal(access(path, F_OK), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_unwritable),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
