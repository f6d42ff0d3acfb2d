// SPDX-License-Identifier: Apache-2.0
/* preu_vec.c: PREU bench operation sequences (see preu_vec.h) and their expected results. */
#include "preu_vec.h"

#include <math.h>
#include <string.h>

/* xorshift64*: a fixed, portable random sequence. */
static uint64_t rng_state;
static uint32_t rnd32(void)
{
    rng_state ^= rng_state >> 12; rng_state ^= rng_state << 25; rng_state ^= rng_state >> 27;
    return (uint32_t)((rng_state * 0x2545F4914F6CDD1Dull) >> 32);
}
static uint64_t rnd64(void) { uint64_t h = rnd32(); return h << 32 | rnd32(); }
static uint32_t rndn(uint32_t n) { return rnd32() % n; }
static double rndu(double lo, double hi) { return lo + (hi - lo) * (rnd32() * 0x1p-32); }
/* log-uniform in [lo, hi] */
static double rndlog(double lo, double hi) { return exp(log(lo) + rndu(0.0, 1.0) * log(hi / lo)); }

static const uint32_t SPECIAL[] = {
    0x00000000u, 0x80000000u, 0x7f800000u, 0xff800000u, 0x7fc00000u, 0xffc00000u,
    0x7f800001u, 0xff812345u, 0x7fd00badu, 0x00000001u, 0x807fffffu, 0x00800000u,
    0x7f7fffffu, 0xff7fffffu, 0x3f800000u, 0x3f333333u, 0x4b800000u, 0x4b000000u};
#define N_SPECIAL (sizeof SPECIAL / sizeof SPECIAL[0])

/* Wide words worth hitting: zero, e field 0, 1, 254, WIDE_MAX, infinity, NaNs. */
static const uint64_t WSPECIAL[] = {
    WIDE_ZERO, UINT64_C(1), UINT64_C(0x00FFFFFFFFFFFFFF), UINT64_C(0x0180000000000000),
    WIDE_MAX, UINT64_C(0xFEFFFFFF00000000), WIDE_INF, WIDE_NAN, UINT64_C(0xFF00000000000001),
    UINT64_C(0x7F80000000000000), UINT64_C(0x7FFFFFFFFFFFFFFF)};
#define N_WSPECIAL (sizeof WSPECIAL / sizeof WSPECIAL[0])

static uint32_t special_or_random(void)
{
    return rndn(3) ? SPECIAL[rndn(N_SPECIAL)] : rnd32();
}

static void put64(uint32_t *st, int i, uint64_t x) { preu_hpw_put64(st, i, x); }

/* Sprinkle special values over the operation's input words with probability 1/4 each. */
static void add_specials(preu_vec_t *v, int datapath)
{
    for (int k = 0; k < 3; k++) {
        if (rndn(4) == 0) v->hp.pos[k] = special_or_random();
        if (rndn(4) == 0) v->hp.f[k] = special_or_random();
        if (rndn(4) == 0) v->ph.pos[k] = special_or_random();
        if (rndn(4) == 0) v->ph.phi[k] = special_or_random();
        if (rndn(4) == 0) v->l[k] = special_or_random();
    }
    if (!datapath) {
        for (int k = 0; k < 5; k++) if (rndn(4) == 0) v->hp.st[k] = special_or_random();
    } else {
        for (int k = 0; k < 4; k++)
            if (rndn(4) == 0) put64(v->hp.st, k, rndn(3) ? WSPECIAL[rndn(N_WSPECIAL)] : rnd64());
        if (rndn(4) == 0) put64(v->hp.st, 4, rndn(2) ? ~UINT64_C(0) - rndn(2) : rnd64());
    }
}

static uint32_t rnd_count(void)
{
    switch (rndn(4)) {
    case 0: return 0;
    case 1: return preu_f32(0.7 * rndn(64));
    case 2: return preu_f32(0.7 * (double)(uint64_t)rndlog(1.0, 3.0e7));
    default: return preu_f32(rndlog(0.5, 4.0e7));
    }
}

static uint64_t rnd_count64(void)
{
    switch (rndn(6)) {
    case 0: return 0;
    case 1: return rndn(64);
    case 2: return (UINT64_C(1) << 24) - 2 + rndn(4);
    case 3: return (UINT64_C(1) << 32) - 2 + rndn(4);
    case 4: return (uint64_t)rndlog(1.0, 1e15);
    default: return rnd64() >> rndn(64);
    }
}

