// SPDX-License-Identifier: Apache-2.0
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

/* A struct's members as JSON values, from a table: {key, kind, offsetof(type, member)}.
 * JF_U64 reads a 64-bit unsigned member (uint64_t, unsigned long long or size_t), JF_INT an
 * int, JF_LONG a long, JF_REAL a double, JF_BOOL an int (0 false), JF_HEX64 a uint64_t as
 * 16 hex digits in a string (the hashes). */
typedef enum { JF_U64, JF_INT, JF_LONG, JF_REAL, JF_BOOL, JF_HEX64 } json_field_kind_t;
typedef struct {
    const char *key;
    json_field_kind_t kind;
    size_t off;
} json_field_t;
#define JSON_FIELD(type, member, kind) {#member, kind, offsetof(type, member)}
#define JSON_FIELD_AS(type, member, kind, key) {key, kind, offsetof(type, member)}

/* Set each field of base (a struct) in o, in table order. */
void json_set_fields(json_t *o, const void *base, const json_field_t *fields, size_t n);
/* A new object holding those fields (NULL when out of memory). */
json_t *json_fields(const void *base, const json_field_t *fields, size_t n);

#endif
