/* json_file.c: JSON files through jansson, written atomically (see json_file.h). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "json_file.h"

int json_file_write(const char *path, json_t *v, char *err, size_t errlen)
{
    if (!v) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    char tmp[4096];
    int len = snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, (long)getpid());
    if (len < 0 || (size_t)len >= sizeof tmp) {
        snprintf(err, errlen, "%s: path too long", path);
        json_decref(v);
        return -1;
    }
    FILE *f = fopen(tmp, "w");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        json_decref(v);
        return -1;
    }
    int bad = json_dumpf(v, f, PREE_JSON_FLAGS) != 0 || fputc('\n', f) == EOF;
    json_decref(v);
    int saved = errno;
    if (fclose(f) != 0) { bad = 1; saved = errno; }
    if (!bad && rename(tmp, path) != 0) { bad = 1; saved = errno; }
    if (bad) {
        snprintf(err, errlen, "%s: %s", path, saved ? strerror(saved) : "write failed");
        unlink(tmp);
        return -1;
    }
    return 0;
}

int json_file_print(FILE *f, json_t *v)
{
    if (!v) return -1;
    int rc = json_dumpf(v, f, JSON_REAL_PRECISION(17) | JSON_ENSURE_ASCII);
    json_decref(v);
    if (rc != 0 || fputc('\n', f) == EOF) return -1;
    return 0;
}