/* A wide value near x, with random low significand bits (truncation matters there). */
static uint64_t rnd_wide(double x)
{
    uint64_t w = wide_from_double(x);
    if (wide_exp(w) >= 1 && wide_exp(w) <= 254 && rndn(2)) w ^= rnd64() & 0x7u;
    return w;
}

/* A realistic update: positions 0..200, r2 0.01..1, photons inside, near and far. */
static void gen_update(preu_vec_t *v, int datapath)
{
    double r2 = rndlog(0.01, 1.0), r = sqrt(r2);
    double spread = rndn(2) ? r : 2.0 * r;
    int far = rndn(5) == 0;
    for (int k = 0; k < 3; k++) {
        double p = rndu(0.0, 200.0);
        v->hp.pos[k] = preu_f32(p);
        v->ph.pos[k] = preu_f32(far ? rndu(0.0, 200.0) : p + rndu(-spread, spread));
        v->hp.f[k] = preu_f32(rndn(8) ? rndu(0.0, 1.0) : 0.0);
        v->ph.phi[k] = preu_f32(rndlog(1e-3, 1e5));
    }
    if (!datapath) {
        for (int k = 0; k < 3; k++) v->hp.st[k] = preu_f32(rndn(4) ? rndlog(1e-6, 1e4) : 0.0);
        v->hp.st[3] = preu_f32(r2);
        v->hp.st[4] = rnd_count();
    } else {
        for (int k = 0; k < 3; k++) put64(v->hp.st, k, rndn(4) ? rnd_wide(rndlog(1e-6, 1e12)) : WIDE_ZERO);
        put64(v->hp.st, 3, rnd_wide(1.0 / r2 * (rndn(4) ? 1.0 : rndlog(1.0, 1e6))));
        put64(v->hp.st, 4, rnd_count64());
    }
    if (rndn(8) == 0) {                 /* radius exactly at the distance, or one ulp off */
        preu_vec_expect(v, datapath);
        if (!datapath) {
            preu_hp_t hp;
            preu_trace_t tr;
            preu_hpw_to_paper(&v->hp, &hp);
            preu_update_trace(&tr, &hp, &v->ph, v->alpha);
            if (!fp32_is_nan(tr.d2) && tr.d2 > 0 && tr.d2 < 0x7f800000u)
                v->hp.st[3] = tr.d2 + (uint32_t)rndn(3) - 1u;
        } else {
            preu_shp_t hp;
            preu_strace_t tr;
            preu_hpw_to_stable(&v->hp, &hp);
            preu_stable_update_trace(&tr, &hp, &v->ph, v->kappa);
            if (!fp32_is_nan(tr.d2) && tr.d2 > 0 && tr.d2 < 0x7f800000u) {
                uint64_t w = wide_from_double(1.0 / (double)fp32_from_bits(tr.d2));
                put64(v->hp.st, 3, w + ((uint64_t)rndn(3) << 32) - (UINT64_C(1) << 32));
            }
        }
    }
}

static void gen_radiance(preu_vec_t *v, int datapath)
{
    for (int k = 0; k < 3; k++) {
        v->l[k] = preu_f32(rndn(8) ? rndlog(1e-9, 1e3) : 0.0);
        v->hp.pos[k] = rnd32();            /* unused in this mode: random, so that it cannot matter */
        v->hp.f[k] = rnd32();
        v->ph.pos[k] = rnd32();
        v->ph.phi[k] = rnd32();
    }
    if (!datapath) {
        for (int k = 0; k < 3; k++) v->hp.st[k] = preu_f32(rndn(8) ? rndlog(1e-6, 1e5) : 0.0);
        v->hp.st[3] = preu_f32(rndlog(1e-4, 1.0));
        v->hp.st[4] = rnd32();
    } else {
        for (int k = 0; k < 3; k++) put64(v->hp.st, k, rndn(8) ? rnd_wide(rndlog(1e-6, 1e12)) : WIDE_ZERO);
        put64(v->hp.st, 3, rnd64());
        put64(v->hp.st, 4, rnd64());
    }
}

