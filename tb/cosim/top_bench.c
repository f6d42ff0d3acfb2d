/* top_bench.c: Verilator bench of pree_top (rtl/pree_top.v) against the C model, with
 * synthetic and adversarial traces. The expected hit-point state comes from model/preu_fp32.h
 * applied in photon order; the expected pixels from the same model in the radiance issue order
 * of model/adiso_order.h. Compares every word and prints the first mismatches.
 *
 * usage: top_bench [--preu 4|8|16] [--scenario random|one|dense|mixed] [--photons N]
 *                  [--hp N] [--gap P] [--no-reorder] [--seed S] [--trace FILE.fst]
 *   random  photons with 1..40 random distinct candidates among --hp hit points
 *   one     every photon hits hit point 0 (and nothing else): in-flight hazards every cycle
 *   dense   few pixels with dozens of hit points each, photons on small neighbourhoods
 *   mixed   random, with every fourth photon also on hit point 0
 * Exit status 0 when every word matches, 1 on a mismatch, 2 on a usage error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "adiso_order.h"
#include "cosim_drv.h"

static uint64_t rng_state;
static uint32_t rnd(void)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(rng_state >> 33);
}
static float frand(float lo, float hi) { return lo + (hi - lo) * (float)(rnd() & 0xffffff) / 16777216.0f; }
static uint32_t fb(float x) { return fp32_to_bits(x); }

int main(int argc, char **argv)
{
    int preu = 4, photons = 3000, nhp = 2000, reorder = 1;
    double gap = 0;
    const char *scenario = "random", *trace = NULL;
    uint64_t seed = 1;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(o, "--no-reorder")) { reorder = 0; continue; }
        if (!v) { fprintf(stderr, "top_bench: %s needs a value\n", o); return 2; }
        i++;
        if (!strcmp(o, "--preu")) preu = atoi(v);
        else if (!strcmp(o, "--scenario")) scenario = v;
        else if (!strcmp(o, "--photons")) photons = atoi(v);
        else if (!strcmp(o, "--hp")) nhp = atoi(v);
        else if (!strcmp(o, "--gap")) gap = atof(v);
        else if (!strcmp(o, "--seed")) seed = strtoull(v, NULL, 0);
        else if (!strcmp(o, "--trace")) trace = v;
        else { fprintf(stderr, "top_bench: unknown option %s\n", o); return 2; }
    }
    int one = !strcmp(scenario, "one"), dense = !strcmp(scenario, "dense"), mixed = !strcmp(scenario, "mixed");
    if (!one && !dense && !mixed && strcmp(scenario, "random")) { fprintf(stderr, "top_bench: unknown scenario %s\n", scenario); return 2; }
    if (nhp < 1 || nhp > (1 << COSIM_HPAW) || photons < 0) { fprintf(stderr, "top_bench: bad sizes\n"); return 2; }
    rng_state = seed * 0x9E3779B97F4A7C15ull + 7;

    char err[256];
    cosim_rtl_t *rtl = cosim_rtl_new(preu, trace, err, sizeof err);
    if (!rtl) { fprintf(stderr, "top_bench: %s\n", err); return 2; }
    cosim_drv_opts_t dopt = {.preu = preu, .hp_bank_w = cosim_rtl_hp_bank_w(rtl), .reorder = reorder, .gap = gap, .seed = seed};
    cosim_drv_t *drv = cosim_drv_new(rtl, &dopt);

    /* Hit points in the unit cube; dense: 40 per pixel, else 3 per pixel. */
    const int per_px = dense ? 40 : 3;
    const int npix = (nhp + per_px - 1) / per_px;
    preu_hp_t *hp = calloc((size_t)nhp, sizeof *hp), *init = calloc((size_t)nhp, sizeof *init);
    int32_t *pixel = calloc((size_t)nhp, sizeof *pixel);
    uint32_t *cand = malloc(64 * sizeof *cand);
    for (int i = 0; i < nhp; i++) {
        for (int c = 0; c < 3; c++) {
            hp[i].pos[c] = fb(frand(0, 1));
            hp[i].f[c] = fb(frand(0, 1));
            hp[i].tau[c] = 0;
        }
        hp[i].r2 = fb(one ? 4.0f : frand(0.01f, 0.2f));
        hp[i].n = 0;
        pixel[i] = i / per_px;
    }
    memcpy(init, hp, (size_t)nhp * sizeof *hp);
    cosim_drv_load_hp(drv, init, pixel, (size_t)nhp);

    /* Photons, applied to the model in photon order and streamed to the RTL. */
    for (int p = 0; p < photons; p++) {
        preu_photon_t ph;
        for (int c = 0; c < 3; c++) { ph.pos[c] = fb(frand(0, 1)); ph.phi[c] = fb(frand(0, 2)); }
        size_t n = 0;
        if (one) {
            cand[n++] = 0;
        } else {
            size_t want = dense ? 1 + rnd() % 60 : 1 + rnd() % 40;
            uint32_t base = dense ? (rnd() % (uint32_t)nhp) : 0;
            while (n < want) {
                uint32_t h = dense ? (base + rnd() % 80) % (uint32_t)nhp : rnd() % (uint32_t)nhp;
                int dup = 0;
                for (size_t k = 0; k < n; k++) dup |= cand[k] == h;
                if (!dup) cand[n++] = h;
                if (n >= (size_t)nhp) break;
            }
            if (mixed && p % 4 == 0) {
                int has0 = 0;
                for (size_t k = 0; k < n; k++) has0 |= cand[k] == 0;
                if (!has0) cand[n++] = 0;
            }
        }
        for (size_t k = 0; k < n; k++) preu_update(&hp[cand[k]], &ph);
        if (cosim_drv_photon(drv, &ph, cand, n)) { fprintf(stderr, "top_bench: %s\n", cosim_drv_error(drv)); return 1; }
    }
    if (cosim_drv_drain(drv)) { fprintf(stderr, "top_bench: %s\n", cosim_drv_error(drv)); return 1; }
    uint64_t cnt[COSIM_NCNT];
    cosim_drv_counters(drv, cnt);

    unsigned long long bad = 0;
    for (int i = 0; i < nhp; i++) {
        preu_hp_t h;
        uint32_t px;
        cosim_drv_read_hp(drv, (uint32_t)i, &h, &px);
        if (memcmp(&h, &hp[i], sizeof h) || px != (uint32_t)pixel[i]) {
            if (bad < 20)
                printf("MISMATCH hit point %d: RTL tau %08x %08x %08x r2 %08x n %08x px %u, model tau %08x %08x %08x r2 %08x n %08x px %d\n",
                       i, h.tau[0], h.tau[1], h.tau[2], h.r2, h.n, px, hp[i].tau[0], hp[i].tau[1], hp[i].tau[2],
                       hp[i].r2, hp[i].n, pixel[i]);
            bad++;
        }
    }
    /* Radiance: model in issue order, RTL pass. */
    uint32_t ne = preu_n_emitted((uint64_t)photons > 0 ? (uint64_t)photons : 1);
    uint32_t *order = malloc((size_t)nhp * sizeof *order);
    uint32_t *Lm = calloc((size_t)npix * 3, sizeof *Lm), *Lr = calloc((size_t)npix * 3, sizeof *Lr);
    adiso_order((uint32_t)nhp, preu, 12, order);
    for (int k = 0; k < nhp; k++) preu_radiance(Lm + 3 * (size_t)pixel[order[k]], &hp[order[k]], ne);
    cosim_drv_radiance(drv, (uint32_t)nhp, ne, (size_t)npix, Lr);
    uint64_t cnt2[COSIM_NCNT];
    cosim_drv_counters(drv, cnt2);
    for (int j = 0; j < npix * 3; j++) {
        if (Lr[j] != Lm[j]) {
            if (bad < 20) printf("MISMATCH pixel %d channel %d: RTL %08x model %08x\n", j / 3, j % 3, Lr[j], Lm[j]);
            bad++;
        }
    }
    uint64_t ops = 0, rops = 0;
    for (int l = 0; l < preu; l++) { ops += cnt[CNT_OPS0 + l]; rops += cnt2[CNT_OPS0 + l]; }
    rops -= ops;
    if (ops != cosim_drv_ops_sent(drv) || rops != (uint64_t)nhp) {
        printf("MISMATCH operation counts: update %llu (sent %llu), radiance %llu (hit points %d)\n",
               (unsigned long long)ops, (unsigned long long)cosim_drv_ops_sent(drv), (unsigned long long)rops, nhp);
        bad++;
    }
    printf("top_bench preu=%d scenario=%s photons=%d hp=%d gap=%g reorder=%d: update %llu ops / %llu cycles "
           "(util %.4f; short cycles haz %llu dup %llu bank %llu abank %llu starve %llu), radiance %llu ops / %llu cycles "
           "(haz %llu dup %llu bank %llu abank %llu starve %llu): %s\n",
           preu, scenario, photons, nhp, gap, reorder, (unsigned long long)ops, (unsigned long long)cnt[CNT_CYC_UPD],
           cnt[CNT_CYC_UPD] ? (double)ops / (double)(preu * cnt[CNT_CYC_UPD]) : 0.0,
           (unsigned long long)cnt[CNT_HAZ], (unsigned long long)cnt[CNT_DUP], (unsigned long long)cnt[CNT_BANK],
           (unsigned long long)cnt[CNT_ABANK], (unsigned long long)cnt[CNT_STARVE],
           (unsigned long long)rops, (unsigned long long)cnt2[CNT_CYC_RAD],
           (unsigned long long)(cnt2[CNT_HAZ] - cnt[CNT_HAZ]), (unsigned long long)(cnt2[CNT_DUP] - cnt[CNT_DUP]),
           (unsigned long long)(cnt2[CNT_BANK] - cnt[CNT_BANK]), (unsigned long long)(cnt2[CNT_ABANK] - cnt[CNT_ABANK]),
           (unsigned long long)(cnt2[CNT_STARVE] - cnt[CNT_STARVE]), bad ? "FAIL" : "PASS");
    free(order); free(Lm); free(Lr); free(hp); free(init); free(pixel); free(cand);
    cosim_drv_free(drv);
    cosim_rtl_free(rtl);
    return bad ? 1 : 0;
}
