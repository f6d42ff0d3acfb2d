// SPDX-License-Identifier: Apache-2.0
/* test_atomic_out.c: outputs through a temporary beside the target (model/util/atomic_out.c):
 * committed over a regular file or nothing, refused over a device, a directory or a link;
 * discarded and listed temporaries removed (atomic_out_cleanup, as at exit). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "atomic_out.h"

static char dir[64];

static int count_temps(void)
{
    int n = 0;
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d));) n += strstr(e->d_name, ".pree.tmp-") != NULL;
    if (d) closedir(d);
    return n;
}

static void write_via(const char *path, const char *text, int expect_rc)
{
    char tmp[4096], err[512];
    int fd = atomic_out_begin(path, tmp, sizeof tmp, err, sizeof err);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, text, strlen(text)), (int)strlen(text));
    close(fd);
    assert_int_equal(atomic_out_commit(tmp, path, err, sizeof err), expect_rc);
}

static void test_commit_and_refuse(void **state)
{
    (void)state;
    char path[128], link_path[128], err[512], buf[16] = {0};
    snprintf(path, sizeof path, "%s/out.txt", dir);
    write_via(path, "one", 0);
    write_via(path, "two", 0);   /* over a regular file */
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    assert_int_equal(fread(buf, 1, sizeof buf - 1, f), 3);
    fclose(f);
    assert_string_equal(buf, "two");
    assert_int_equal(atomic_out_target_ok("/dev/null", err, sizeof err), -1);
    assert_non_null(strstr(err, "/dev/null: not a regular file"));
    assert_int_equal(atomic_out_target_ok(dir, err, sizeof err), -1);
    assert_non_null(strstr(err, "is a directory"));
    snprintf(link_path, sizeof link_path, "%s/link.txt", dir);
    assert_int_equal(symlink(path, link_path), 0);
    write_via(link_path, "three", -1);   /* refused, the temporary removed */
    struct stat st;
    assert_int_equal(lstat(link_path, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_int_equal(count_temps(), 0);
    unlink(link_path);
    unlink(path);
}

static void test_cleanup(void **state)
{
    (void)state;
    char path[512], tmp[2][4096], err[512];
    snprintf(path, sizeof path, "%s/%0250d.png", dir, 7);   /* a 254-byte name: the temporary is short */
    for (int k = 0; k < 2; k++) {
        int fd = atomic_out_begin(path, tmp[k], sizeof tmp[k], err, sizeof err);
        assert_true(fd >= 0);
        close(fd);
    }
    assert_int_equal(count_temps(), 2);
    atomic_out_discard(tmp[0]);
    assert_int_equal(count_temps(), 1);
    atomic_out_cleanup();
    assert_int_equal(count_temps(), 0);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/pree-test-atomic-XXXXXX");
    if (!mkdtemp(dir)) return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_commit_and_refuse),
        cmocka_unit_test(test_cleanup),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    rmdir(dir);
    return rc;
}
