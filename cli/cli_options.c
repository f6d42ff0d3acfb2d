// SPDX-License-Identifier: Apache-2.0
/* cli_options.c: option scanning (getopt_long) and strict value parsing. */
#include <errno.h>
#include <omp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "cli_options.h"

void cli_begin(cli_args_t *a, int argc, char **argv, const char *cmd, const struct option *longopts,
               render_options_t *render, int min_size)
{
    *a = (cli_args_t){.argc = argc, .argv = argv, .cmd = cmd, .longopts = longopts, .render = render,
                      .min_size = min_size};
    optind = 0;   /* glibc: full re-initialisation of the scan */
    opterr = 0;   /* the messages are ours */
}

/* One getopt_long step: the option's id, 0 at the end, -1 on a scanning error (printed). */
static int cli_scan(cli_args_t *a)
{
    int idx = -1;
    /* GNU order: operands may come between options. ":" makes a missing value ':' rather
     * than '?'. -h is the only short option. */
    int c = getopt_long(a->argc, a->argv, ":h", a->longopts, &idx);
    if (c == -1) return 0;
    const char *arg = a->argv[optind - 1];
    a->val = optarg;
    if (idx >= 0) snprintf(a->name, sizeof a->name, "--%s", a->longopts[idx].name);
    else snprintf(a->name, sizeof a->name, "%s", arg);
    if (c == ':') {
        snprintf(a->name, sizeof a->name, "%s", arg);
        cli_error(a, "%s needs a value", a->name);
        return -1;
    }
    if (c == '?') {
        const char *eq = strchr(arg, '=');
        if (optopt != 0 && eq && !strncmp(arg, "--", 2))   /* glibc: optopt is the flag's id */
            cli_error(a, "option '%.*s' takes no value (see 'pree %s --help')", (int)(eq - arg), arg, a->cmd);
        else
            cli_error(a, "unknown option '%s' (see 'pree %s --help')", arg, a->cmd);
        return -1;
    }
    return c;
}

int cli_next(cli_args_t *a)
{
    for (;;) {
        int id = cli_scan(a);
        if (id <= 0 || !a->render || id == CLI_HELP) return id;
        int r = cli_render_option(a, id, a->render, a->min_size);
        if (r == 1) return id;
        if (r != 0) return -1;
    }
}

char **cli_operands(const cli_args_t *a, int *n)
{
    *n = a->argc - optind;
    return a->argv + optind;
}

const char *cli_scene(cli_args_t *a)
{
    int n;
    char **ops = cli_operands(a, &n);
    if (n == 1) return ops[0];
    if (n == 0) cli_error(a, "no scene given (usage: pree %s SCENE [options])", a->cmd);
    else cli_error(a, "more than one scene given ('%s' and '%s')", ops[0], ops[1]);
    return NULL;
}

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

int cli_int(cli_args_t *a, long long lo, long long hi, long long *out)
{
    const char *s = a->val;
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (end == s || *end != '\0')
        return cli_error(a, "%s: '%s' is not an integer", a->name, s);
    if (errno == ERANGE || v < lo || v > hi)
        return cli_error(a, "%s: %s is out of range [%lld, %lld]", a->name, s, lo, hi);
    *out = v;
    return 0;
}

int cli_size(cli_args_t *a, uint64_t *out)
{
    const char *s = a->val;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    const char *units = "KMGT";
    const char *u = *end ? strchr(units, *end) : NULL;
    double scale = u ? (double)(1ull << (10 * (u - units + 1))) : 1.0;
    if (end == s || errno || !(v >= 0) || (*end && (!u || end[1])))
        return cli_error(a, "%s: '%s' is not a size (bytes, or a number with K, M, G or T)", a->name, s);
    v *= scale;
    if (v < 1048576.0 || v > 1125899906842624.0) return cli_error(a, "%s: %s is out of range [1M, 1024T]", a->name, s);
    *out = (uint64_t)v;
    return 0;
}

int cli_real(cli_args_t *a, double lo, int lo_open, double hi, double *out)
{
    const char *s = a->val;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || v != v)
        return cli_error(a, "%s: '%s' is not a number", a->name, s);
    if ((lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi))
        return cli_error(a, "%s: %s is out of range %s%g, %g]", a->name, s, lo_open ? "(" : "[", lo, hi);
    *out = v;
    return 0;
}