void preu_vec_expect(preu_vec_t *v, int datapath)
{
    memset(v->sto, 0, sizeof v->sto);
    memset(v->lo, 0, sizeof v->lo);
    v->accept = 0;
    if (v->mode == 0 && !datapath) {
        preu_hp_t hp;
        preu_trace_t tr;
        preu_hpw_to_paper(&v->hp, &hp);
        preu_update_trace(&tr, &hp, &v->ph, v->alpha);
        v->accept = tr.accept;
        memcpy(v->sto, tr.tau_n, sizeof tr.tau_n);
        v->sto[3] = tr.r2n;
        v->sto[4] = tr.na;
    } else if (v->mode == 0) {
        preu_shp_t hp;
        preu_strace_t tr;
        preu_hpw_to_stable(&v->hp, &hp);
        preu_stable_update_trace(&tr, &hp, &v->ph, v->kappa);
        v->accept = tr.accept;
        for (int c = 0; c < 3; c++) put64(v->sto, c, tr.Tn[c]);
        put64(v->sto, 3, tr.wn);
        put64(v->sto, 4, tr.kn);
    } else if (!datapath) {
        preu_hp_t hp;
        preu_hpw_to_paper(&v->hp, &hp);
        memcpy(v->lo, v->l, sizeof v->lo);
        preu_radiance(v->lo, &hp, v->ne);
    } else {
        preu_shp_t hp;
        preu_hpw_to_stable(&v->hp, &hp);
        memcpy(v->lo, v->l, sizeof v->lo);
        preu_stable_radiance(v->lo, &hp, v->ne);
    }
}

/* Directed cases: the hand-worked ones of tests/unit/test_preu_fp32.c and edge values. */
static int gen_directed(preu_vec_t *v, int n, int datapath)
{
    const uint32_t P10 = 0x41200000u, P20 = 0x41a00000u, P30 = 0x41f00000u;
    const uint32_t P13 = 0x41500000u, P24 = 0x41c00000u, P11 = 0x41300000u, P21 = 0x41a80000u;
    preu_vec_t base;
    memset(&base, 0, sizeof base);
    base.hp.pos[0] = P10; base.hp.pos[1] = P20; base.hp.pos[2] = P30;
    base.hp.f[0] = 0x3f000000u; base.hp.f[1] = 0x3e800000u; base.hp.f[2] = 0x3f800000u;
    base.alpha = PREU_ALPHA;
    base.kappa = preu_kappa(PREU_ALPHA);
    if (!datapath) base.hp.st[3] = PREU_ONE;
    else put64(base.hp.st, 3, wide_from_double(1.0));
    memcpy(base.ph.pos, base.hp.pos, sizeof base.ph.pos);
    base.ph.phi[0] = base.ph.phi[1] = 0x40000000u; base.ph.phi[2] = 0x40400000u;
    enum { ND = 14 };
    preu_vec_t d[ND];
    for (int i = 0; i < ND; i++) d[i] = base;
    /* 0: first accept; 1: rejected (d2 = 2); 2, 3: d2 = 25 = r2, and r2 one ulp less */
    d[1].ph.pos[0] = P11; d[1].ph.pos[1] = P21;
    d[2].ph.pos[0] = P13; d[2].ph.pos[1] = P24;
    d[3] = d[2];
    /* 4: NaN photon position; 5: sNaN r2 (w); 6: inf - inf; 7: NaN flux, weight, 0 * inf */
    d[4].ph.pos[1] = 0x7fc01234u;
    d[6].hp.pos[2] = d[6].ph.pos[2] = 0x7f800000u;
    d[7].hp.f[1] = 0xff812345u; d[7].hp.f[2] = 0;
    d[7].ph.phi[2] = 0x7f800000u;
    if (!datapath) {
        d[2].hp.st[3] = 0x41c80000u;
        d[3].hp.st[3] = 0x41c80000u - 1u;
        d[5].hp.st[3] = 0x7f800001u;
        d[7].hp.st[0] = 0x7f800001u;
        d[8].hp.st[4] = 0xff800010u;        /* 8: NaN N; 9: N = 2^24 */
        d[9].hp.st[4] = 0x4b800000u;
        d[12].hp.st[4] = 0x4b000000u;       /* 12: N = 2^23; 13: alpha 0.1 */
    } else {
        put64(d[2].hp.st, 3, wide_from_double(1.0 / 25.0));
        put64(d[3].hp.st, 3, wide_from_double(1.0 / 25.0) + (UINT64_C(1) << 32));
        put64(d[5].hp.st, 3, WIDE_NAN);
        put64(d[7].hp.st, 0, WIDE_MAX);
        put64(d[8].hp.st, 4, ~UINT64_C(0));               /* 8: count wraps; 9: k = 2^24 - 1 */
        put64(d[9].hp.st, 4, (UINT64_C(1) << 24) - 1);
        put64(d[12].hp.st, 0, WIDE_MAX);                  /* 12: saturation of T and w */
        put64(d[12].hp.st, 3, WIDE_MAX);
    }
    d[13].alpha = preu_f32(0.1);
    d[13].kappa = preu_kappa(d[13].alpha);
    /* radiance 10: r2 = 1 (tau | T = 1, 2, 0.5), NE = 1; 11: r2 = 0 or saturated T */
    d[10].mode = d[11].mode = 1;
    d[10].ne = d[11].ne = PREU_ONE;
    if (!datapath) {
        d[10].hp.st[0] = PREU_ONE; d[10].hp.st[1] = 0x40000000u; d[10].hp.st[2] = 0x3f000000u;
        d[11] = d[10]; d[11].hp.st[3] = 0;
    } else {
        put64(d[10].hp.st, 0, wide_from_double(1.0)); put64(d[10].hp.st, 1, wide_from_double(2.0));
        put64(d[10].hp.st, 2, wide_from_double(0.5));
        d[11] = d[10]; put64(d[11].hp.st, 0, WIDE_MAX); put64(d[11].hp.st, 1, WIDE_NAN);
    }
    /* The radiance cases go last, so that the update cases share one phase. */
    const int order[ND] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 12, 13, 10, 11};
    int m = n < ND ? n : ND;
    for (int i = 0; i < m; i++) {
        v[i] = d[order[i]];
        /* Cases 10, 11 run with alpha 0.1: the pipeline drains first (alpha and kappa may change
         * only while the PREU is idle). */
        if (i >= 10 && i < 12) { v[i].alpha = d[13].alpha; v[i].kappa = d[13].kappa; }
        if (i == 10) v[i].gap = 14;
        preu_vec_expect(&v[i], datapath);
    }
    return m;
}

