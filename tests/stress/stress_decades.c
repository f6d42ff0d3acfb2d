// SPDX-License-Identifier: Apache-2.0
/* stress_decades.c: the stress program's decade run (tests/stress/stress_hitpoint.c): one hit
 * point fed K accepted photons through both datapaths and the references, a table row at every
 * decade and --at, CSV rows at every checkpoint, the change tracking and the error extremes. */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "stress_hitpoint.h"

/* Change tracking: first accept with an unchanged word, last accept that changed it. */
typedef struct {
    uint64_t first_unchanged, last_changed, unchanged;
} track_t;

static inline void track(track_t *t, int changed, uint64_t k)
{
    if (changed) t->last_changed = k;
    else {
        t->unchanged++;
        if (!t->first_unchanged) t->first_unchanged = k;
    }
}

static void print_track(const char *dp, const char *word, const track_t *t, uint64_t K, const char *extra)
{
    char fu[32];
    if (t->first_unchanged) snprintf(fu, sizeof fu, "%" PRIu64, t->first_unchanged);
    else snprintf(fu, sizeof fu, "never");
    printf("event %-6s %-4s first_unchanged=%s last_changed=%" PRIu64 " unchanged=%" PRIu64 " of %" PRIu64 "%s\n",
           dp, word, fu, t->last_changed, t->unchanged, K, extra ? extra : "");
}

