// SPDX-License-Identifier: Apache-2.0
/* top_vecgen.c: writes the vector files of the Icarus bench of pree_top (tb/cosim/top_tb.v):
 * hit points to load, the photon stream with its index-table entries, and the expected hit-point
 * memory and pixel words. The expectations come from the fp32 PREU model (model/pree/preu_fp32.h)
 * applied in photon order and, for the pixels, in the radiance issue order of
 * model/pree/adiso_order.h, as tb/cosim/top_bench.c does for the Verilated top.
 *
 * usage: top_vecgen --preu P --hp-aw A --idx-aw I --px-aw X [--scenario S] [--photons N]
 *                   [--hp N] [--seed S] [--place packed|random] OUT
 *   scenarios: random (1..40 random distinct candidates, a few photons with none),
 *              one (every photon on hit point 0 only), dense (pixels of 40 hit points, photons
 *              on neighbourhoods of 80), mixed (random, every fourth photon also on hit point 0)
 *   place:     packed (docs/pree_top.md "Host protocol": p_k = p_(k-1) - N^P_k mod P, no stage-A
 *              bank conflict), random (0..2P-1 entries of random padding: stage-A conflicts)
 * Files (one $readmemh word per line, fields most significant first, all hex):
 *   OUT.meta  16 x 32 bits: nhp, npix, photons, entries, ne, operations, P, A, I, X,
 *             placement (0 packed, 1 random), 0...
 *   OUT.hp    per hit point, 384 bits: pixel, f b g r, pos z y x, n, r2, tau b g r
 *             (the low PxAW + 352 bits are pree_top's hp_wdata_i)
 *   OUT.ph    per photon, 288 bits: end of its entries in OUT.idx, p_addr, N^P, phi b g r, pos z y x
 *   OUT.idx   per index entry in write order, 96 bits: photons that must be done before it is
 *             written (photons with N^P > 0, in order), index address, hit-point address
 *   OUT.hpx   expected hit-point memory after the update pass, layout of OUT.hp
 *   OUT.px    expected pixel sums after the radiance pass, 96 bits: b g r
 * Prints one summary line. Exit status 0, 1 on an I/O error, 2 on a usage error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "adiso_order.h"
#include "bench_draw.h"
#include "preu_fp32.h"

#define MAX_CAND 64

static uint64_t rng_state;
static uint32_t rnd(void) { return draw_u32(&rng_state); }
static uint32_t frand_bits(float lo, float hi) { return draw_f32_bits(&rng_state, lo, hi); }

static FILE *open_out(const char *base, const char *ext)
{
    char path[4096];
    snprintf(path, sizeof path, "%s.%s", base, ext);
    FILE *f = fopen(path, "w");
    if (!f) perror(path);
    return f;
}

static void put_hp(FILE *f, const preu_hp_t *h, uint32_t pixel)
{
    fprintf(f, "%08x%08x%08x%08x%08x%08x%08x%08x%08x%08x%08x%08x\n", pixel, h->f[2], h->f[1], h->f[0],
            h->pos[2], h->pos[1], h->pos[0], h->n, h->r2, h->tau[2], h->tau[1], h->tau[0]);
}

/* The generator's options (the usage below) and what follows from them. */
typedef struct {
    int preu, hp_aw, idx_aw, px_aw, photons, nhp, place_random, per_px, npix;
    const char *scenario, *out;
    draw_scenario_t sc;
    uint64_t seed;
} vecgen_opts_t;

