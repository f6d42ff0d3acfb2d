// SPDX-License-Identifier: Apache-2.0
/* cli_series.c: the convergence series' options and file names (cli_series.h). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli_series.h"

/* One count: digits (with a fraction before k or M), an optional k or M; a whole number of
 * thousands, at least 1000. 0, or 2 printed. */
static int parse_count(cli_args_t *a, const char *s, size_t len, uint64_t *out)
{
    char buf[64], *end;
    if (len == 0 || len >= sizeof buf) return cli_error(a, "%s: '%.*s' is not a photon count", a->name, (int)len, s);
    memcpy(buf, s, len);
    buf[len] = 0;
    errno = 0;
    double v = strtod(buf, &end);
    double scale = *end == 'k' || *end == 'K' ? 1e3 : *end == 'M' ? 1e6 : 1;
    if (scale != 1) end++;
    if (end == buf || *end || errno || !(v >= 0) || buf[0] == '-' || buf[0] == '+')
        return cli_error(a, "%s: '%s' is not a photon count (e.g. 100000, 100k, 1.5M)", a->name, buf);
    v *= scale;
    if (v < 1000 || v > 1e10 || v != floor(v) || fmod(v, 1000) != 0)
        return cli_error(a, "%s: %s is not a whole number of thousands of photons in [1000, 1e10]", a->name, buf);
    *out = (uint64_t)v;
    return 0;
}

int cli_series_option(cli_args_t *a, int every, cli_series_t *ser)
{
    if (every) return parse_count(a, a->val, strlen(a->val), &ser->every);
    ser->nat = 0;
    for (const char *p = a->val;;) {
        const char *comma = strchr(p, ',');
        const size_t len = comma ? (size_t)(comma - p) : strlen(p);
        if (ser->nat == CLI_SERIES_MAX) return cli_error(a, "%s: more than %d counts", a->name, CLI_SERIES_MAX);
        if (parse_count(a, p, len, &ser->at[ser->nat++])) return 2;
        if (!comma) return 0;
        p = comma + 1;
    }
}

static int cmp_u64(const void *x, const void *y)
{
    const uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
    return a < b ? -1 : a > b;
}

int cli_series_points(cli_series_t *ser, uint64_t photons)
{
    uint64_t all[2 * CLI_SERIES_MAX];
    int n = 0;
    for (int k = 0; k < ser->nat; k++) {
        if (ser->at[k] > photons) {
            fprintf(stderr, "pree render: --write-at %llu is beyond the render's %llu photons\n",
                    (unsigned long long)ser->at[k], (unsigned long long)photons);
            return 2;
        }
        all[n++] = ser->at[k];
    }
    if (ser->every && photons / ser->every > CLI_SERIES_MAX) {
        fprintf(stderr, "pree render: --write-every %llu gives more than %d images in %llu photons\n",
                (unsigned long long)ser->every, CLI_SERIES_MAX, (unsigned long long)photons);
        return 2;
    }
    for (uint64_t p = ser->every; ser->every && p <= photons; p += ser->every) all[n++] = p;
    qsort(all, (size_t)n, sizeof *all, cmp_u64);
    ser->npoints = 0;
    for (int k = 0; k < n; k++)
        if (!ser->npoints || ser->points[ser->npoints - 1] != all[k]) {
            if (ser->npoints == CLI_SERIES_MAX) {
                fprintf(stderr, "pree render: --write-every and --write-at give more than %d images\n", CLI_SERIES_MAX);
                return 2;
            }
            ser->points[ser->npoints++] = all[k];
        }
    return 0;
}

int cli_series_name(const char *path, uint64_t photons, char *out, size_t len)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash)) dot = path + strlen(path);
    const int n = snprintf(out, len, "%.*s-%llu%s", (int)(dot - path), path, (unsigned long long)photons, dot);
    return n < 0 || (size_t)n >= len ? -1 : 0;
}

void cli_series_note(const cli_series_t *ser, char *note, size_t len)
{
    size_t used = 0;
    note[0] = 0;
    if (ser->every) used += (size_t)snprintf(note, len, "--write-every %llu\n", (unsigned long long)ser->every);
    for (int k = 0; k < ser->nat && used < len; k++)
        used += (size_t)snprintf(note + used, len - used, "%s%llu%s", k ? "," : "--write-at ",
                                 (unsigned long long)ser->at[k], k == ser->nat - 1 ? "\n" : "");
}