typedef struct { double lo, hi; uint64_t at_lo, at_hi; } extreme_t;
static inline void extreme(extreme_t *x, double e, uint64_t k)
{
    if (!(e >= x->lo)) { if (!isnan(e) || !isnan(x->lo)) { x->lo = e; x->at_lo = k; } }
    if (!(e <= x->hi)) { if (!isnan(e) || !isnan(x->hi)) { x->hi = e; x->at_hi = k; } }
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* One checkpoint's figures for one datapath. */
typedef struct {
    double r2, n, tau, rad, L;            /* the datapath's values (host view) */
    double e_r2, e_r2c, e_n, e_tau, e_tauld, e_rad, e_L;
} row_t;

static void print_header(void)
{
    printf("%-7s %14s %10s %10s %10s %10s %10s %10s %10s  %-13s %-13s %-13s\n", "model", "accepts", "r2/double",
           "r2/closed", "N/(a*k)", "tau/double", "tau/ld", "rad/double", "L/double", "r2", "N", "tau");
}

static int g_ld = 1;   /* the long-double recurrence ran: else its columns print "-" */

static void print_row(const char *dp, uint64_t k, const row_t *r)
{
    char e[7][16];
    fmt_err(e[0], 16, r->e_r2); fmt_err(e[1], 16, r->e_r2c); fmt_err(e[2], 16, r->e_n);
    fmt_err(e[3], 16, r->e_tau); fmt_err(e[4], 16, r->e_tauld); fmt_err(e[5], 16, r->e_rad); fmt_err(e[6], 16, r->e_L);
    if (!g_ld) {
        snprintf(e[4], 16, "-");
        if (!strcmp(dp, "double")) { snprintf(e[5], 16, "-"); snprintf(e[6], 16, "-"); }
    }
    printf("%-7s %14" PRIu64 " %10s %10s %10s %10s %10s %10s %10s  %-13.7g %-13.10g %-13.7g\n", dp, k, e[0], e[1], e[2],
           e[3], e[4], e[5], e[6], r->r2, r->n, r->tau);
}

static void csv_row(FILE *f, const opts_t *o, const char *dp, uint64_t k, const row_t *r)
{
    if (!f) return;
    fprintf(f, "%s,%s,%.9g,%.9g,%.9g,%s,%.9g,%" PRIu64 ",%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.9g,%.12g,%.9g,%.9g\n",
            o->label, dp, o->alpha, o->r2, o->flux, o->flux_random ? "random" : "const", o->epa, k, r->e_r2, r->e_r2c,
            r->e_n, r->e_tau, r->e_tauld, r->e_rad, r->e_L, r->r2, r->n, r->tau, r->L);
}

/* The checkpoints: 10^(d + i/P) up to K, the --at list, and K, sorted, each once. Returns how
 * many (at most MAX_CP). */
static int checkpoints(const opts_t *o, uint64_t *cp)
{
    const uint64_t K = o->accepts;
    int ncp = 0;
    for (int d = 0; d < 20; d++)
        for (int i = 0; i < o->per_decade; i++) {
            double v = pow(10.0, d + (double)i / o->per_decade);
            if (v > (double)K || ncp >= MAX_CP - MAX_AT - 1) break;
            cp[ncp++] = (uint64_t)llround(v);
        }
    for (int i = 0; i < o->n_at; i++) if (o->at[i] <= K) cp[ncp++] = o->at[i];
    cp[ncp++] = K;
    qsort(cp, (size_t)ncp, sizeof cp[0], cmp_u64);
    int m = 0;
    for (int i = 0; i < ncp; i++) if (!m || cp[i] != cp[m - 1]) cp[m++] = cp[i];
    return m;
}

/* The CSV (appended to; the header when the file is new), NULL without --csv. Sets *bad when it
 * cannot be written. */
static FILE *open_csv(const opts_t *o, int *bad)
{
    *bad = 0;
    if (!o->csv) return NULL;
    FILE *t = fopen(o->csv, "r");
    int fresh = !t;
    if (t) fclose(t);
    FILE *csv = fopen(o->csv, "a");
    if (!csv) { fprintf(stderr, "stress_hitpoint: cannot write %s\n", o->csv); *bad = 1; return NULL; }
    if (fresh)
        fprintf(csv, "label,model,alpha,r2_0,flux,flux_mode,emitted_per_accept,accepts,err_r2_double,err_r2_closed,"
                     "err_n,err_tau_double,err_tau_ld,err_rad_double,err_L_double,r2,n,tau,L\n");
    return csv;
}

/* One decade run's state: the inputs as binary32 words and their values, every model's state,
 * and what is tracked over the accepts. */
typedef struct {
    uint32_t alpha32, kappa32, r2_32, f32w, flux32;
    double a, r2_0, fw;
    long double c;                                    /* 1 / a, for the closed form */
    preu_hp_t hp;
    preu_shp_t sp;
    ref_d_t rd;
    ref_ld_t rl;
    preu_photon_t ph;
    track_t tp_r2, tp_n, tp_tau, ts_w, ts_T;
    extreme_t xp_r2, xp_rad, xs_r2, xs_rad;
    uint64_t rej_p, rej_s, seed, kbad;
} decade_run_t;

static void run_init(decade_run_t *r, const opts_t *o)
{
    memset(r, 0, sizeof *r);
    r->alpha32 = preu_f32(o->alpha);
    r->kappa32 = preu_kappa(r->alpha32);
    r->r2_32 = preu_f32(o->r2);
    r->f32w = preu_f32(o->weight);
    r->flux32 = preu_f32(o->flux);
    r->a = f32v(r->alpha32);
    r->r2_0 = f32v(r->r2_32);
    r->fw = f32v(r->f32w);
    r->c = 1.0L / (long double)r->a;
    const uint32_t w = r->f32w;
    r->hp = (preu_hp_t){{0, 0, 0}, {w, w, w}, {0, 0, 0}, r->r2_32, 0};
    r->sp = (preu_shp_t){{0, 0, 0}, {w, w, w}, {0, 0, 0}, 0, 0};
    preu_stable_init(&r->sp, r->r2_0);
    r->rd = (ref_d_t){r->r2_0, 0, 0};
    r->rl = (ref_ld_t){r->r2_0, 0, 0};
    r->ph = (preu_photon_t){{0, 0, 0}, {r->flux32, r->flux32, r->flux32}};
    const extreme_t none = {INFINITY, -INFINITY, 0, 0};
    r->xp_r2 = r->xp_rad = r->xs_r2 = r->xs_rad = none;
    r->seed = 12345;
}

static void print_preamble(const decade_run_t *r, const opts_t *o)
{
    const uint64_t K = o->accepts;
    printf("# one hit point, %" PRIu64 " accepted photons (distance 0); alpha %.9g (binary32 0x%08x), kappa %.9g "
           "(0x%08x)\n# r2_0 %.9g (0x%08x), flux %.9g (0x%08x) %s, weight %.9g, N_emitted = %.9g x accepts\n",
           K, r->a, r->alpha32, f32v(r->kappa32), r->kappa32, r->r2_0, r->r2_32, f32v(r->flux32), r->flux32,
           o->flux_random ? "x u, u in [0.5, 1.5) (splitmix64)" : "constant", r->fw, o->epa);
    printf("# errors: relative, signed; r2/closed against Gamma(k+1) Gamma(1/a) / Gamma(k+1/a); "
           "tau/ld against the long-double recurrence;\n# rad = tau / r2 (stable: T / PI); L = the datapath's "
           "radiance word, NE = binary32(N_emitted), against tau / (PI r2 N_emitted) in double\n");
    long double lr = closed_lnR(K, r->c), lr7 = closed_lnR(K, 1.0L / (long double)o->alpha);
    printf("# alpha rounding: the closed-form r2 at %" PRIu64 " accepts with alpha = %.17g (double) differs from "
           "alpha = binary32 by %+.2e\n", K, o->alpha, (double)expm1l(lr7 - lr));
}

/* Accept k: the photon through every model, the change tracking, and the extremes against the
 * long-double recurrence (else double). */
static void run_accept(decade_run_t *r, const opts_t *o, uint64_t k)
{
    if (o->flux_random) {
        double u = 0.5 + (double)(splitmix64(&r->seed) >> 11) * 0x1p-53;
        uint32_t p = preu_f32(o->flux * u);
        r->ph.phi[0] = r->ph.phi[1] = r->ph.phi[2] = p;
    }
    const double phi = f32v(r->ph.phi[0]);
    if (o->paper) {
        const uint32_t r2o = r->hp.r2, no = r->hp.n, to = r->hp.tau[0];
        if (!preu_update(&r->hp, &r->ph, r->alpha32)) r->rej_p++;
        track(&r->tp_r2, r->hp.r2 != r2o, k);
        track(&r->tp_n, r->hp.n != no, k);
        track(&r->tp_tau, r->hp.tau[0] != to, k);
    }
    if (o->stable) {
        const uint64_t wo = r->sp.w, To = r->sp.T[0];
        if (!preu_stable_update(&r->sp, &r->ph, r->kappa32)) r->rej_s++;
        track(&r->ts_w, r->sp.w != wo, k);
        track(&r->ts_T, r->sp.T[0] != To, k);
        if (r->sp.k != k) r->kbad++;
    }
    ref_d_update(&r->rd, r->a, r->fw, phi);
    if (o->ld) ref_ld_update(&r->rl, r->a, r->fw, phi);
    const ref_ld_t *rl = &r->rl;
    const long double r2x = o->ld ? rl->r2 : r->rd.r2;
    const long double radx = o->ld ? rl->tau / rl->r2 : (long double)r->rd.tau / r->rd.r2;
    if (o->paper) {
        extreme(&r->xp_r2, relerr(f32v(r->hp.r2), r2x), k);
        extreme(&r->xp_rad, relerr((long double)f32v(r->hp.tau[0]) / f32v(r->hp.r2), radx), k);
    }
    if (o->stable) {
        extreme(&r->xs_r2, relerr(preu_stable_r2(&r->sp), r2x), k);
        extreme(&r->xs_rad, relerr(wide_to_double(r->sp.T[0]) / PI_LD, radx), k);
    }
}

/* The rows of checkpoint k: each datapath and the double reference to the CSV, and to the table
 * when show is set (the long-double reference to the table only). */
static void run_checkpoint(const decade_run_t *r, const opts_t *o, uint64_t k, int show, FILE *csv)
{
    const ref_d_t *rd = &r->rd;
    const ref_ld_t *rl = &r->rl;
    const long double r2c = (long double)r->r2_0 * expl(closed_lnR(k, r->c));
    const double ne_d = o->epa * (double)k;
    const uint32_t NE = preu_n_emitted((uint64_t)llround(ne_d));
    const double Lref = rd->tau * (1.0 / ((PI_D * rd->r2) * ne_d));
    const long double Lref_ld = rl->tau * (1.0L / ((PI_LD * rl->r2) * (long double)ne_d));
    if (o->paper) {
        row_t w;
        uint32_t L[3] = {0, 0, 0};
        preu_radiance(L, &r->hp, NE);
        w.r2 = f32v(r->hp.r2); w.n = f32v(r->hp.n); w.tau = f32v(r->hp.tau[0]); w.rad = w.tau / w.r2; w.L = f32v(L[0]);
        w.e_r2 = relerr(w.r2, rd->r2); w.e_r2c = relerr(w.r2, r2c);
        w.e_n = relerr(w.n, (long double)r->a * (long double)k);
        w.e_tau = relerr(w.tau, rd->tau); w.e_tauld = o->ld ? relerr(w.tau, rl->tau) : NAN;
        w.e_rad = relerr((long double)w.tau / w.r2, (long double)rd->tau / rd->r2); w.e_L = relerr(w.L, Lref);
        if (show) print_row("paper", k, &w);
        csv_row(csv, o, "paper", k, &w);
    }
    if (o->stable) {
        row_t w;
        uint32_t L[3] = {0, 0, 0};
        preu_stable_radiance(L, &r->sp, NE);
        w.r2 = preu_stable_r2(&r->sp); w.n = (double)r->sp.k; w.tau = preu_stable_tau(&r->sp, 0);
        w.rad = wide_to_double(r->sp.T[0]) / PI_D; w.L = f32v(L[0]);
        w.e_r2 = relerr(w.r2, rd->r2); w.e_r2c = relerr(w.r2, r2c);
        w.e_n = r->sp.k == k ? 0 : relerr((long double)r->sp.k, (long double)k);
        w.e_tau = relerr(w.tau, rd->tau); w.e_tauld = o->ld ? relerr(w.tau, rl->tau) : NAN;
        w.e_rad = relerr(wide_to_double(r->sp.T[0]) / PI_LD, (long double)rd->tau / rd->r2); w.e_L = relerr(w.L, Lref);
        if (show) print_row("stable", k, &w);
        csv_row(csv, o, "stable", k, &w);
    }
    {   /* The double reference's own error: r2 against the closed form, tau against long double. */
        row_t w;
        w.r2 = rd->r2; w.n = (double)rd->count; w.tau = rd->tau; w.rad = rd->tau / rd->r2; w.L = Lref;
        w.e_r2 = 0; w.e_r2c = relerr(rd->r2, r2c); w.e_n = 0; w.e_tau = 0;
        w.e_tauld = o->ld ? relerr(rd->tau, rl->tau) : NAN;
        w.e_rad = o->ld ? relerr((long double)rd->tau / rd->r2, rl->tau / rl->r2) : NAN;
        w.e_L = o->ld ? relerr(Lref, Lref_ld) : NAN;
        if (show) print_row("double", k, &w);
        csv_row(csv, o, "double", k, &w);
    }
    if (o->ld && show) {
        row_t w;
        w.r2 = (double)rl->r2; w.n = (double)rl->count; w.tau = (double)rl->tau; w.rad = (double)(rl->tau / rl->r2);
        w.L = (double)Lref_ld;
        w.e_r2 = relerr(rl->r2, rd->r2); w.e_r2c = relerr(rl->r2, r2c); w.e_n = 0; w.e_tau = relerr(rl->tau, rd->tau);
        w.e_tauld = 0; w.e_rad = 0; w.e_L = 0;
        print_row("ldouble", k, &w);
    }
}

/* The end of the run: each state word's change tracking, rejections, the extremes, the time. */
static void print_summary(const decade_run_t *r, const opts_t *o, double sec)
{
    const uint64_t K = o->accepts;
    if (o->paper) {
        char ex[96];
        print_track("paper", "r2", &r->tp_r2, K, NULL);
        snprintf(ex, sizeof ex, " final_N=%.9g", f32v(r->hp.n));
        print_track("paper", "N", &r->tp_n, K, ex);
        print_track("paper", "tau", &r->tp_tau, K, NULL);
        printf("event paper  rejected=%" PRIu64 "\n", r->rej_p);
        printf("extreme paper  r2 min=%+.3e (at %" PRIu64 ") max=%+.3e (at %" PRIu64 ")  rad min=%+.3e (at %" PRIu64
               ") max=%+.3e (at %" PRIu64 ")\n", r->xp_r2.lo, r->xp_r2.at_lo, r->xp_r2.hi, r->xp_r2.at_hi,
               r->xp_rad.lo, r->xp_rad.at_lo, r->xp_rad.hi, r->xp_rad.at_hi);
    }
    if (o->stable) {
        print_track("stable", "w", &r->ts_w, K, NULL);
        print_track("stable", "T", &r->ts_T, K, NULL);
        printf("event stable k final=%" PRIu64 " expected=%" PRIu64 " mismatched_steps=%" PRIu64 " w_saturated=%d"
               " T_saturated=%d\n", r->sp.k, K, r->kbad, r->sp.w == WIDE_MAX, r->sp.T[0] == WIDE_MAX);
        printf("event stable rejected=%" PRIu64 "\n", r->rej_s);
        printf("extreme stable r2 min=%+.3e (at %" PRIu64 ") max=%+.3e (at %" PRIu64 ")  rad min=%+.3e (at %" PRIu64
               ") max=%+.3e (at %" PRIu64 ")\n", r->xs_r2.lo, r->xs_r2.at_lo, r->xs_r2.hi, r->xs_r2.at_hi,
               r->xs_rad.lo, r->xs_rad.at_lo, r->xs_rad.hi, r->xs_rad.at_hi);
    }
    printf("# extremes over accepts 1..%" PRIu64 " against the %s recurrence\n", K, o->ld ? "long-double" : "double");
    printf("seconds %.2f (%.1f ns per accept, all models)\n", sec, 1e9 * sec / (double)K);
}

int run_decades(const opts_t *o)
{
    const uint64_t K = o->accepts;
    g_ld = o->ld;
    uint64_t cp[MAX_CP];
    const int ncp = checkpoints(o, cp);
    int bad;
    FILE *csv = open_csv(o, &bad);
    if (bad) return 2;
    decade_run_t run, *r = &run;
    run_init(r, o);
    print_preamble(r, o);
    print_header();
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int ci = 0;
    for (uint64_t k = 1; k <= K; k++) {
        run_accept(r, o, k);
        if (k != cp[ci]) continue;
        /* A checkpoint: in the table at a power of ten, an --at, and the last one. */
        int show = ci == ncp - 1 || k == K;
        for (uint64_t p = 1; p <= k; p *= 10) {
            if (p == k) show = 1;
            if (p > UINT64_MAX / 10) break;
        }
        for (int i = 0; i < o->n_at; i++) if (o->at[i] == k) show = 1;
        run_checkpoint(r, o, k, show, csv);
        ci++;
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    print_summary(r, o, (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    if (csv) fclose(csv);
    return 0;
}
