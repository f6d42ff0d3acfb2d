/* json_file.h: the engine's JSON files, written through jansson: indented, keys in insertion
 * order, reals with 17 significant digits (enough to read the same double back), every string
 * escaped by the library. */
#ifndef PREE_JSON_FILE_H
#define PREE_JSON_FILE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <jansson.h>

/* The dump flags every writer uses. */
#define PREE_JSON_FLAGS (JSON_INDENT(2) | JSON_REAL_PRECISION(17) | JSON_ENSURE_ASCII)

/* Write v to path atomically (a temporary file beside it, renamed into place) and release v.
 * Returns 0, or -1 with a one-line message naming the file in err. A NULL v (a failed
 * allocation while building it) is reported as out of memory. */
int json_file_write(const char *path, json_t *v, char *err, size_t errlen);
/* Print v to f on one line (for a program's standard output), a newline after it, and release
 * v; 0, or -1. */
int json_file_print(FILE *f, json_t *v);

/* Builders that tolerate a NULL container (json_object_set_new releases the value then). */
static inline void json_set_u64(json_t *o, const char *key, uint64_t v)
{
    json_object_set_new(o, key, json_integer((json_int_t)v));
}
static inline void json_set_real(json_t *o, const char *key, double v)
{
    json_object_set_new(o, key, json_real(v));
}
static inline void json_set_str(json_t *o, const char *key, const char *v)
{
    json_object_set_new(o, key, json_string(v));
}
static inline void json_set_bool(json_t *o, const char *key, int v)
{
    json_object_set_new(o, key, json_boolean(v));
}

#endif
