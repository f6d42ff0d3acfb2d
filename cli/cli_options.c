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
    if (end == s || *end != '\0' || errno == ERANGE)
        return cli_error(a, "%s: '%s' is not an integer", opt, s);
    if (v < lo || v > hi) return cli_error(a, "%s: %lld is out of range [%lld, %lld]", opt, v, lo, hi);
    *out = v;
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

int cli_update_rule(cli_args_t *a, const char *arg, datapath_t *datapath, double *alpha)
{
    if (!strcmp(arg, "--alpha")) return cli_real(a, arg, 0, 1, 1, alpha);
    if (strcmp(arg, "--datapath")) return 1;
    const char *s = cli_value(a, arg);
    if (!s) return 2;
    if (!strcmp(s, "paper")) *datapath = DATAPATH_PAPER;
    else if (!strcmp(s, "stable")) *datapath = DATAPATH_STABLE;
    else return cli_error(a, "--datapath: '%s' is not paper or stable", s);
    return 0;
}

int cli_image_ext(cli_args_t *a, const char *path)
{
    const char *dot = strrchr(path, '.');
    if (dot && (!strcasecmp(dot, ".png") || !strcasecmp(dot, ".ppm") || !strcasecmp(dot, ".exr"))) return 0;
    return cli_error(a, "%s: the image name must end in .png, .ppm or .exr", path);
}
