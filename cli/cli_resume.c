// SPDX-License-Identifier: Apache-2.0
/* cli_resume.c: the options a checkpoint carries, and the command line of a resume (cli_resume.h). */
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli_resume.h"

/* The options that change the bits: a resume may not change them. */
static const char *const BIT_OPTIONS[] = {"--width", "--height", "--photon-offset", "--precision", "--datapath",
                                          "--alpha", "--grid", "--no-skip", "--preu", "--pipe-fast", "--layout",
                                          "--prees", "--light-sampling", "--hide-lights", "--eye-rays",
                                          "--max-bounces", "--radius"};

typedef struct { char *p; size_t left; int full; } buf_t;

static void add(buf_t *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void add(buf_t *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(b->p, b->left, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= b->left) { b->full = 1; return; }
    b->p += n;
    b->left -= (size_t)n;
}

/* path made absolute (against the current folder; the scene through realpath): 0, or 2 printed. */
static int absolute(const char *what, const char *path, int must_exist, char *out, size_t len)
{
    if (strchr(path, '\n')) {
        fprintf(stderr, "pree render: %s %s: a path with a newline cannot be kept in a checkpoint\n", what, path);
        return 2;
    }
    if (must_exist && realpath(path, out)) return 0;
    char cwd[PATH_MAX];
    if (path[0] == '/' || !getcwd(cwd, sizeof cwd)) snprintf(out, len, "%s", path);
    else if ((size_t)snprintf(out, len, "%s/%s", cwd, path) >= len) {
        fprintf(stderr, "pree render: %s %s: the path is too long to keep in a checkpoint\n", what, path);
        return 2;
    }
    return 0;
}

/* The shortest decimal that reads back as x. */
static void shortest(double x, char *out, size_t len)
{
    for (int p = 1; p <= 17; p++) {
        snprintf(out, len, "%.*g", p, x);
        if (strtod(out, NULL) == x) return;
    }
}

int cli_resume_note(const render_options_t *o, const cli_resume_job_t *j, char *note, size_t len)
{
    static const char *const precision[] = {"double", "fp32"}, *const datapath[] = {"paper", "stable"},
                             *const layout[] = {"spatial", "pixel"};
    const char *grid = o->grid == GRID_SMALLPPM ? "smallppm" : o->grid == GRID_BRUTE ? "brute" : "cells";
    char path[PATH_MAX + 8], alpha[32];
    buf_t b = {note, len, 0};
    shortest(render_alpha(o), alpha, sizeof alpha);
    if (j->scene) {
        if (absolute("the scene", j->scene, 1, path, sizeof path)) return 2;
        add(&b, "scene %s\n", path);
    }
    add(&b, "--width %d\n--height %d\n--photons %llu\n--photon-offset %llu\n--precision %s\n--datapath %s\n"
            "--alpha %s\n--grid %s\n--preu %d\n--layout %s\n--prees %d\n--checkpoint-every %llu\n--eye-rays %d\n",
        o->width, o->height, (unsigned long long)o->photons, (unsigned long long)o->photon_offset,
        precision[o->precision == PRECISION_FP32], datapath[o->datapath == DATAPATH_STABLE], alpha, grid,
        o->preu ? o->preu : 4, layout[o->layout == HP_LAYOUT_PIXEL], o->prees > 1 ? o->prees : 1,
        (unsigned long long)(o->checkpoint_every ? o->checkpoint_every : RENDER_CHECKPOINT_EVERY),
        o->eye_rays > 1 ? o->eye_rays : 1);
    if (o->no_skip) add(&b, "--no-skip\n");
    if (o->pipe_fast) add(&b, "--pipe-fast\n");
    if (o->hide_lights) add(&b, "--hide-lights\n");
    if (o->initial_radius > 0) {
        shortest(o->initial_radius, alpha, sizeof alpha);
        add(&b, "--radius %s\n", alpha);
    }
    if (o->exposure != 0) {
        shortest(o->exposure, alpha, sizeof alpha);
        add(&b, "--exposure %s\n", alpha);
    }
    for (int k = 0; k < j->nout; k++) {
        if (absolute("--out", j->outs[k], 0, path, sizeof path)) return 2;
        add(&b, "--out %s\n", path);
    }
    if (j->stats) {
        if (absolute("--stats", j->stats, 0, path, sizeof path)) return 2;
        add(&b, "--stats %s\n", path);
    }
    if (j->series) add(&b, "%s", j->series);
    if (b.full) { fprintf(stderr, "pree render: the options are too long to keep in a checkpoint\n"); return 2; }
    return 0;
}

/* The value of option name in a note ("" for a flag that is there), or NULL when absent; the
 * value runs to the line's end, copied into val[len]. */
static const char *note_value(const char *note, const char *name, char *val, size_t len)
{
    const size_t n = strlen(name);
    for (const char *line = note; line && *line; line = strchr(line, '\n'), line = line ? line + 1 : NULL) {
        if (strncmp(line, name, n) || (line[n] != ' ' && line[n] != '\n' && line[n] != 0)) continue;
        const char *v = line[n] == ' ' ? line + n + 1 : line + n, *end = strchr(v, '\n');
        snprintf(val, len, "%.*s", (int)(end ? end - v : (long)strlen(v)), v);
        return val;
    }
    return NULL;
}

static int given_has(const char *const *given, int ngiven, const char *name)
{
    for (int k = 0; k < ngiven; k++)
        if (!strcmp(given[k], name)) return 1;
    return 0;
}

/* Options of argv that change the bits and differ from the checkpoint's: 0, or 2 printed. */
static int conflicts(const char *ckpt, const char *rec, const char *cmd, const char *const *given, int ngiven)
{
    for (size_t k = 0; k < sizeof BIT_OPTIONS / sizeof *BIT_OPTIONS; k++) {
        const char *name = BIT_OPTIONS[k];
        char a[256], b[256];
        if (!given_has(given, ngiven, name)) continue;
        const char *mine = note_value(cmd, name, a, sizeof a), *theirs = note_value(rec, name, b, sizeof b);
        if (mine && theirs && !strcmp(mine, theirs)) continue;
        if (!mine || !theirs)   /* a flag */
            fprintf(stderr, "pree render: --resume %s: %s %s, but the checkpoint's render ran %s it (a resume may add "
                    "photons and outputs only)\n", ckpt, name, mine ? "is given" : "is not given", theirs ? "with" : "without");
        else
            fprintf(stderr, "pree render: --resume %s: %s %s conflicts with the checkpoint's %s %s (a resume may add "
                    "photons and outputs only)\n", ckpt, name, mine, name, theirs);
        return 2;
    }
    return 0;
}

int cli_resume_args(const char *ckpt, const char *rec, const char *cmd, const char *const *given, int ngiven,
                    int has_scene, int argc, char **argv, int *out_argc, char ***out_argv)
{
    if (conflicts(ckpt, rec, cmd, given, ngiven)) return 1;
    size_t lines = 0;
    for (const char *p = rec; *p; p++) lines += *p == '\n';
    char **v = calloc(2 * lines + (size_t)argc + 4, sizeof *v);
    if (!v) { fprintf(stderr, "pree render: out of memory\n"); return 2; }
    int n = 0;
    v[n++] = strdup(argv[0]);
    for (const char *line = rec; *line;) {
        const char *end = strchr(line, '\n'), *sp = memchr(line, ' ', (size_t)(end ? end - line : (long)strlen(line)));
        const size_t len = end ? (size_t)(end - line) : strlen(line), nlen = sp ? (size_t)(sp - line) : len;
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)nlen, line);
        const int scene = !strcmp(name, "scene");
        if (scene ? !has_scene : !given_has(given, ngiven, name)) {
            if (!scene) v[n++] = strdup(name);
            if (sp) v[n++] = strndup(sp + 1, len - nlen - 1);
        }
        line = end ? end + 1 : line + len;
    }
    if (!given_has(given, ngiven, "--checkpoint")) {
        v[n++] = strdup("--checkpoint");
        v[n++] = strdup(ckpt);
    }
    for (int k = 1; k < argc; k++) v[n++] = strdup(argv[k]);
    for (int k = 0; k < n; k++)
        if (!v[k]) { cli_resume_free(n, v); fprintf(stderr, "pree render: out of memory\n"); return 2; }
    *out_argc = n;
    *out_argv = v;
    return 0;
}

void cli_resume_free(int argc, char **argv)
{
    for (int k = 0; k < argc; k++) free(argv[k]);
    free(argv);
}
