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
static uint32_t rndn(uint32_t n) { return rnd32() % n; }
static double rndu(double lo, double hi) { return lo + (hi - lo) * (rnd32() * 0x1p-32); }
/* log-uniform in [lo, hi] */
static double rndlog(double lo, double hi) { return exp(log(lo) + rndu(0.0, 1.0) * log(hi / lo)); }

static const uint32_t SPECIAL[] = {
    0x00000000u, 0x80000000u, 0x7f800000u, 0xff800000u, 0x7fc00000u, 0xffc00000u,
    0x7f800001u, 0xff812345u, 0x7fd00badu, 0x00000001u, 0x807fffffu, 0x00800000u,
    0x7f7fffffu, 0xff7fffffu, 0x3f800000u, 0x3f333333u, 0x4b800000u, 0x4b000000u};
#define N_SPECIAL (sizeof SPECIAL / sizeof SPECIAL[0])

static uint32_t special_or_random(void)
{
    return rndn(3) ? SPECIAL[rndn(N_SPECIAL)] : rnd32();
}

/* Sprinkle special values over the operation's input words with probability 1/4 each. */
static void add_specials(preu_vec_t *v)
{
    uint32_t *w = (uint32_t *)&v->hp;
    for (unsigned k = 0; k < sizeof v->hp / 4; k++) if (rndn(4) == 0) w[k] = special_or_random();
    w = (uint32_t *)&v->ph;
    for (unsigned k = 0; k < sizeof v->ph / 4; k++) if (rndn(4) == 0) w[k] = special_or_random();
    for (int k = 0; k < 3; k++) if (rndn(4) == 0) v->l[k] = special_or_random();
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

/* A realistic update: positions 0..200, r2 0.01..1, photons inside, near and far. */
static void gen_update(preu_vec_t *v)
{
    double r2 = rndlog(0.01, 1.0), r = sqrt(r2);
    double spread = rndn(2) ? r : 2.0 * r;
    int far = rndn(5) == 0;
    for (int k = 0; k < 3; k++) {
        double p = rndu(0.0, 200.0);
        v->hp.pos[k] = preu_f32(p);
        v->ph.pos[k] = preu_f32(far ? rndu(0.0, 200.0) : p + rndu(-spread, spread));
        v->hp.f[k] = preu_f32(rndn(8) ? rndu(0.0, 1.0) : 0.0);
        v->hp.tau[k] = preu_f32(rndn(4) ? rndlog(1e-6, 1e4) : 0.0);
        v->ph.phi[k] = preu_f32(rndlog(1e-3, 1e5));
    }
    v->hp.r2 = preu_f32(r2);
    v->hp.n = rnd_count();
    if (rndn(8) == 0) {                 /* radius exactly at the distance, or one ulp off */
        preu_trace_t tr;
        preu_update_trace(&tr, &v->hp, &v->ph, PREU_ALPHA);
        if (!fp32_is_nan(tr.d2) && tr.d2 > 0 && tr.d2 < 0x7f800000u)
            v->hp.r2 = tr.d2 + (uint32_t)rndn(3) - 1u;
    }
}

static void gen_radiance(preu_vec_t *v)
{
    for (int k = 0; k < 3; k++) {
        v->hp.tau[k] = preu_f32(rndn(8) ? rndlog(1e-6, 1e5) : 0.0);
        v->l[k] = preu_f32(rndn(8) ? rndlog(1e-9, 1e3) : 0.0);
        v->hp.pos[k] = rnd32();         /* unused in this mode: random, so that it cannot matter */
        v->hp.f[k] = rnd32();
        v->ph.pos[k] = rnd32();
        v->ph.phi[k] = rnd32();
    }
    v->hp.r2 = preu_f32(rndlog(1e-4, 1.0));
    v->hp.n = rnd32();
}

static void expect(preu_vec_t *v)
{
    if (v->mode == 0) {
        preu_trace_t tr;
        preu_update_trace(&tr, &v->hp, &v->ph, PREU_ALPHA);
        v->accept = tr.accept;
        memcpy(v->tau, tr.tau_n, sizeof v->tau);
        v->r2 = tr.r2n;
        v->n = tr.na;
        memset(v->lo, 0, sizeof v->lo);
    } else {
        memcpy(v->lo, v->l, sizeof v->lo);
        preu_radiance(v->lo, &v->hp, v->ne);
        v->accept = 0;
        memset(v->tau, 0, sizeof v->tau);
        v->r2 = v->n = 0;
    }
}

/* Directed cases: the hand-worked ones of tests/unit/test_preu_fp32.c and edge values. */
static int gen_directed(preu_vec_t *v, int n)
{
    const uint32_t P10 = 0x41200000u, P20 = 0x41a00000u, P30 = 0x41f00000u;
    const uint32_t P13 = 0x41500000u, P24 = 0x41c00000u, P11 = 0x41300000u, P21 = 0x41a80000u;
    preu_vec_t base;
    memset(&base, 0, sizeof base);
    base.hp.pos[0] = P10; base.hp.pos[1] = P20; base.hp.pos[2] = P30;
    base.hp.f[0] = 0x3f000000u; base.hp.f[1] = 0x3e800000u; base.hp.f[2] = 0x3f800000u;
    base.hp.r2 = PREU_ONE;
    memcpy(base.ph.pos, base.hp.pos, sizeof base.ph.pos);
    base.ph.phi[0] = base.ph.phi[1] = 0x40000000u; base.ph.phi[2] = 0x40400000u;
    preu_vec_t d[12];
    for (int i = 0; i < 12; i++) d[i] = base;
    /* 0: first accept; 1: rejected (d2 = 2); 2, 3: d2 = 25 = r2, and r2 one ulp less */
    d[1].ph.pos[0] = P11; d[1].ph.pos[1] = P21;
    d[2].ph.pos[0] = P13; d[2].ph.pos[1] = P24; d[2].hp.r2 = 0x41c80000u;
    d[3] = d[2]; d[3].hp.r2 = 0x41c80000u - 1u;
    /* 4: NaN photon position; 5: sNaN r2; 6: inf - inf; 7: NaN flux, weight, 0 * inf; 8: NaN N */
    d[4].ph.pos[1] = 0x7fc01234u;
    d[5].hp.r2 = 0x7f800001u;
    d[6].hp.pos[2] = d[6].ph.pos[2] = 0x7f800000u;
    d[7].hp.tau[0] = 0x7f800001u; d[7].hp.f[1] = 0xff812345u; d[7].hp.f[2] = 0;
    d[7].ph.phi[2] = 0x7f800000u;
    d[8].hp.n = 0xff800010u;
    /* 9: N = 2^24; radiance 10: r2 = 1, NE = 1; 11: r2 = 0 */
    d[9].hp.n = 0x4b800000u;
    d[10].mode = d[11].mode = 1;
    d[10].ne = d[11].ne = PREU_ONE;
    d[10].hp.tau[0] = PREU_ONE; d[10].hp.tau[1] = 0x40000000u; d[10].hp.tau[2] = 0x3f000000u;
    d[11] = d[10]; d[11].hp.r2 = 0;
    int m = n < 12 ? n : 12;
    for (int i = 0; i < m; i++) { v[i] = d[i]; expect(&v[i]); }
    return m;
}

void preu_seq_gen(preu_vec_t *v, int n, uint64_t seed)
{
    rng_state = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
    memset(v, 0, (size_t)n * sizeof *v);
    int i = gen_directed(v, n);
    int mode = 0;
    while (i < n) {
        /* a phase: one mode, a length from 1 to 3000, a gap pattern */
        uint32_t pl = rndn(4);
        int len = 1 + (int)rndn(pl == 0 ? 8 : pl == 3 ? 3000 : 300);
        int dense = rndn(3) == 0;                    /* back-to-back throughout */
        uint32_t ne = preu_n_emitted((uint64_t)rndlog(1.0, 1.0e8));
        for (int j = 0; j < len && i < n; j++, i++) {
            preu_vec_t *o = &v[i];
            o->mode = mode;
            o->ne = ne;
            if (mode == 0) gen_update(o); else gen_radiance(o);
            if (rndn(10) == 0) add_specials(o);
            if (!dense) {
                uint32_t r = rndn(20);
                o->gap = r < 11 ? 0 : r < 17 ? 1 + (int)rndn(3) : 4 + (int)rndn(17);
            }
            expect(o);
        }
        mode ^= 1;
    }
}

void preu_vec_words(uint32_t w[PREU_VEC_WORDS], const preu_vec_t *v)
{
    int k = 0;
    w[k++] = (uint32_t)v->mode;
    w[k++] = (uint32_t)v->gap;
    for (int c = 0; c < 3; c++) w[k++] = v->hp.pos[c];
    for (int c = 0; c < 3; c++) w[k++] = v->hp.f[c];
    for (int c = 0; c < 3; c++) w[k++] = v->hp.tau[c];
    w[k++] = v->hp.r2;
    w[k++] = v->hp.n;
    for (int c = 0; c < 3; c++) w[k++] = v->ph.pos[c];
    for (int c = 0; c < 3; c++) w[k++] = v->ph.phi[c];
    w[k++] = v->ne;
    for (int c = 0; c < 3; c++) w[k++] = v->l[c];
    w[k++] = (uint32_t)v->accept;                /* word 23 */
    for (int c = 0; c < 3; c++) w[k++] = v->tau[c];
    w[k++] = v->r2;
    w[k++] = v->n;
    for (int c = 0; c < 3; c++) w[k++] = v->lo[c];
    /* k == 32 */
}
