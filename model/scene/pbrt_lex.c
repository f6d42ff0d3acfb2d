// SPDX-License-Identifier: Apache-2.0
/* pbrt_lex.c: tokens and parameter lists of pbrt-v4 scene files (pbrt_lex.h). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "file_in.h"
#include "pbrt_lex.h"
#include "text_escape.h"

#define PBRT_FILE_MAX (1LL << 30)

static int read_all(pbrt_src_t *s, const char *path, char *err, size_t errlen)
{
    FILE *f = file_in_open(path, PBRT_FILE_MAX, err, errlen);
    if (!f) return -1;
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap + 1);
    for (size_t got; buf && (got = fread(buf + len, 1, cap - len, f)) > 0;) {
        len += got;
        if (len == cap) {
            char *nb = realloc(buf, 2 * cap + 1);
            if (!nb) { free(buf); buf = NULL; break; }
            buf = nb;
            cap *= 2;
        }
    }
    const int bad = !buf || ferror(f);
    fclose(f);
    if (bad) { free(buf); snprintf(err, errlen, "%s: %s", path, buf ? "read error" : "out of memory"); return -1; }
    buf[len] = 0;
    if (memchr(buf, 0, len)) { free(buf); snprintf(err, errlen, "%s: binary data (a NUL byte)", path); return -1; }
    *s = (pbrt_src_t){.text = buf, .len = len, .pos = 0, .line = 1};
    snprintf(s->path, sizeof s->path, "%s", path);
    return 0;
}

int pbrt_lex_open(pbrt_lex_t *lx, const char *path, char *err, size_t errlen)
{
    memset(lx, 0, sizeof *lx);
    lx->err = err;
    lx->errlen = errlen;
    if (read_all(&lx->src[0], path, err, errlen)) return -1;
    lx->depth = 1;
    return 0;
}

int pbrt_lex_include(pbrt_lex_t *lx, const pbrt_tok_t *at, const char *name)
{
    if (lx->depth == PBRT_INCLUDE_DEPTH)
        return pbrt_fail(lx, at, "Include: more than %d files deep (an Include loop?)", PBRT_INCLUDE_DEPTH);
    char path[4096];
    const char *slash = strrchr(at->file, '/');
    if (name[0] == '/' || !slash) snprintf(path, sizeof path, "%s", name);
    else snprintf(path, sizeof path, "%.*s/%s", (int)(slash - at->file), at->file, name);
    char e[4400];
    if (read_all(&lx->src[lx->depth], path, e, sizeof e)) return pbrt_fail(lx, at, "Include: %s", e);
    lx->depth++;
    return 0;
}

void pbrt_lex_close(pbrt_lex_t *lx)
{
    for (int k = 0; k < PBRT_INCLUDE_DEPTH; k++) free(lx->src[k].text);
    memset(lx->src, 0, sizeof lx->src);
    lx->depth = 0;
}

int pbrt_fail(pbrt_lex_t *lx, const pbrt_tok_t *at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    text_error_at(lx->err, lx->errlen, at->file, at->line, fmt, ap);
    va_end(ap);
    return -1;
}

static int lex(pbrt_lex_t *lx, pbrt_tok_t *t)
{
    for (;;) {
        if (lx->depth == 0) { t->kind = PT_EOF; return 0; }
        pbrt_src_t *s = &lx->src[lx->depth - 1];
        const char *p = s->text;
        while (s->pos < s->len) {   /* blanks and comments */
            char c = p[s->pos];
            if (c == '\n') { s->line++; s->pos++; }
            else if (c == ' ' || c == '\t' || c == '\r') s->pos++;
            else if (c == '#') { while (s->pos < s->len && p[s->pos] != '\n') s->pos++; }
            else break;
        }
        if (s->pos == s->len) {   /* the end of an included file: back to the one that included it */
            if (lx->depth == 1) { t->kind = PT_EOF; t->file = s->path; t->line = s->line; return 0; }
            free(s->text);   /* the path stays: a directive read from this file may still name it */
            s->text = NULL;
            lx->depth--;
            continue;
        }
        t->file = s->path;
        t->line = s->line;
        t->text[0] = 0;
        const char c = p[s->pos];
        if (c == '[' || c == ']') { t->kind = c == '[' ? PT_LBRACKET : PT_RBRACKET; s->pos++; return 0; }
        if (c == '"') {
            const size_t start = ++s->pos;
            while (s->pos < s->len && p[s->pos] != '"' && p[s->pos] != '\n') s->pos++;
            if (s->pos == s->len || p[s->pos] == '\n') return pbrt_fail(lx, t, "a string is not closed on its line");
            if (s->pos - start >= sizeof t->text) return pbrt_fail(lx, t, "a string longer than %zu bytes", sizeof t->text - 1);
            memcpy(t->text, p + start, s->pos - start);
            t->text[s->pos - start] = 0;
            s->pos++;
            t->kind = PT_STRING;
            return 0;
        }
        const size_t start = s->pos;
        while (s->pos < s->len && !strchr(" \t\r\n[]\"#", p[s->pos])) s->pos++;
        const size_t n = s->pos - start;
        if (n >= sizeof t->text) return pbrt_fail(lx, t, "a word longer than %zu bytes", sizeof t->text - 1);
        memcpy(t->text, p + start, n);
        t->text[n] = 0;
        if (strchr("+-.0123456789", c)) {
            char *end;
            errno = 0;
            t->num = strtod(t->text, &end);
            if (*end || end == t->text) return pbrt_fail(lx, t, "'%s' is not a number", t->text);
            if (!isfinite(t->num)) return pbrt_fail(lx, t, "'%s' is not a finite number", t->text);
            t->kind = PT_NUMBER;
            return 0;
        }
        t->kind = PT_WORD;
        return 0;
    }
}

