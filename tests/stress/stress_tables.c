// SPDX-License-Identifier: Apache-2.0
/* stress_tables.c: the stress program's tables (tests/stress/stress_hitpoint.c): non-finite and
 * out-of-range inputs, N_emitted through 2^24 and 2^32, the references against each other, and
 * what the stable datapath's r2 error is made of. */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>

#include "stress_hitpoint.h"

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

/* One case through the paper datapath: 10 normal accepts (not for r2), the case's value, the case
 * photon ph, then two normal photons ph0; one table line. */
static void nf_paper(const nf_case_t *cs, const preu_photon_t *ph, const preu_photon_t *ph0, uint32_t alpha32)
{
    const uint32_t one = PREU_ONE;
    preu_hp_t hp = {{0, 0, 0}, {one, one, one}, {0, 0, 0}, one, 0};
    if (cs->field != F_R2)
        for (int j = 0; j < 10; j++) preu_update(&hp, ph0, PREU_ALPHA);
    switch (cs->field) {
    case F_WEIGHT: hp.f[0] = hp.f[1] = hp.f[2] = cs->v32; break;
    case F_R2: hp.r2 = cs->v32; break;
    case F_N: hp.n = cs->v32; break;
    case F_TAU: hp.tau[0] = hp.tau[1] = hp.tau[2] = cs->v32; break;
    default: break;
    }
    int a1 = preu_update(&hp, ph, alpha32);
    char r2s[40], taus[40], r2b[40], taub[40], ns[24];
    hexval(r2s, sizeof r2s, hp.r2); hexval(taus, sizeof taus, hp.tau[0]);
    snprintf(ns, sizeof ns, "%.8g", f32v(hp.n));
    int a2 = preu_update(&hp, ph0, alpha32), a3 = preu_update(&hp, ph0, alpha32);
    snprintf(r2b, sizeof r2b, "%.4g", f32v(hp.r2)); snprintf(taub, sizeof taub, "%.4g", f32v(hp.tau[0]));
    printf("%-44s %-6s %d %d %d %-27s %-16s %-27s %s, %s\n", cs->what, "paper", a1, a2, a3, r2s, ns, taus, r2b, taub);
}

/* The same through the stable datapath (no normal accepts first for r2 and w). */
static void nf_stable(const nf_case_t *cs, const preu_photon_t *ph, const preu_photon_t *ph0, uint32_t kappa32)
{
    const uint32_t one = PREU_ONE;
    preu_shp_t sp = {{0, 0, 0}, {one, one, one}, {0, 0, 0}, 0, 0};
    preu_stable_init(&sp, 1.0);
    if (cs->field != F_R2 && cs->field != F_W)
        for (int j = 0; j < 10; j++) preu_stable_update(&sp, ph0, preu_kappa(PREU_ALPHA));
    switch (cs->field) {
    case F_WEIGHT: sp.f[0] = sp.f[1] = sp.f[2] = cs->v32; break;
    case F_R2: preu_stable_init(&sp, f32v(cs->v32)); break;
    case F_W: sp.w = cs->v64; break;
    case F_T: sp.T[0] = sp.T[1] = sp.T[2] = cs->v64; break;
    case F_K: sp.k = cs->v64; break;
    default: break;
    }
    int a1 = preu_stable_update(&sp, ph, kappa32);
    char r2s[48], taus[48], ks[24], r2b[24], taub[24];
    snprintf(r2s, sizeof r2s, "%016" PRIx64 " %-10.4g", sp.w, preu_stable_r2(&sp));
    snprintf(taus, sizeof taus, "%016" PRIx64 " %-10.4g", sp.T[0], preu_stable_tau(&sp, 0));
    snprintf(ks, sizeof ks, "%" PRIu64, sp.k);
    int a2 = preu_stable_update(&sp, ph0, kappa32), a3 = preu_stable_update(&sp, ph0, kappa32);
    snprintf(r2b, sizeof r2b, "%.4g", preu_stable_r2(&sp)); snprintf(taub, sizeof taub, "%.4g", preu_stable_tau(&sp, 0));
    printf("%-44s %-6s %d %d %d %-27s %-16s %-27s %s, %s\n", cs->what, "stable", a1, a2, a3, r2s, ks, taus, r2b, taub);
}

/* Radiance evaluation with special state or NE. */
static void nf_radiance(void)
{
    const uint32_t one = PREU_ONE;
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
}

int run_nonfinite(void)
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
        if (cs->field == F_PHI) ph.phi[0] = ph.phi[1] = ph.phi[2] = cs->v32;
        if (cs->field == F_POS) ph.pos[0] = cs->v32;
        if (cs->field == F_WEIGHT && cs->v32 == 0) ph.phi[0] = ph.phi[1] = ph.phi[2] = 0x7F800000u;
        if (cs->paper) nf_paper(cs, &ph, &ph0, alpha32);
        if (cs->stable) nf_stable(cs, &ph, &ph0, preu_kappa(alpha32));
    }
    nf_radiance();
    return 0;
}

/* ---- N_emitted through 2^24 and 2^32 ------------------------------------------------------ */
int run_ne_table(void)
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
int run_selftest(void)
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

int run_decompose(uint64_t K)
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

