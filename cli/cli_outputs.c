// SPDX-License-Identifier: Apache-2.0
/* cli_outputs.c: the checks on output paths before any work (cli_outputs.h). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "atomic_out.h"
#include "cli_outputs.h"

#define TMP_SUFFIX_MAX 40   /* ".pree.tmp-<pid>-<n>" */

typedef struct {
    struct stat dir, file;
    int exists;
    const char *name;   /* the last component */
} out_id_t;

/* Check one output and fill its identity; 0, or 1 with the error printed. */
static int check_one(const char *cmd, const cli_file_t *o, out_id_t *id)
{
    const char *p = o->path, *slash = strrchr(p, '/');
    char dir[PATH_MAX], err[PATH_MAX + 256];
    id->name = slash ? slash + 1 : p;
    size_t dirlen = slash ? (size_t)(slash - p) + 1 : 0;
    const char *why = NULL;
    if (!*id->name) why = "not a file name";
    else if (strlen(id->name) > NAME_MAX) why = "the name is longer than the file system's 255 bytes";
    else if (dirlen + TMP_SUFFIX_MAX >= sizeof dir || strlen(p) >= PATH_MAX) why = "the path is too long";
    if (why) { fprintf(stderr, "pree %s: %s %s: %s\n", cmd, o->what, p, why); return 1; }
    if (dirlen) snprintf(dir, sizeof dir, "%.*s", (int)dirlen, p);
    else snprintf(dir, sizeof dir, ".");
    int e = stat(dir, &id->dir) != 0 ? errno : S_ISDIR(id->dir.st_mode) ? 0 : ENOTDIR;
    if (e) {
        fprintf(stderr, "pree %s: %s %s: the directory '%s' %s\n", cmd, o->what, p, dir,
                e == ENOENT ? "does not exist" : strerror(e));
        return 1;
    }
    if (access(dir, W_OK | X_OK) != 0) {
        fprintf(stderr, "pree %s: %s %s: cannot write in '%s': %s\n", cmd, o->what, p, dir, strerror(errno));
        return 1;
    }
    if (atomic_out_target_ok(p, err, sizeof err)) { fprintf(stderr, "pree %s: %s %s\n", cmd, o->what, err); return 1; }
    /* The temporary the write will use, made and removed: catches what access() cannot (a
     * directory such as /proc that takes no new file, a read-only mount for root). */
    char tmp[PATH_MAX + TMP_SUFFIX_MAX + 8];
    int fd = atomic_out_begin(p, tmp, sizeof tmp, err, sizeof err);
    if (fd < 0) { fprintf(stderr, "pree %s: %s %s\n", cmd, o->what, err); return 1; }
    close(fd);
    atomic_out_discard(tmp);
    id->exists = stat(p, &id->file) == 0;
    return 0;
}

static int same_file(const struct stat *a, const struct stat *b)
{
    return a->st_dev == b->st_dev && a->st_ino == b->st_ino;
}

int cli_outputs_check(const char *cmd, const cli_file_t *in, int nin, const cli_file_t *out, int nout)
{
    out_id_t id[16];
    if (nout > 16) { fprintf(stderr, "pree %s: more than 16 outputs\n", cmd); return 1; }
    for (int k = 0; k < nout; k++) {
        if (check_one(cmd, &out[k], &id[k])) return 1;
        for (int i = 0; i < nin && id[k].exists; i++) {
            struct stat st;
            if (stat(in[i].path, &st) == 0 && same_file(&st, &id[k].file)) {
                fprintf(stderr, "pree %s: %s %s: the same file as %s %s (an input would be overwritten)\n", cmd,
                        out[k].what, out[k].path, in[i].what, in[i].path);
                return 1;
            }
        }
        for (int j = 0; j < k; j++) {
            if ((same_file(&id[j].dir, &id[k].dir) && !strcmp(id[j].name, id[k].name)) ||
                (id[j].exists && id[k].exists && same_file(&id[j].file, &id[k].file))) {
                fprintf(stderr, "pree %s: %s %s: the same file as %s %s\n", cmd, out[k].what, out[k].path,
                        out[j].what, out[j].path);
                return 1;
            }
        }
    }
    return 0;
}
