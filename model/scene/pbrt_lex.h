// SPDX-License-Identifier: Apache-2.0
/* pbrt_lex.h: the tokens of a pbrt-v4 scene file (scene_pbrt.c), across Include/Import: words
 * (directives, true/false), quoted strings, numbers, [ and ]; `#` starts a comment. Every token
 * knows its file and line, for errors "FILE:LINE: ...". Directives read their parameter lists
 * ("type name" value or [values]) with pbrt_params_read. */
#ifndef PREE_PBRT_LEX_H
#define PREE_PBRT_LEX_H

#include <stddef.h>

#define PBRT_INCLUDE_DEPTH 16
#define PBRT_PARAMS_MAX 48

typedef enum { PT_EOF = 0, PT_WORD, PT_STRING, PT_NUMBER, PT_LBRACKET, PT_RBRACKET } pbrt_tok_kind_t;

typedef struct {
    pbrt_tok_kind_t kind;
    char text[256];          /* the word or string (strings longer than this are refused) */
    double num;
    const char *file;
    int line;
} pbrt_tok_t;

typedef struct {
    char *text;
    size_t len, pos;
    int line;
    char path[4096];
} pbrt_src_t;

typedef struct {
    pbrt_src_t src[PBRT_INCLUDE_DEPTH];
    int depth;               /* sources open; 0 at the end */
    pbrt_tok_t peeked;
    int has_peek;
    char *err;
    size_t errlen;
} pbrt_lex_t;

/* One parameter: "TYPE NAME" and its values (numbers, or strings for string/texture/spectrum
 * names, or bools as 0/1 numbers). */
typedef struct {
    char type[24], name[64];
    double *num;
    char (*str)[256];
    int n, cap, is_str, used;
    const char *file;
    int line;
} pbrt_param_t;

typedef struct {
    pbrt_param_t p[PBRT_PARAMS_MAX];
    int n;
} pbrt_params_t;

/* Open the top file: 0, or -1 with "PATH: why" in err. */
int pbrt_lex_open(pbrt_lex_t *lx, const char *path, char *err, size_t errlen);
/* Push an included file, relative to the including one's folder: 0, or -1 with err. */
int pbrt_lex_include(pbrt_lex_t *lx, const pbrt_tok_t *at, const char *name);
void pbrt_lex_close(pbrt_lex_t *lx);
/* The next token (PT_EOF at the end of the top file); -1 with err on a lexical error. */
int pbrt_lex_next(pbrt_lex_t *lx, pbrt_tok_t *t);
int pbrt_lex_peek(pbrt_lex_t *lx, pbrt_tok_t *t);
/* Format "FILE:LINE: message" (at: the token where it went wrong) into err; returns -1. */
int pbrt_fail(pbrt_lex_t *lx, const pbrt_tok_t *at, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* The parameter list after a directive (until the next word): 0, or -1 with err (ps then empty). */
int pbrt_params_read(pbrt_lex_t *lx, pbrt_params_t *ps);
void pbrt_params_free(pbrt_params_t *ps);
/* The parameter NAME (marked used), or NULL. */
pbrt_param_t *pbrt_param(pbrt_params_t *ps, const char *name);

#endif
