// SPDX-License-Identifier: Apache-2.0
/* atomic_out.c: temporaries beside their targets, renamed over regular files only, and a
 * signal-safe list of the live ones (atomic_out.h). */
#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "atomic_out.h"

#define SLOTS 16
#define TMP_MAX_LEN 4096

/* A slot is free (0), being filled or emptied (1), or holds a live temporary (2). */
static atomic_int slot_state[SLOTS];
static char slot_path[SLOTS][TMP_MAX_LEN];
static atomic_flag atexit_done = ATOMIC_FLAG_INIT;

static int set_err(char *err, size_t errlen, const char *path, const char *why)
{
    if (err && errlen) snprintf(err, errlen, "%s: %s", path, why);
    return -1;
}

void atomic_out_cleanup(void)
{
    for (int i = 0; i < SLOTS; i++)
        if (atomic_load(&slot_state[i]) == 2) unlink(slot_path[i]);
}

static void list_add(const char *tmp)
{
    if (!atomic_flag_test_and_set(&atexit_done)) atexit(atomic_out_cleanup);
    for (int i = 0; i < SLOTS; i++) {
        int expect = 0;
        if (atomic_compare_exchange_strong(&slot_state[i], &expect, 1)) {
            snprintf(slot_path[i], TMP_MAX_LEN, "%s", tmp);
            atomic_store(&slot_state[i], 2);
            return;
        }
    }   /* more than SLOTS at once: that one is still removed on every error path */
}

static void list_remove(const char *tmp)
{
    for (int i = 0; i < SLOTS; i++) {
        int expect = 2;
        if (atomic_load(&slot_state[i]) == 2 && !strcmp(slot_path[i], tmp) &&
            atomic_compare_exchange_strong(&slot_state[i], &expect, 1)) {
            atomic_store(&slot_state[i], 0);
            return;
        }
    }
}

int atomic_out_target_ok(const char *path, char *err, size_t errlen)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return errno == ENOENT ? 0 : set_err(err, errlen, path, strerror(errno));
    if (S_ISREG(st.st_mode)) return 0;
    return set_err(err, errlen, path, S_ISDIR(st.st_mode) ? "is a directory"
               : S_ISLNK(st.st_mode) ? "is a symbolic link (outputs replace regular files only; name its target)"
               : "not a regular file (outputs are written atomically and never replace a device, FIFO or socket)");
}

int atomic_out_begin(const char *path, char *tmp, size_t tmplen, char *err, size_t errlen)
{
    static atomic_uint counter;
    const char *slash = strrchr(path, '/');
    int dirlen = slash ? (int)(slash - path + 1) : 0;
    if (!*(slash ? slash + 1 : path)) return set_err(err, errlen, path, "not a file name");
    for (int tries = 0; tries < 100; tries++) {
        unsigned n = atomic_fetch_add(&counter, 1);
        int len = snprintf(tmp, tmplen, "%.*s.pree.tmp-%ld-%u", dirlen, path, (long)getpid(), n);
        if (len < 0 || (size_t)len >= tmplen || len >= TMP_MAX_LEN) return set_err(err, errlen, path, "path too long");
        int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) { list_add(tmp); return fd; }
        if (errno != EEXIST) {
            if (err && errlen)
                snprintf(err, errlen, "%s: cannot create a temporary file beside it: %s", path, strerror(errno));
            return -1;
        }
    }
    return set_err(err, errlen, path, "cannot find a free temporary file name");
}

int atomic_out_commit(const char *tmp, const char *path, char *err, size_t errlen)
{
    int rc = atomic_out_target_ok(path, err, errlen);
    if (rc == 0 && rename(tmp, path) != 0) {
        if (err && errlen)
            snprintf(err, errlen, "%s: cannot rename the finished temporary file over it: %s", path, strerror(errno));
        rc = -1;
    }
    if (rc) unlink(tmp);
    list_remove(tmp);
    return rc;
}

void atomic_out_discard(const char *tmp)
{
    unlink(tmp);
    list_remove(tmp);
}