/* Parses and checks the command line; 0, or 2 after a usage line on stderr. */
static int parse_args(int argc, char **argv, vecgen_opts_t *o)
{
    *o = (vecgen_opts_t){.preu = 4, .hp_aw = 10, .idx_aw = 8, .px_aw = 9, .photons = 300, .scenario = "random",
                         .seed = 1};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (a[0] != '-') { o->out = a; continue; }
        if (!v) { fprintf(stderr, "top_vecgen: %s needs a value\n", a); return 2; }
        i++;
        if (!strcmp(a, "--preu")) o->preu = atoi(v);
        else if (!strcmp(a, "--hp-aw")) o->hp_aw = atoi(v);
        else if (!strcmp(a, "--idx-aw")) o->idx_aw = atoi(v);
        else if (!strcmp(a, "--px-aw")) o->px_aw = atoi(v);
        else if (!strcmp(a, "--scenario")) o->scenario = v;
        else if (!strcmp(a, "--photons")) o->photons = atoi(v);
        else if (!strcmp(a, "--hp")) o->nhp = atoi(v);
        else if (!strcmp(a, "--seed")) o->seed = strtoull(v, NULL, 0);
        else if (!strcmp(a, "--place")) o->place_random = !strcmp(v, "random");
        else { fprintf(stderr, "top_vecgen: unknown option %s\n", a); return 2; }
    }
    const int bad_sc = draw_scenario(o->scenario, &o->sc);
    if (!o->out || bad_sc || o->preu < 1 || o->preu > 64 || (o->preu & (o->preu - 1)) || o->hp_aw < 4 ||
        o->hp_aw > 24 || o->idx_aw < 6 || o->idx_aw > 16 || o->px_aw < 2 || o->px_aw > 24 || o->photons < 1) {
        fprintf(stderr, "usage: top_vecgen --preu P --hp-aw A --idx-aw I --px-aw X [--scenario "
                        "random|one|dense|mixed] [--photons N] [--hp N] [--seed S] [--place packed|random] OUT\n");
        return 2;
    }
    if (o->nhp <= 0) o->nhp = (1 << o->hp_aw) - (1 << o->hp_aw) / 8;   /* leave some addresses unused */
    o->per_px = o->sc == DRAW_DENSE ? 40 : 3;
    o->npix = (o->nhp + o->per_px - 1) / o->per_px;
    if (o->nhp > (1 << o->hp_aw) || o->npix > (1 << o->px_aw) || MAX_CAND + 2 * (uint32_t)o->preu > (1u << o->idx_aw)) {
        fprintf(stderr, "top_vecgen: %d hit points / %d pixels / %d-entry photons do not fit\n", o->nhp, o->npix,
                MAX_CAND);
        return 2;
    }
    return 0;
}

/* Hit points in the unit cube, per_px consecutive ones per pixel ("one": a radius covering it),
 * written to fhp. */
static void make_hit_points(FILE *fhp, preu_hp_t *hp, const vecgen_opts_t *opt)
{
    for (int i = 0; i < opt->nhp; i++) {
        for (int c = 0; c < 3; c++) {
            hp[i].pos[c] = frand_bits(0, 1);
            hp[i].f[c] = frand_bits(0, 1);
        }
        hp[i].r2 = opt->sc == DRAW_ONE ? fp32_to_bits(4.0f) : frand_bits(0.01f, 0.2f);
        put_hp(fhp, &hp[i], (uint32_t)(i / opt->per_px));
    }
}

/* Radiance: each pixel accumulated from +0 in the hardware's issue order, written to fpx.
 * 0, 1 (memory) or 2 (the order). */
static int write_radiance(FILE *fpx, const preu_hp_t *hp, const vecgen_opts_t *opt, uint32_t ne)
{
    uint32_t *order = malloc((size_t)opt->nhp * sizeof *order);
    uint32_t *L = calloc((size_t)opt->npix * 3, sizeof *L);
    int rc = !order || !L;
    if (!rc && adiso_order((uint32_t)opt->nhp, opt->preu, 12, order)) {
        fprintf(stderr, "top_vecgen: adiso_order failed\n");
        rc = 2;
    }
    if (!rc) {
        for (int k = 0; k < opt->nhp; k++)
            preu_radiance(L + 3 * (size_t)(order[k] / (uint32_t)opt->per_px), &hp[order[k]], ne);
        for (int j = 0; j < opt->npix; j++) fprintf(fpx, "%08x%08x%08x\n", L[3 * j + 2], L[3 * j + 1], L[3 * j]);
    }
    free(order);
    free(L);
    return rc;
}