void preu_seq_gen(preu_vec_t *v, int n, uint64_t seed, int datapath)
{
    rng_state = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
    memset(v, 0, (size_t)n * sizeof *v);
    int i = gen_directed(v, n, datapath);
    int mode = 0;
    while (i < n) {
        /* a phase: one mode, a length from 1 to 3000, a gap pattern */
        uint32_t pl = rndn(4);
        int len = 1 + (int)rndn(pl == 0 ? 8 : pl == 3 ? 3000 : 300);
        int dense = rndn(3) == 0;                    /* back-to-back throughout */
        uint32_t ne = preu_n_emitted((uint64_t)rndlog(1.0, 1.0e8));
        uint32_t alpha = rndn(2) ? PREU_ALPHA : preu_f32(rndu(0.05, 1.0));
        for (int j = 0; j < len && i < n; j++, i++) {
            preu_vec_t *o = &v[i];
            o->mode = mode;
            o->ne = ne;
            o->alpha = alpha;
            o->kappa = preu_kappa(alpha);
            if (mode == 0) gen_update(o, datapath); else gen_radiance(o, datapath);
            if (rndn(10) == 0) add_specials(o, datapath);
            if (!dense) {
                uint32_t r = rndn(20);
                o->gap = r < 11 ? 0 : r < 17 ? 1 + (int)rndn(3) : 4 + (int)rndn(17);
            }
            preu_vec_expect(o, datapath);
        }
        mode ^= 1;
    }
}

void preu_vec_words(uint32_t w[PREU_VEC_WORDS], const preu_vec_t *v)
{
    int k = 0;
    w[k++] = (uint32_t)v->mode;                  /* word 0 */
    w[k++] = (uint32_t)v->gap;
    for (int c = 0; c < 3; c++) w[k++] = v->hp.pos[c];
    for (int c = 0; c < 3; c++) w[k++] = v->hp.f[c];
    for (int c = 0; c < PREU_STATE_MAX; c++) w[k++] = v->hp.st[c];   /* words 8..17 */
    for (int c = 0; c < 3; c++) w[k++] = v->ph.pos[c];            /* 18 */
    for (int c = 0; c < 3; c++) w[k++] = v->ph.phi[c];            /* 21 */
    w[k++] = v->ne;                                               /* 24 */
    for (int c = 0; c < 3; c++) w[k++] = v->l[c];                 /* 25 */
    w[k++] = v->alpha;                                            /* 28 */
    w[k++] = v->kappa;                                            /* 29 */
    w[k++] = (uint32_t)v->accept;                                 /* 30 */
    for (int c = 0; c < PREU_STATE_MAX; c++) w[k++] = v->sto[c];  /* 31..40 */
    for (int c = 0; c < 3; c++) w[k++] = v->lo[c];                /* 41..43 */
    /* k == 44 */
}
