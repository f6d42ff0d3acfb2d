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
#include <float.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "preu_fp32.h"
#include "preu_stable.h"

#define PI_D  3.14159265358979      /* smallppm's pi (model/scene/scene.h PREE_PI)            */
#define PI_LD 3.14159265358979L     /* the same truncated pi in long double              */
#define MAX_AT 32
#define MAX_CP 512

typedef struct {
    uint64_t accepts;
    double alpha, r2, flux, weight, epa;
    int flux_random, paper, stable, ld, per_decade, n_at;
    uint64_t at[MAX_AT];
    const char *csv, *label;
} opts_t;

static double f32v(uint32_t b) { return (double)fp32_from_bits(b); }

/* Relative error of x against ref: 0 when equal (also both 0 or both inf), +-inf when ref is 0
 * and x is not, NaN when either is NaN. */
static double relerr(long double x, long double ref)
{
    if (x == ref) return 0;
    if (isnan(x) || isnan(ref)) return NAN;
    if (ref == 0 || isinf(ref)) return x > ref ? INFINITY : -INFINITY;
    return (double)((x - ref) / ref);
}

static uint64_t splitmix64(uint64_t *s)
{
    uint64_t z = (*s += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* ---- The closed form of the radius product ----------------------------------------------
 * smallppm's g_j = (j a + a) / (j a + 1) = (j + 1) / (j + c), c = 1 / a, so after k accepts
 *   r2_k / r2_0 = R(k) = prod_{j<k} (j + 1) / (j + c) = Gamma(k + 1) Gamma(c) / Gamma(k + c).
 * ln R(k) = lgamma(c) + D(k), D(k) = lnGamma(k + 1) - lnGamma(k + c). For k < 64 the product
 * itself in long double; above, D from Stirling's series written so that nothing large cancels:
 * with x = k + 1, y = k + c, delta = 1 - c,
 *   D = delta ln y + (x - 1/2) log1p(delta / y) - delta + S(x) - S(y),
 *   S(z) = 1/(12 z) - 1/(360 z^3) + 1/(1260 z^5) - 1/(1680 z^7) + 1/(1188 z^9)
 * (truncation below 1e-19 for z >= 64). */
#define CLOSED_K0 64

static long double stirling_s(long double z)
{
    long double iz = 1.0L / z, iz2 = iz * iz;
    return iz * (1.0L / 12 - iz2 * (1.0L / 360 - iz2 * (1.0L / 1260 - iz2 * (1.0L / 1680 - iz2 / 1188))));
}

static long double closed_lnR(uint64_t k, long double c)
{
    if (k < CLOSED_K0) {
        long double p = 1.0L;
        for (uint64_t j = 0; j < k; j++) p *= ((long double)j + 1.0L) / ((long double)j + c);
        return logl(p);
    }
    const long double delta = 1.0L - c;
    const long double x = (long double)k + 1.0L, y = (long double)k + c;
    return lgammal(c) + delta * logl(y) + (x - 0.5L) * log1pl(delta / y) - delta + stirling_s(x) - stirling_s(y);
}

/* ---- The models ----------------------------------------------------------------------- */
typedef struct {              /* smallppm's update in double (or long double), integer count */
    double r2, tau;
    uint64_t count;
} ref_d_t;
typedef struct {
    long double r2, tau;
    uint64_t count;
} ref_ld_t;

static inline void ref_d_update(ref_d_t *s, double a, double f, double phi)
{
    /* model/ppm/update.h update_accept_double: g = (n a + a) / (n a + 1); r2 *= g; n++;
     * tau = (tau + f phi (1 / PI)) g. */
    double g = ((double)s->count * a + a) / ((double)s->count * a + 1.0);
    s->r2 = s->r2 * g;
    s->count++;
    s->tau = (s->tau + (f * phi) * (1. / PI_D)) * g;
}

static inline void ref_ld_update(ref_ld_t *s, long double a, long double f, long double phi)
{
    long double g = ((long double)s->count * a + a) / ((long double)s->count * a + 1.0L);
    s->r2 = s->r2 * g;
    s->count++;
    s->tau = (s->tau + (f * phi) * (1.0L / PI_LD)) * g;
}

/* ---- Change tracking: first accept with an unchanged word, last accept that changed it ---- */
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

static void fmt_err(char *b, size_t n, double e)
{
    if (e == 0) snprintf(b, n, "0");
    else if (isnan(e)) snprintf(b, n, "nan");
    else snprintf(b, n, "%+.2e", e);
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

static int run_decades(const opts_t *o)
{
    const uint64_t K = o->accepts;
    const uint32_t alpha32 = preu_f32(o->alpha), kappa32 = preu_kappa(alpha32);
    const uint32_t r2_32 = preu_f32(o->r2), f32w = preu_f32(o->weight), flux32 = preu_f32(o->flux);
    const double a = f32v(alpha32), r2_0 = f32v(r2_32), fw = f32v(f32w);
    const long double c = 1.0L / (long double)a;
    g_ld = o->ld;

    /* Checkpoints: 10^(d + i/P) up to K, the --at list, K; table rows at powers of ten, --at, K. */
    uint64_t cp[MAX_CP];
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
    ncp = m;

    FILE *csv = NULL;
    if (o->csv) {
        FILE *t = fopen(o->csv, "r");
        int fresh = !t;
        if (t) fclose(t);
        csv = fopen(o->csv, "a");
        if (!csv) { fprintf(stderr, "stress_hitpoint: cannot write %s\n", o->csv); return 2; }
        if (fresh)
            fprintf(csv, "label,model,alpha,r2_0,flux,flux_mode,emitted_per_accept,accepts,err_r2_double,err_r2_closed,"
                         "err_n,err_tau_double,err_tau_ld,err_rad_double,err_L_double,r2,n,tau,L\n");
    }

    printf("# one hit point, %" PRIu64 " accepted photons (distance 0); alpha %.9g (binary32 0x%08x), kappa %.9g "
           "(0x%08x)\n# r2_0 %.9g (0x%08x), flux %.9g (0x%08x) %s, weight %.9g, N_emitted = %.9g x accepts\n",
           K, a, alpha32, f32v(kappa32), kappa32, r2_0, r2_32, f32v(flux32), flux32,
           o->flux_random ? "x u, u in [0.5, 1.5) (splitmix64)" : "constant", fw, o->epa);
    printf("# errors: relative, signed; r2/closed against Gamma(k+1) Gamma(1/a) / Gamma(k+1/a); "
           "tau/ld against the long-double recurrence;\n# rad = tau / r2 (stable: T / PI); L = the datapath's "
           "radiance word, NE = binary32(N_emitted), against tau / (PI r2 N_emitted) in double\n");
    {
        long double lr = closed_lnR(K, c), lr7 = closed_lnR(K, 1.0L / (long double)o->alpha);
        printf("# alpha rounding: the closed-form r2 at %" PRIu64 " accepts with alpha = %.17g (double) differs from "
               "alpha = binary32 by %+.2e\n", K, o->alpha, (double)expm1l(lr7 - lr));
    }

    preu_hp_t hp = {{0, 0, 0}, {f32w, f32w, f32w}, {0, 0, 0}, r2_32, 0};
    preu_shp_t sp = {{0, 0, 0}, {f32w, f32w, f32w}, {0, 0, 0}, 0, 0};
    preu_stable_init(&sp, r2_0);
    ref_d_t rd = {r2_0, 0, 0};
    ref_ld_t rl = {r2_0, 0, 0};
    track_t tp_r2 = {0}, tp_n = {0}, tp_tau = {0}, ts_w = {0}, ts_T = {0};
    extreme_t xp_r2 = {INFINITY, -INFINITY, 0, 0}, xp_rad = xp_r2, xs_r2 = xp_r2, xs_rad = xp_r2;
    uint64_t rej_p = 0, rej_s = 0, seed = 12345, kbad = 0;
    preu_photon_t ph = {{0, 0, 0}, {flux32, flux32, flux32}};

    print_header();
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int ci = 0;
    for (uint64_t k = 1; k <= K; k++) {
        if (o->flux_random) {
            double u = 0.5 + (double)(splitmix64(&seed) >> 11) * 0x1p-53;
            uint32_t p = preu_f32(o->flux * u);
            ph.phi[0] = ph.phi[1] = ph.phi[2] = p;
        }
        const double phi = f32v(ph.phi[0]);
        if (o->paper) {
            const uint32_t r2o = hp.r2, no = hp.n, to = hp.tau[0];
            if (!preu_update(&hp, &ph, alpha32)) rej_p++;
            track(&tp_r2, hp.r2 != r2o, k);
            track(&tp_n, hp.n != no, k);
            track(&tp_tau, hp.tau[0] != to, k);
        }
        if (o->stable) {
            const uint64_t wo = sp.w, To = sp.T[0];
            if (!preu_stable_update(&sp, &ph, kappa32)) rej_s++;
            track(&ts_w, sp.w != wo, k);
            track(&ts_T, sp.T[0] != To, k);
            if (sp.k != k) kbad++;
        }
        ref_d_update(&rd, a, fw, phi);
        if (o->ld) ref_ld_update(&rl, a, fw, phi);
        /* Extremes over every accept, against the long-double recurrence (else double). */
        const long double r2x = o->ld ? rl.r2 : rd.r2, radx = o->ld ? rl.tau / rl.r2 : (long double)rd.tau / rd.r2;
        if (o->paper) {
            extreme(&xp_r2, relerr(f32v(hp.r2), r2x), k);
            extreme(&xp_rad, relerr((long double)f32v(hp.tau[0]) / f32v(hp.r2), radx), k);
        }
        if (o->stable) {
            extreme(&xs_r2, relerr(preu_stable_r2(&sp), r2x), k);
            extreme(&xs_rad, relerr(wide_to_double(sp.T[0]) / PI_LD, radx), k);
        }
        if (k != cp[ci]) continue;
        /* A checkpoint. */
        const int table = ci == ncp - 1 || k == K;
        int is_dec = 0;
        for (uint64_t p = 1; p <= k; p *= 10) {
            if (p == k) is_dec = 1;
            if (p > UINT64_MAX / 10) break;
        }
        int is_at = 0;
        for (int i = 0; i < o->n_at; i++) if (o->at[i] == k) is_at = 1;
        const long double r2c = (long double)r2_0 * expl(closed_lnR(k, c));
        const double ne_d = o->epa * (double)k;
        const uint32_t NE = preu_n_emitted((uint64_t)llround(ne_d));
        const double Lref = rd.tau * (1.0 / ((PI_D * rd.r2) * ne_d));
        const long double Lref_ld = rl.tau * (1.0L / ((PI_LD * rl.r2) * (long double)ne_d));
        if (o->paper) {
            row_t r;
            uint32_t L[3] = {0, 0, 0};
            preu_radiance(L, &hp, NE);
            r.r2 = f32v(hp.r2); r.n = f32v(hp.n); r.tau = f32v(hp.tau[0]); r.rad = r.tau / r.r2; r.L = f32v(L[0]);
            r.e_r2 = relerr(r.r2, rd.r2); r.e_r2c = relerr(r.r2, r2c);
            r.e_n = relerr(r.n, (long double)a * (long double)k);
            r.e_tau = relerr(r.tau, rd.tau); r.e_tauld = o->ld ? relerr(r.tau, rl.tau) : NAN;
            r.e_rad = relerr((long double)r.tau / r.r2, (long double)rd.tau / rd.r2); r.e_L = relerr(r.L, Lref);
            if (is_dec || is_at || table) print_row("paper", k, &r);
            csv_row(csv, o, "paper", k, &r);
        }
        if (o->stable) {
            row_t r;
            uint32_t L[3] = {0, 0, 0};
            preu_stable_radiance(L, &sp, NE);
            r.r2 = preu_stable_r2(&sp); r.n = (double)sp.k; r.tau = preu_stable_tau(&sp, 0);
            r.rad = wide_to_double(sp.T[0]) / PI_D; r.L = f32v(L[0]);
            r.e_r2 = relerr(r.r2, rd.r2); r.e_r2c = relerr(r.r2, r2c);
            r.e_n = sp.k == k ? 0 : relerr((long double)sp.k, (long double)k);
            r.e_tau = relerr(r.tau, rd.tau); r.e_tauld = o->ld ? relerr(r.tau, rl.tau) : NAN;
            r.e_rad = relerr(wide_to_double(sp.T[0]) / PI_LD, (long double)rd.tau / rd.r2); r.e_L = relerr(r.L, Lref);
            if (is_dec || is_at || table) print_row("stable", k, &r);
            csv_row(csv, o, "stable", k, &r);
        }
        {   /* The double reference's own error: r2 against the closed form, tau against long double. */
            row_t r;
            r.r2 = rd.r2; r.n = (double)rd.count; r.tau = rd.tau; r.rad = rd.tau / rd.r2; r.L = Lref;
            r.e_r2 = 0; r.e_r2c = relerr(rd.r2, r2c); r.e_n = 0; r.e_tau = 0;
            r.e_tauld = o->ld ? relerr(rd.tau, rl.tau) : NAN;
            r.e_rad = o->ld ? relerr((long double)rd.tau / rd.r2, rl.tau / rl.r2) : NAN;
            r.e_L = o->ld ? relerr(Lref, Lref_ld) : NAN;
            if (is_dec || is_at || table) print_row("double", k, &r);
            csv_row(csv, o, "double", k, &r);
        }
        if (o->ld && (is_dec || is_at || table)) {
            row_t r;
            r.r2 = (double)rl.r2; r.n = (double)rl.count; r.tau = (double)rl.tau; r.rad = (double)(rl.tau / rl.r2);
            r.L = (double)Lref_ld;
            r.e_r2 = relerr(rl.r2, rd.r2); r.e_r2c = relerr(rl.r2, r2c); r.e_n = 0; r.e_tau = relerr(rl.tau, rd.tau);
            r.e_tauld = 0; r.e_rad = 0; r.e_L = 0;
            print_row("ldouble", k, &r);
        }
        ci++;
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    const double sec = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    if (o->paper) {
        char ex[96];
        print_track("paper", "r2", &tp_r2, K, NULL);
        snprintf(ex, sizeof ex, " final_N=%.9g", f32v(hp.n));
        print_track("paper", "N", &tp_n, K, ex);
        print_track("paper", "tau", &tp_tau, K, NULL);
        printf("event paper  rejected=%" PRIu64 "\n", rej_p);
        printf("extreme paper  r2 min=%+.3e (at %" PRIu64 ") max=%+.3e (at %" PRIu64 ")  rad min=%+.3e (at %" PRIu64
               ") max=%+.3e (at %" PRIu64 ")\n", xp_r2.lo, xp_r2.at_lo, xp_r2.hi, xp_r2.at_hi, xp_rad.lo, xp_rad.at_lo,
               xp_rad.hi, xp_rad.at_hi);
    }
    if (o->stable) {
        print_track("stable", "w", &ts_w, K, NULL);
        print_track("stable", "T", &ts_T, K, NULL);
        printf("event stable k final=%" PRIu64 " expected=%" PRIu64 " mismatched_steps=%" PRIu64 " w_saturated=%d"
               " T_saturated=%d\n", sp.k, K, kbad, sp.w == WIDE_MAX, sp.T[0] == WIDE_MAX);
        printf("event stable rejected=%" PRIu64 "\n", rej_s);
        printf("extreme stable r2 min=%+.3e (at %" PRIu64 ") max=%+.3e (at %" PRIu64 ")  rad min=%+.3e (at %" PRIu64
               ") max=%+.3e (at %" PRIu64 ")\n", xs_r2.lo, xs_r2.at_lo, xs_r2.hi, xs_r2.at_hi, xs_rad.lo, xs_rad.at_lo,
               xs_rad.hi, xs_rad.at_hi);
    }
    printf("# extremes over accepts 1..%" PRIu64 " against the %s recurrence\n", K, o->ld ? "long-double" : "double");
    printf("seconds %.2f (%.1f ns per accept, all models)\n", sec, 1e9 * sec / (double)K);
    if (csv) fclose(csv);
    return 0;
}

/* ---- Non-finite and out-of-range inputs -------------------------------------------------- */
enum { F_PHI, F_POS, F_WEIGHT, F_R2, F_N, F_TAU, F_W, F_T, F_K, F_ALPHA };
typedef struct {
    const char *what;
    int field;
    uint32_t v32;   /* binary32 word for the paper datapath (and photon/weight for both) */
    uint64_t v64;   /* stable word (F_W, F_T, F_K) */
    int paper, stable;
} nf_case_t;

static const nf_case_t NF_CASES[] = {
    {"photon flux qNaN 0x7fc00000", F_PHI, 0x7FC00000u, 0, 1, 1},
    {"photon flux sNaN 0x7f800001", F_PHI, 0x7F800001u, 0, 1, 1},
    {"photon flux +inf", F_PHI, 0x7F800000u, 0, 1, 1},
    {"photon flux -inf", F_PHI, 0xFF800000u, 0, 1, 1},
    {"photon flux -1", F_PHI, 0xBF800000u, 0, 1, 1},
    {"photon flux -0", F_PHI, 0x80000000u, 0, 1, 1},
    {"photon flux 1e-40 (subnormal)", F_PHI, 0x000116C2u, 0, 1, 1},
    {"photon flux FLT_MAX", F_PHI, 0x7F7FFFFFu, 0, 1, 1},
    {"photon position x NaN", F_POS, 0x7FC00000u, 0, 1, 1},
    {"photon position x +inf", F_POS, 0x7F800000u, 0, 1, 1},
    {"photon position x 1e30 (d2 overflows)", F_POS, 0x7149F2CAu, 0, 1, 1},
    {"weight NaN", F_WEIGHT, 0x7FC00000u, 0, 1, 1},
    {"weight -1", F_WEIGHT, 0xBF800000u, 0, 1, 1},
    {"weight +inf", F_WEIGHT, 0x7F800000u, 0, 1, 1},
    {"weight 0, photon flux +inf", F_WEIGHT, 0, 0, 1, 1},
    {"r2 +inf (stable: w = 1/r2 = 0)", F_R2, 0x7F800000u, 0, 1, 1},
    {"r2 NaN", F_R2, 0x7FC00000u, 0, 1, 1},
    {"r2 0 (stable: w = inf)", F_R2, 0, 0, 1, 1},
    {"r2 -0", F_R2, 0x80000000u, 0, 1, 1},
    {"r2 -1", F_R2, 0xBF800000u, 0, 1, 1},
    {"r2 1e-40 (subnormal; stable: w > FLT_MAX)", F_R2, 0x000116C2u, 0, 1, 1},
    {"r2 3e-39 (stable: w just below FLT_MAX)", F_R2, 0x0020AAFEu, 0, 1, 1},
    {"r2 FLT_MAX", F_R2, 0x7F7FFFFFu, 0, 1, 1},
    {"paper N qNaN", F_N, 0x7FC00000u, 0, 1, 0},
    {"paper N +inf", F_N, 0x7F800000u, 0, 1, 0},
    {"paper N 2^24", F_N, 0x4B800000u, 0, 1, 0},
    {"paper N -1", F_N, 0xBF800000u, 0, 1, 0},
    {"paper tau NaN", F_TAU, 0x7FC00000u, 0, 1, 0},
    {"paper tau +inf", F_TAU, 0x7F800000u, 0, 1, 0},
    {"stable w WIDE_NAN", F_W, 0, WIDE_NAN, 0, 1},
    {"stable w WIDE_INF", F_W, 0, WIDE_INF, 0, 1},
    {"stable w WIDE_MAX (saturated)", F_W, 0, WIDE_MAX, 0, 1},
    {"stable w 0 (r2 = inf)", F_W, 0, WIDE_ZERO, 0, 1},
    {"stable T WIDE_NAN", F_T, 0, WIDE_NAN, 0, 1},
    {"stable T WIDE_INF", F_T, 0, WIDE_INF, 0, 1},
    {"stable T WIDE_MAX", F_T, 0, WIDE_MAX, 0, 1},
    {"stable k 2^32 - 1", F_K, 0, UINT64_C(0xFFFFFFFF), 0, 1},
    {"stable k 2^64 - 1 (wraps)", F_K, 0, UINT64_MAX, 0, 1},
    {"alpha 0 (stable: kappa = inf)", F_ALPHA, 0, 0, 1, 1},
    {"alpha 1 (kappa = 0)", F_ALPHA, 0x3F800000u, 0, 1, 1},
    {"alpha 1.5 (kappa < 0)", F_ALPHA, 0x3FC00000u, 0, 1, 1},
    {"alpha NaN", F_ALPHA, 0x7FC00000u, 0, 1, 1},
};

static void hexval(char *b, size_t n, uint32_t w) { snprintf(b, n, "%08x %-11.4g", w, f32v(w)); }

static int run_nonfinite(void)
{
    const uint32_t one = PREU_ONE;
    printf("# Non-finite and out-of-range inputs. Start: r2_0 = 1, 10 accepts of flux 1, weight 1 at distance 0\n"
           "# (the r2 and stable-w cases start instead from a fresh hit point, count 0 and flux 0, with that r2 or w);\n"
           "# then the case's value is set and one photon (flux 1 at distance 0 unless the case says otherwise) is\n"
           "# offered, then two normal photons. acc: accepted (1) or not (0), for the case photon and the next two.\n"
           "# Stable words: w and T in the wide format (hex), with the host views r2 = 1/w and tau = T r2 / PI.\n");
    printf("%-44s %-6s %-5s %-27s %-16s %-27s %-34s\n", "case", "model", "acc", "r2 after (word, value)", "N / k after",
           "tau after (word, value)", "after 2 more: r2, tau");
    for (size_t i = 0; i < sizeof NF_CASES / sizeof NF_CASES[0]; i++) {
        const nf_case_t *cs = &NF_CASES[i];
        preu_photon_t ph = {{0, 0, 0}, {one, one, one}}, ph0 = ph;
        uint32_t alpha32 = PREU_ALPHA;
        if (cs->field == F_ALPHA) alpha32 = cs->v32;
        const uint32_t kappa32 = preu_kappa(alpha32);
        if (cs->field == F_PHI) ph.phi[0] = ph.phi[1] = ph.phi[2] = cs->v32;
        if (cs->field == F_POS) ph.pos[0] = cs->v32;
        if (cs->field == F_WEIGHT && cs->v32 == 0) ph.phi[0] = ph.phi[1] = ph.phi[2] = 0x7F800000u;
        if (cs->paper) {
            preu_hp_t hp = {{0, 0, 0}, {one, one, one}, {0, 0, 0}, one, 0};
            if (cs->field != F_R2)
                for (int j = 0; j < 10; j++) preu_update(&hp, &ph0, PREU_ALPHA);
            switch (cs->field) {
            case F_WEIGHT: hp.f[0] = hp.f[1] = hp.f[2] = cs->v32; break;
            case F_R2: hp.r2 = cs->v32; break;
            case F_N: hp.n = cs->v32; break;
            case F_TAU: hp.tau[0] = hp.tau[1] = hp.tau[2] = cs->v32; break;
            default: break;
            }
            int a1 = preu_update(&hp, &ph, alpha32);
            char r2s[40], taus[40], r2b[40], taub[40], ns[24];
            hexval(r2s, sizeof r2s, hp.r2); hexval(taus, sizeof taus, hp.tau[0]);
            snprintf(ns, sizeof ns, "%.8g", f32v(hp.n));
            int a2 = preu_update(&hp, &ph0, alpha32), a3 = preu_update(&hp, &ph0, alpha32);
            snprintf(r2b, sizeof r2b, "%.4g", f32v(hp.r2)); snprintf(taub, sizeof taub, "%.4g", f32v(hp.tau[0]));
            printf("%-44s %-6s %d %d %d %-27s %-16s %-27s %s, %s\n", cs->what, "paper", a1, a2, a3, r2s, ns, taus, r2b, taub);
        }
        if (cs->stable) {
            preu_shp_t sp = {{0, 0, 0}, {one, one, one}, {0, 0, 0}, 0, 0};
            preu_stable_init(&sp, 1.0);
            if (cs->field != F_R2 && cs->field != F_W)
                for (int j = 0; j < 10; j++) preu_stable_update(&sp, &ph0, preu_kappa(PREU_ALPHA));
            switch (cs->field) {
            case F_WEIGHT: sp.f[0] = sp.f[1] = sp.f[2] = cs->v32; break;
            case F_R2: preu_stable_init(&sp, f32v(cs->v32)); break;
            case F_W: sp.w = cs->v64; break;
            case F_T: sp.T[0] = sp.T[1] = sp.T[2] = cs->v64; break;
            case F_K: sp.k = cs->v64; break;
            default: break;
            }
            int a1 = preu_stable_update(&sp, &ph, kappa32);
            char r2s[48], taus[48], ks[24], r2b[24], taub[24];
            snprintf(r2s, sizeof r2s, "%016" PRIx64 " %-10.4g", sp.w, preu_stable_r2(&sp));
            snprintf(taus, sizeof taus, "%016" PRIx64 " %-10.4g", sp.T[0], preu_stable_tau(&sp, 0));
            snprintf(ks, sizeof ks, "%" PRIu64, sp.k);
            int a2 = preu_stable_update(&sp, &ph0, kappa32), a3 = preu_stable_update(&sp, &ph0, kappa32);
            snprintf(r2b, sizeof r2b, "%.4g", preu_stable_r2(&sp)); snprintf(taub, sizeof taub, "%.4g", preu_stable_tau(&sp, 0));
            printf("%-44s %-6s %d %d %d %-27s %-16s %-27s %s, %s\n", cs->what, "stable", a1, a2, a3, r2s, ks, taus, r2b, taub);
        }
    }
    /* Radiance evaluation with special state. */
    printf("\n# Radiance evaluation (L starts at 0): the datapath's L word for a special state or NE\n");
    printf("%-44s %-6s %s\n", "case", "model", "L (word, value)");
    struct { const char *what; uint32_t r2, tau, ne; } pr[] = {
        {"paper r2 0, tau 0", 0, 0, 0x447A0000u},           /* NE = 1000 */
        {"paper r2 0, tau 1", 0, one, 0x447A0000u},
        {"paper r2 1, tau NaN", one, 0x7FC00000u, 0x447A0000u},
        {"paper r2 1, tau 1, NE 0", one, one, 0},
        {"paper r2 1e30, tau 1, NE 1e9 (PI r2 NE > FLT_MAX)", 0x7149F2CAu, one, 0x4E6E6B28u},
        {"paper r2 1e-40, tau 1, NE 1 (1/(PI r2 NE) > FLT_MAX)", 0x000116C2u, one, one},
    };
    for (size_t i = 0; i < sizeof pr / sizeof pr[0]; i++) {
        preu_hp_t hp = {{0, 0, 0}, {one, one, one}, {pr[i].tau, pr[i].tau, pr[i].tau}, pr[i].r2, 0};
        uint32_t L[3] = {0, 0, 0};
        preu_radiance(L, &hp, pr[i].ne);
        char s[40];
        hexval(s, sizeof s, L[0]);
        printf("%-44s %-6s %s\n", pr[i].what, "paper", s);
    }
    struct { const char *what; uint64_t T; uint32_t ne; } sr[] = {
        {"stable T 0, NE 1000", WIDE_ZERO, 0x447A0000u},
        {"stable T NaN", WIDE_NAN, 0x447A0000u},
        {"stable T WIDE_INF", WIDE_INF, 0x447A0000u},
        {"stable T WIDE_MAX, NE 1000", WIDE_MAX, 0x447A0000u},
        {"stable T WIDE_MAX, NE 0.01 (L overflows)", WIDE_MAX, 0x3C23D70Au},
        {"stable T 1, NE 0", wide_from_double(1.0), 0},
        {"stable T 0, NE 0", WIDE_ZERO, 0},
    };
    for (size_t i = 0; i < sizeof sr / sizeof sr[0]; i++) {
        preu_shp_t sp = {{0, 0, 0}, {one, one, one}, {sr[i].T, sr[i].T, sr[i].T}, wide_from_double(1.0), 1};
        uint32_t L[3] = {0, 0, 0};
        preu_stable_radiance(L, &sp, sr[i].ne);
        char s[40];
        hexval(s, sizeof s, L[0]);
        printf("%-44s %-6s %s\n", sr[i].what, "stable", s);
    }
    return 0;
}

/* ---- N_emitted through 2^24 and 2^32 ------------------------------------------------------ */
static int run_ne_table(void)
{
    static const uint64_t counts[] = {
        16777215, 16777216, 16777217, 16777219, 100000001, 768000ull * 64, 4294967295ull, 4294967296ull,
        4294967297ull, 4294967553ull, 10000000007ull, 1000000000000ull + 1, (1ull << 53) + 1, UINT64_MAX};
    printf("# N_emitted -> NE = preu_n_emitted (binary32, nearest even); u64_to_f32 is the stable datapath's count\n"
           "# converter (rtl/pree_u64_to_f32.v); L: one radiance evaluation of a hit point after 1000 accepts of flux 1\n"
           "# (r2_0 = 1, alpha 0.7) against tau / (PI r2 N_emitted) in double with the exact count\n");
    printf("%-22s %-12s %-16s %-10s %-8s %-11s %-11s\n", "N_emitted", "NE (hex)", "NE", "rel.err", "u64_to_f32",
           "L paper", "L stable");
    const uint32_t one = PREU_ONE;
    preu_hp_t hp = {{0, 0, 0}, {one, one, one}, {0, 0, 0}, one, 0};
    preu_shp_t sp = {{0, 0, 0}, {one, one, one}, {0, 0, 0}, 0, 0};
    preu_stable_init(&sp, 1.0);
    ref_d_t rd = {1.0, 0, 0};
    preu_photon_t ph = {{0, 0, 0}, {one, one, one}};
    const uint32_t kappa = preu_kappa(PREU_ALPHA);
    for (int j = 0; j < 1000; j++) {
        preu_update(&hp, &ph, PREU_ALPHA);
        preu_stable_update(&sp, &ph, kappa);
        ref_d_update(&rd, f32v(PREU_ALPHA), 1.0, 1.0);
    }
    int bad = 0;
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        const uint64_t n = counts[i];
        const uint32_t ne = preu_n_emitted(n), ne2 = u64_to_f32(n);
        const double e = relerr((long double)f32v(ne), (long double)n);
        if (fabs(e) > 0x1p-24) bad = 1;
        uint32_t Lp[3] = {0, 0, 0}, Ls[3] = {0, 0, 0};
        preu_radiance(Lp, &hp, ne);
        preu_stable_radiance(Ls, &sp, ne);
        const long double Lref = (long double)rd.tau / ((long double)PI_D * rd.r2 * (long double)n);
        char eb[16], p[16], s[16];
        fmt_err(eb, sizeof eb, e);
        fmt_err(p, sizeof p, relerr(f32v(Lp[0]), Lref));
        fmt_err(s, sizeof s, relerr(f32v(Ls[0]), Lref));
        printf("%-22" PRIu64 " %08x     %-16.10g %-10s %-8s %-11s %-11s\n", n, ne, f32v(ne), eb, ne == ne2 ? "same" : "DIFFERS",
               p, s);
    }
    printf("# |NE rel.err| <= 2^-24 = 5.96e-08 for every count: %s\n", bad ? "NO" : "yes");
    return bad;
}

/* ---- The references against each other -------------------------------------------------- */
static int run_selftest(void)
{
    int fail = 0;
    static const double alphas[] = {0.1, 0.3, 0.5, 0.7, 0.9, 1.0};
    printf("# closed form: product (k < %d) against Stirling (k >= %d) at k = 64..400, and against the double and\n"
           "# long-double recurrences at k <= 10^5; the long-double recurrence against the closed form at 10^6\n", CLOSED_K0, CLOSED_K0);
    for (size_t i = 0; i < sizeof alphas / sizeof alphas[0]; i++) {
        const double a = f32v(preu_f32(alphas[i]));
        const long double c = 1.0L / (long double)a;
        long double p = 1.0L, maxd = 0;
        for (uint64_t j = 0; j < 400; j++) {
            if (j >= CLOSED_K0) { long double d = fabsl(closed_lnR(j, c) - logl(p)); if (d > maxd) maxd = d; }
            p *= ((long double)j + 1.0L) / ((long double)j + c);
        }
        ref_d_t rd = {1.0, 0, 0};
        ref_ld_t rl = {1.0L, 0, 0};
        double maxdd = 0, maxld = 0;
        for (uint64_t k = 1; k <= 1000000; k++) {
            ref_d_update(&rd, a, 1.0, 1.0);
            ref_ld_update(&rl, a, 1.0L, 1.0L);
            if (k <= 100000) {
                long double r2c = expl(closed_lnR(k, c));
                if (r2c < 1e-300L) continue;   /* beyond double's range (alpha 0.1) */
                double dd = fabs(relerr(rd.r2, r2c)), dl = fabs(relerr(rl.r2, r2c));
                if (dd > maxdd) maxdd = dd;
                if (dl > maxld) maxld = dl;
            }
        }
        double end_ld = relerr(rl.r2, expl(closed_lnR(1000000, c)));
        int ok = maxd < 1e-17L && maxdd < 1e-10 && maxld < 1e-14 && fabs(end_ld) < 1e-13;
        if (!ok) fail = 1;
        printf("alpha %-4g  |ln R| Stirling vs product <= %.1e; double recurrence vs closed <= %.1e, long double <= %.1e "
               "(k <= 1e5); long double at 1e6: %+.1e  %s\n",
               alphas[i], (double)maxd, maxdd, maxld, end_ld, ok ? "ok" : "FAIL");
    }
    printf("selftest %s\n", fail ? "FAILED" : "passed");
    return fail;
}

/* ---- What the stable datapath's r2 error is made of -------------------------------------
 * w' = w + w32 e: the exact recurrence w (1 + kappa / k) in long double with one datapath effect
 * at a time: the increment taken from w truncated to 24 significant bits (wide_f32), and kappa
 * rounded to binary32 (preu_kappa); both; and the datapath itself. */
static long double trunc24(long double w)
{
    int e;
    long double m = frexpl(w, &e);
    return ldexpl(floorl(ldexpl(m, 24)), e - 24);
}

static int run_decompose(uint64_t K)
{
    const uint32_t k32 = preu_kappa(PREU_ALPHA);
    const long double a = f32v(PREU_ALPHA), ke = (1.0L - a) / a, kf = f32v(k32);
    long double w0 = 1, w1 = 1, w2 = 1, w3 = 1;
    preu_shp_t sp = {{0, 0, 0}, {PREU_ONE, PREU_ONE, PREU_ONE}, {0, 0, 0}, 0, 0};
    preu_stable_init(&sp, 1.0);
    const preu_photon_t ph = {{0, 0, 0}, {PREU_ONE, PREU_ONE, PREU_ONE}};
    printf("# stable datapath, alpha %.9g, r2_0 = 1: r2 error against the exact recurrence, kappa = %.9g (binary32: "
           "%.9g, %+.2e)\n", (double)a, (double)ke, (double)kf, (double)(kf / ke - 1));
    printf("%14s %16s %16s %16s %16s\n", "accepts", "w32 truncation", "kappa rounding", "both", "datapath");
    uint64_t next = 10;
    for (uint64_t k = 1; k <= K; k++) {
        w0 = w0 * (1.0L + ke / (long double)k);
        w1 = w1 + trunc24(w1) * ke / (long double)k;
        w2 = w2 * (1.0L + kf / (long double)k);
        w3 = w3 + trunc24(w3) * kf / (long double)k;
        preu_stable_update(&sp, &ph, k32);
        if (k == next || k == K) {
            printf("%14" PRIu64 " %+16.2e %+16.2e %+16.2e %+16.2e\n", k, (double)(w0 / w1 - 1), (double)(w0 / w2 - 1),
                   (double)(w0 / w3 - 1), (double)(w0 / wide_to_double(sp.w) - 1));
            if (k == next) next *= 10;
        }
    }
    return 0;
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
