/* cli_options.c: strict command-line value parsing. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "cli_options.h"

int cli_error(cli_args_t *a, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "pree %s: ", a->cmd);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return 2;
}

const char *cli_value(cli_args_t *a, const char *opt)
{
    if (a->i >= a->argc) { cli_error(a, "%s needs a value", opt); return NULL; }
    return a->argv[a->i++];
}

int cli_int(cli_args_t *a, const char *opt, long long lo, long long hi, long long *out)
{
    const char *s = cli_value(a, opt);
    if (!s) return 2;
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (end == s || *end != '\0') return cli_error(a, "%s: '%s' is not an integer", opt, s);
    if (errno == ERANGE) return cli_error(a, "%s: %s is out of range [%lld, %lld]", opt, s, lo, hi);
    if (v < lo || v > hi) return cli_error(a, "%s: %lld is out of range [%lld, %lld]", opt, v, lo, hi);
    *out = v;
    return 0;
}

int cli_size(cli_args_t *a, const char *opt, uint64_t *out)
{
    const char *s = cli_value(a, opt);
    if (!s) return 2;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    const char *units = "KMGT";
    const char *u = *end ? strchr(units, *end) : NULL;
    double scale = u ? (double)(1ull << (10 * (u - units + 1))) : 1.0;
    if (end == s || errno || !(v >= 0) || (*end && (!u || end[1])))
        return cli_error(a, "%s: '%s' is not a size (bytes, or a number with K, M, G or T)", opt, s);
    v *= scale;
    if (v < 1048576.0 || v > 1125899906842624.0) return cli_error(a, "%s: %s is out of range [1M, 1024T]", opt, s);
    *out = (uint64_t)v;
    return 0;
}

int cli_real(cli_args_t *a, const char *opt, double lo, int lo_open, double hi, double *out)
{
    const char *s = cli_value(a, opt);
    if (!s) return 2;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || v != v)
        return cli_error(a, "%s: '%s' is not a number", opt, s);
    if ((lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi))
        return cli_error(a, "%s: %s is out of range %s%g, %g]", opt, s, lo_open ? "(" : "[", lo, hi);
    *out = v;
    return 0;
}

/* The value of a keyword option: the index of it in names[0..n), or -1 (error printed). */
static int cli_keyword(cli_args_t *a, const char *opt, const char *const *names, int n, const char *list)
{
    const char *s = cli_value(a, opt);
    if (!s) return -1;
    for (int k = 0; k < n; k++)
        if (!strcmp(s, names[k])) return k;
    cli_error(a, "%s: '%s' is not %s", opt, s, list);
    return -1;
}

int cli_render_option(cli_args_t *a, const char *arg, render_options_t *opt, int min_size)
{
    long long v;
    if (!strcmp(arg, "--alpha")) return cli_real(a, arg, 0, 1, 1, &opt->alpha);
    if (!strcmp(arg, "--datapath")) {
        static const char *const names[] = {"paper", "stable"};
        int k = cli_keyword(a, arg, names, 2, "paper or stable");
        if (k < 0) return 2;
        opt->datapath = k ? DATAPATH_STABLE : DATAPATH_PAPER;
        return 0;
    }
    if (!strcmp(arg, "--grid")) {
        static const char *const names[] = {"cells", "smallppm", "brute"};
        static const grid_kind_t kinds[] = {GRID_CELLS, GRID_SMALLPPM, GRID_BRUTE};
        int k = cli_keyword(a, arg, names, 3, "cells, smallppm or brute");
        if (k < 0) return 2;
        opt->grid = kinds[k];
        return 0;
    }
    if (!strcmp(arg, "--width") || !strcmp(arg, "--height")) {
        if (cli_int(a, arg, min_size, 16384, &v)) return 2;
        *(arg[2] == 'w' ? &opt->width : &opt->height) = (int)v;
        return 0;
    }
    if (!strcmp(arg, "--photons")) {
        if (cli_int(a, arg, 1, 10000000000LL, &v)) return 2;
        opt->photons = (uint64_t)v;
        return 0;
    }
    if (!strcmp(arg, "--preu")) {
        if (cli_int(a, arg, 4, 16, &v)) return 2;
        if (v != 4 && v != 8 && v != 16) return cli_error(a, "--preu: %lld is not 4, 8 or 16", v);
        opt->preu = (int)v;
        return 0;
    }
    if (!strcmp(arg, "--no-skip")) { opt->no_skip = 1; return 0; }
    if (!strcmp(arg, "--quiet")) { opt->progress = 0; return 0; }
    return 1;
}

int cli_image_ext(cli_args_t *a, const char *path)
{
    const char *dot = strrchr(path, '.');
    if (dot && (!strcasecmp(dot, ".png") || !strcasecmp(dot, ".ppm") || !strcasecmp(dot, ".exr"))) return 0;
    return cli_error(a, "%s: the image name must end in .png, .ppm or .exr", path);
}