int main(int argc, char **argv)
{
    vecgen_opts_t opt;
    if (parse_args(argc, argv, &opt)) return 2;
    const int preu = opt.preu, photons = opt.photons, nhp = opt.nhp, place_random = opt.place_random;
    const int per_px = opt.per_px, npix = opt.npix;
    const int random_sc = opt.sc == DRAW_RANDOM;
    const draw_scenario_t sc = opt.sc;
    const char *out = opt.out, *scenario = opt.scenario;
    const uint32_t depth = 1u << opt.idx_aw;
    const uint64_t seed = opt.seed;
    rng_state = seed * 0x9E3779B97F4A7C15ull + 11;

    FILE *fhp = open_out(out, "hp"), *fph = open_out(out, "ph"), *fidx = open_out(out, "idx");
    FILE *fhpx = open_out(out, "hpx"), *fpx = open_out(out, "px"), *fmeta = open_out(out, "meta");
    preu_hp_t *hp = calloc((size_t)nhp, sizeof *hp);
    uint64_t *start = malloc((size_t)photons * sizeof *start);   /* absolute entry of each sent photon */
    if (!fhp || !fph || !fidx || !fhpx || !fpx || !fmeta || !hp || !start) return 1;
    make_hit_points(fhp, hp, &opt);

    /* Photons: model update in photon order; index entries placed in the circular table. */
    uint64_t alloc_end = 0, prev_p = 0, entries = 0, ops = 0;
    int sent = 0, oldest = 0;
    for (int p = 0; p < photons; p++) {
        preu_photon_t ph;
        for (int c = 0; c < 3; c++) { ph.pos[c] = frand_bits(0, 1); ph.phi[c] = frand_bits(0, 2); }
        uint32_t cand[DRAW_MAX_CAND];
        /* random: about 3% of the photons without candidates */
        size_t n = (random_sc && rnd() % 32 == 0) ? 0 : draw_candidates(&rng_state, sc, p, (uint32_t)nhp, cand);
        for (size_t k = 0; k < n; k++) preu_update(&hp[cand[k]], &ph, PREU_ALPHA);
        uint64_t pa = 0;
        if (n) {
            if (place_random) {
                pa = alloc_end + rnd() % (2u * (uint32_t)preu);
            } else {
                uint64_t target = (prev_p + (uint64_t)preu * MAX_CAND - n) % (uint64_t)preu;
                pa = alloc_end + (target + (uint64_t)preu - alloc_end % (uint64_t)preu) % (uint64_t)preu;
            }
            /* Entries pa .. pa+n-1 reuse those of photons starting before pa + n - depth. */
            while (oldest < sent && start[oldest] + depth < pa + n) oldest++;
            /* The k-th operation AFTSO-HpUOC emits reads entry pa + n - 1 - k. */
            for (size_t k = 0; k < n; k++)
                fprintf(fidx, "%08x%08x%08x\n", (unsigned)oldest, (unsigned)((pa + n - 1 - k) & (depth - 1)), cand[k]);
            start[sent++] = pa;
            alloc_end = pa + n;
            prev_p = pa;
            entries += n;
            ops += n;
        }
        fprintf(fph, "%08x%08x%08x%08x%08x%08x%08x%08x%08x\n", (unsigned)entries, (unsigned)(pa & (depth - 1)),
                (unsigned)n, ph.phi[2], ph.phi[1], ph.phi[0], ph.pos[2], ph.pos[1], ph.pos[0]);
    }
    for (int i = 0; i < nhp; i++) put_hp(fhpx, &hp[i], (uint32_t)(i / per_px));

    const uint32_t ne = preu_n_emitted((uint64_t)photons);
    const int rad = write_radiance(fpx, hp, &opt, ne);
    if (rad) return rad;

    const uint32_t meta[16] = {(uint32_t)nhp, (uint32_t)npix, (uint32_t)photons, (uint32_t)entries, ne,
                               (uint32_t)ops, (uint32_t)preu, (uint32_t)opt.hp_aw, (uint32_t)opt.idx_aw,
                               (uint32_t)opt.px_aw,
                               (uint32_t)place_random};
    for (int k = 0; k < 16; k++) fprintf(fmeta, "%08x\n", meta[k]);
    int bad = 0;
    FILE *all[] = {fhp, fph, fidx, fhpx, fpx, fmeta};
    for (size_t k = 0; k < sizeof all / sizeof *all; k++) bad |= fclose(all[k]) != 0;
    if (bad) { perror("top_vecgen"); return 1; }
    printf("top_vecgen preu=%d scenario=%s place=%s photons=%d sent=%d hp=%d pixels=%d entries=%llu ops=%llu\n",
           preu, scenario, place_random ? "random" : "packed", photons, sent, nhp, npix,
           (unsigned long long)entries, (unsigned long long)ops);
    free(hp); free(start);
    return 0;
}
