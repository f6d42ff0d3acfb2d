// SPDX-License-Identifier: Apache-2.0
/* json_file.c: JSON files through jansson, written atomically (model/util/atomic_out.h). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "atomic_out.h"
#include "json_file.h"

int json_file_write(const char *path, json_t *v, char *err, size_t errlen)
{
    if (!v) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    char tmp[4096];
    int fd = atomic_out_begin(path, tmp, sizeof tmp, err, errlen);
    FILE *f = fd < 0 ? NULL : fdopen(fd, "w");
    if (!f) {
        if (fd >= 0) { snprintf(err, errlen, "%s: %s", path, strerror(errno)); close(fd); atomic_out_discard(tmp); }
        json_decref(v);
        return -1;
    }
    int bad = json_dumpf(v, f, PREE_JSON_FLAGS) != 0 || fputc('\n', f) == EOF;
    json_decref(v);
    int saved = errno;
    if (fclose(f) != 0) { bad = 1; saved = errno; }
    if (bad) {
        snprintf(err, errlen, "%s: %s", path, saved ? strerror(saved) : "write failed");
        atomic_out_discard(tmp);
        return -1;
    }
    return atomic_out_commit(tmp, path, err, errlen);   /* over a regular file only */
}

int json_file_print(FILE *f, json_t *v)
{
    if (!v) return -1;
    int rc = json_dumpf(v, f, JSON_REAL_PRECISION(17) | JSON_ENSURE_ASCII);
    json_decref(v);
    if (rc != 0 || fputc('\n', f) == EOF) return -1;
    return 0;
}

_Static_assert(sizeof(size_t) == 8 && sizeof(unsigned long long) == 8, "JF_U64 reads 8-byte members");

void json_set_fields(json_t *o, const void *base, const json_field_t *fields, size_t n)
{
    const char *b = base;
    for (size_t k = 0; k < n; k++) {
        const json_field_t *f = &fields[k];
        const char *p = b + f->off;
        uint64_t u;
        int i;
        long l;
        double d;
        char hex[17];
        json_t *v = NULL;
        switch (f->kind) {
        case JF_U64: memcpy(&u, p, 8); v = json_integer((json_int_t)u); break;
        case JF_INT: memcpy(&i, p, sizeof i); v = json_integer(i); break;
        case JF_LONG: memcpy(&l, p, sizeof l); v = json_integer(l); break;
        case JF_REAL: memcpy(&d, p, sizeof d); v = json_real(d); break;
        case JF_BOOL: memcpy(&i, p, sizeof i); v = json_boolean(i); break;
        case JF_HEX64:
            memcpy(&u, p, 8);
            snprintf(hex, sizeof hex, "%016llx", (unsigned long long)u);
            v = json_string(hex);
            break;
        }
        json_object_set_new(o, f->key, v);
    }
}

json_t *json_fields(const void *base, const json_field_t *fields, size_t n)
{
    json_t *o = json_object();
    if (o) json_set_fields(o, base, fields, n);
    return o;
}