int cli_keyword(cli_args_t *a, const char *const *names, int n)
{
    for (int k = 0; k < n; k++)
        if (!strcmp(a->val, names[k])) return k;
    char list[256] = "";
    for (int k = 0; k < n; k++) {
        size_t len = strlen(list);
        snprintf(list + len, sizeof list - len, "%s%s", k == 0 ? "" : k == n - 1 ? " or " : ", ", names[k]);
    }
    cli_error(a, "%s: '%s' is not %s", a->name, a->val, list);
    return -1;
}

int cli_render_option(cli_args_t *a, int id, render_options_t *opt, int min_size)
{
    long long v;
    int k;
    switch (id) {
    case CLI_ALPHA: return cli_real(a, 0, 1, 1, &opt->alpha);
    case CLI_DATAPATH: {
        static const char *const names[] = {"paper", "stable"};
        if ((k = cli_keyword(a, names, 2)) < 0) return 2;
        opt->datapath = k ? DATAPATH_STABLE : DATAPATH_PAPER;
        return 0;
    }
    case CLI_GRID: {
        static const char *const names[] = {"cells", "smallppm", "brute"};
        static const grid_kind_t kinds[] = {GRID_CELLS, GRID_SMALLPPM, GRID_BRUTE};
        if ((k = cli_keyword(a, names, 3)) < 0) return 2;
        opt->grid = kinds[k];
        return 0;
    }
    case CLI_WIDTH:
    case CLI_HEIGHT:
        if (cli_int(a, min_size, 16384, &v)) return 2;
        *(id == CLI_WIDTH ? &opt->width : &opt->height) = (int)v;
        return 0;
    case CLI_PHOTONS:
        if (cli_int(a, 1, 10000000000LL, &v)) return 2;
        opt->photons = (uint64_t)v;
        return 0;
    case CLI_PREU:
        if (cli_int(a, 1, 16, &v)) return 2;
        if (v & (v - 1)) return cli_error(a, "--preu: %lld is not 1, 2, 4, 8 or 16", v);
        opt->preu = (int)v;
        return 0;
    case CLI_THREADS: {
        static int warned;   /* once a process (a resume parses its command line twice) */
        if (cli_int(a, 1, 1024, &v)) return 2;
        opt->threads = (int)v;
        const int hw = omp_get_num_procs();
        if (v > hw && !warned++)
            fprintf(stderr, "pree %s: warning: --threads %lld is more than the %d hardware threads: the extra "
                    "threads take turns on them (slower, the same image)\n", a->cmd, v, hw);
        return 0;
    }
    case CLI_LAYOUT: {
        static const char *const names[] = {"spatial", "pixel"};
        if ((k = cli_keyword(a, names, 2)) < 0) return 2;
        opt->layout = k ? HP_LAYOUT_PIXEL : HP_LAYOUT_SPATIAL;
        return 0;
    }
    case CLI_PIPE_FAST: opt->pipe_fast = 1; return 0;
    case CLI_NO_SKIP: opt->no_skip = 1; return 0;
    case CLI_HIDE_LIGHTS: opt->hide_lights = 1; return 0;
    case CLI_EYE_RAYS:
        if (cli_int(a, 1, EYE_RAYS_MAX, &v)) return 2;
        opt->eye_rays = (int)v;
        return 0;
    case CLI_EXPOSURE: return cli_real(a, -30, 0, 30, &opt->exposure);
    case CLI_RADIUS: return cli_real(a, 0, 1, 1e30, &opt->initial_radius);
    case CLI_QUIET: opt->progress = 0; return 0;
    default: return 1;
    }
}

int cli_image_ext(cli_args_t *a, const char *path)
{
    const char *dot = strrchr(path, '.');
    if (dot && (!strcasecmp(dot, ".png") || !strcasecmp(dot, ".ppm") || !strcasecmp(dot, ".exr"))) return 0;
    return cli_error(a, "%s: the image name must end in .png, .ppm or .exr", path);
}