int pbrt_lex_next(pbrt_lex_t *lx, pbrt_tok_t *t)
{
    if (lx->has_peek) { *t = lx->peeked; lx->has_peek = 0; return 0; }
    return lex(lx, t);
}

int pbrt_lex_peek(pbrt_lex_t *lx, pbrt_tok_t *t)
{
    if (!lx->has_peek) {
        if (lex(lx, &lx->peeked)) return -1;
        lx->has_peek = 1;
    }
    *t = lx->peeked;
    return 0;
}

/* Append one value to a parameter: 0, or -1 (memory). */
static int push(pbrt_param_t *pp, const pbrt_tok_t *t)
{
    if (pp->n == pp->cap) {
        const int want = pp->cap ? 2 * pp->cap : 4;
        void *q = pp->is_str ? realloc(pp->str, (size_t)want * sizeof *pp->str)
                             : realloc(pp->num, (size_t)want * sizeof *pp->num);
        if (!q) return -1;
        if (pp->is_str) pp->str = q;
        else pp->num = q;
        pp->cap = want;
    }
    if (pp->is_str) snprintf(pp->str[pp->n], sizeof pp->str[0], "%s", t->text);
    else pp->num[pp->n] = t->kind == PT_NUMBER ? t->num : !strcmp(t->text, "true");
    pp->n++;
    return 0;
}

/* Whether a token is a value of a parameter of this type. */
static int value_fits(const pbrt_param_t *pp, const pbrt_tok_t *t)
{
    if (pp->is_str) return t->kind == PT_STRING;
    if (!strcmp(pp->type, "bool"))
        return (t->kind == PT_WORD || t->kind == PT_STRING) && (!strcmp(t->text, "true") || !strcmp(t->text, "false"));
    return t->kind == PT_NUMBER;
}

static int params_read(pbrt_lex_t *lx, pbrt_params_t *ps);

int pbrt_params_read(pbrt_lex_t *lx, pbrt_params_t *ps)
{
    memset(ps, 0, sizeof *ps);
    const int rc = params_read(lx, ps);
    if (rc) pbrt_params_free(ps);   /* nothing is left to the caller on an error */
    return rc;
}

static int params_read(pbrt_lex_t *lx, pbrt_params_t *ps)
{
    pbrt_tok_t t;
    for (;;) {
        if (pbrt_lex_peek(lx, &t)) return -1;
        if (t.kind != PT_STRING) return 0;
        pbrt_lex_next(lx, &t);
        if (ps->n == PBRT_PARAMS_MAX) return pbrt_fail(lx, &t, "more than %d parameters", PBRT_PARAMS_MAX);
        pbrt_param_t *pp = &ps->p[ps->n++];
        pp->file = t.file;
        pp->line = t.line;
        if (sscanf(t.text, "%23s %63s", pp->type, pp->name) != 2)
            return pbrt_fail(lx, &t, "\"%s\" is not a parameter (\"TYPE NAME\")", t.text);
        pp->is_str = !strcmp(pp->type, "string") || !strcmp(pp->type, "texture") || !strcmp(pp->type, "spectrum");
        pbrt_tok_t v;
        if (pbrt_lex_next(lx, &v)) return -1;
        const int list = v.kind == PT_LBRACKET;
        if (list && pbrt_lex_next(lx, &v)) return -1;
        while (!list || v.kind != PT_RBRACKET) {
            if (!strcmp(pp->type, "spectrum") && v.kind == PT_NUMBER)
                return pbrt_fail(lx, &v, "\"%s %s\": a spectrum of numbers is not supported (use \"rgb %s\")",
                                 pp->type, pp->name, pp->name);
            if (!value_fits(pp, &v)) return pbrt_fail(lx, &v, "\"%s %s\": unexpected value '%s'", pp->type, pp->name,
                                                     v.kind == PT_EOF ? "end of file" : v.text[0] ? v.text : "[");
            if (push(pp, &v)) return pbrt_fail(lx, &v, "out of memory");
            if (!list) break;
            if (pbrt_lex_next(lx, &v)) return -1;
        }
    }
}

void pbrt_params_free(pbrt_params_t *ps)
{
    for (int k = 0; k < ps->n; k++) { free(ps->p[k].num); free(ps->p[k].str); }
    memset(ps, 0, sizeof *ps);
}

pbrt_param_t *pbrt_param(pbrt_params_t *ps, const char *name)
{
    for (int k = 0; k < ps->n; k++)
        if (!strcmp(ps->p[k].name, name)) { ps->p[k].used = 1; return &ps->p[k]; }
    return NULL;
}
