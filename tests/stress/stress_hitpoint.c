// SPDX-License-Identifier: Apache-2.0
/* stress_hitpoint.c: one hit point fed N accepted photons through both fp32 datapaths of the
 * PREU model (the paper's, model/pree/preu_fp32.h, and the stable one, model/pree/preu_stable.h), against
 * smallppm's double update with an integer count, the same recurrence in long double, and the
 * closed form of the radius product (issue 10, part 1; docs/numerics.md).
 *
 * Every photon lands on the hit point (distance 0), so every one is accepted. At every decade
 * (and at --at K) it prints, for each datapath, the relative error of r2, of the count N, of
 * tau (channel r) and of the radiance, and at the end the accept at which each state word first
 * stops changing and last changes (detected exactly: the word compared with its previous value
 * at every accept), and the extremes of the r2 and tau/r2 errors over all accepts.
 *
 * Usage: stress_hitpoint [run options]        the decade run (default 1e6 accepts, alpha 0.7)
 *        stress_hitpoint --nonfinite          non-finite and out-of-range inputs: what each
 *                                             datapath does, one update from a normal state
 *        stress_hitpoint --ne-table           N_emitted -> NE (binary32) and the radiance
 *                                             through 2^24 and 2^32 emitted photons
 *        stress_hitpoint --selftest           the references checked against each other
 *        stress_hitpoint --decompose K        the stable datapath's r2 error at alpha 0.7 split into
 *                                             its two biases (w truncated to binary32 in the
 *                                             increment; kappa rounded), each alone in long double
 * Run options:
 *   --accepts K            accepted photons (integer or 1e9-style; default 1e6)
 *   --alpha A              alpha (default 0.7), rounded once to binary32 as the datapaths take it
 *   --r2 R                 initial radius squared (default 1), rounded once to binary32; every
 *                          model starts from that binary32 value
 *   --flux F               photon flux per channel (default 1)
 *   --flux-mode const|random   constant F, or F * u with u in [0.5, 1.5) from a fixed
 *                          splitmix64 sequence (rounded to binary32; every model sees the
 *                          same binary32 flux)
 *   --weight W             hit-point weight f (default 1)
 *   --emitted-per-accept E N_emitted = E * accepts in the radiance (default 1000)
 *   --datapaths LIST       paper,stable (default both)
 *   --no-ld                no long-double recurrence (faster; extremes then against double)
 *   --at K                 an extra checkpoint (table and CSV; repeatable)
 *   --per-decade P         CSV checkpoints at 10^(d + i/P) (default 1: decades only)
 *   --csv FILE             append one CSV row per checkpoint and datapath (header if new)
 *   --label NAME           the run's name in the CSV (default "run")
 * Exit status: 0, or 2 on a usage error, 1 when --selftest fails. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stress_hitpoint.h"

static uint64_t parse_count(const char *s)
{
    char *end;
    if (strspn(s, "0123456789") == strlen(s) && *s) {
        unsigned long long v = strtoull(s, &end, 10);
        if (v >= 1) return v;
    } else {
        double v = strtod(s, &end);
        if (!*end && v >= 1 && v < 1.8e19) return (uint64_t)llround(v);
    }
    fprintf(stderr, "stress_hitpoint: bad count '%s'\n", s);
    exit(2);
}

static double parse_real(const char *s)
{
    char *end;
    double v = strtod(s, &end);
    if (*end || end == s) { fprintf(stderr, "stress_hitpoint: bad number '%s'\n", s); exit(2); }
    return v;
}

static void usage(void)
{
    fprintf(stderr, "usage: stress_hitpoint [--accepts K] [--alpha A] [--r2 R] [--flux F] [--flux-mode const|random] "
                    "[--weight W]\n       [--emitted-per-accept E] [--datapaths paper,stable] [--no-ld] [--at K]... "
                    "[--per-decade P] [--csv FILE] [--label NAME]\n       stress_hitpoint --nonfinite | --ne-table | --selftest\n");
    exit(2);
}

int main(int argc, char **argv)
{
    opts_t o = {1000000, 0.7, 1.0, 1.0, 1.0, 1000.0, 0, 1, 1, 1, 1, 0, {0}, NULL, "run"};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--nonfinite")) return run_nonfinite();
        if (!strcmp(a, "--ne-table")) return run_ne_table();
        if (!strcmp(a, "--selftest")) return run_selftest();
        if (!strcmp(a, "--decompose") && v) return run_decompose(parse_count(v));
        if (!strcmp(a, "--no-ld")) { o.ld = 0; continue; }
        if (!v) usage();
        i++;
        if (!strcmp(a, "--accepts")) o.accepts = parse_count(v);
        else if (!strcmp(a, "--alpha")) o.alpha = parse_real(v);
        else if (!strcmp(a, "--r2")) o.r2 = parse_real(v);
        else if (!strcmp(a, "--flux")) o.flux = parse_real(v);
        else if (!strcmp(a, "--weight")) o.weight = parse_real(v);
        else if (!strcmp(a, "--emitted-per-accept")) o.epa = parse_real(v);
        else if (!strcmp(a, "--flux-mode")) {
            if (!strcmp(v, "const")) o.flux_random = 0;
            else if (!strcmp(v, "random")) o.flux_random = 1;
            else usage();
        } else if (!strcmp(a, "--datapaths")) {
            o.paper = strstr(v, "paper") != NULL;
            o.stable = strstr(v, "stable") != NULL;
            if (!o.paper && !o.stable) usage();
        } else if (!strcmp(a, "--at")) {
            if (o.n_at >= MAX_AT) usage();
            o.at[o.n_at++] = parse_count(v);
        } else if (!strcmp(a, "--per-decade")) {
            o.per_decade = atoi(v);
            if (o.per_decade < 1 || o.per_decade > 20) usage();
        } else if (!strcmp(a, "--csv")) o.csv = v;
        else if (!strcmp(a, "--label")) o.label = v;
        else usage();
    }
    if (!(o.alpha > 0 && o.alpha <= 1) || !(o.epa > 0)) usage();
    return run_decades(&o);
}
