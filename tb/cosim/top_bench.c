// SPDX-License-Identifier: Apache-2.0
/* top_bench.c: Verilator bench of pree_top (rtl/pree_top.v) against the C model, with
 * synthetic and adversarial traces. The expected hit-point state comes from model/pree/preu_fp32.h
 * (--datapath 0) or model/pree/preu_stable.h (--datapath 1) applied in photon order; the expected pixels from the same model in the radiance issue order
 * of model/pree/adiso_order.h. Compares every word and prints the first mismatches.
 *
 * usage: top_bench [--preu 4|8|16] [--datapath 0|1] [--pipe-fast] [--alpha A] [--scenario random|one|dense|mixed|abank]
 *                  [--photons N] [--hp N] [--gap P] [--stall P] [--no-reorder] [--seed S] [--trace FILE.fst [--trace-window A:B]]
 *                  [--reset-at K] [--hold-reset] [--wait-limit N]
 *   random  photons with 1..40 random distinct candidates among --hp hit points
 *   one     every photon hits hit point 0 (and nothing else): in-flight hazards every cycle
 *   dense   few pixels with dozens of hit points each, photons on small neighbourhoods
 *   mixed   random, with every fourth photon also on hit point 0
 *   abank   random, streamed by this file's own host (misplaced_stream) with the index entries
 *           misplaced on purpose: 0..2P-1 entries of random padding between photons instead of
 *           the driver's p_k = p_(k-1) - N^P_k (mod P), so that an offer spanning two photons
 *           reads one index bank twice (stage-A bank conflicts in update mode). The results
 *           must stay bit-exact and the abank counter must be non-zero.
 * In the other scenarios the driver places the entries as docs/pree_top.md "Host protocol" says,
 * and the update pass's abank counter must be zero.
 * Faults (not with abank): --gap P idles the photon input, --stall P writes fewer index entries
 * than the port takes and idles the hit-point load, each in a cycle with probability P;
 * --reset-at K resets pree_top (rst_ni low 2 cycles) after K photons were streamed, in mid-pass,
 * then reloads the hit points and streams every photon again with a fresh driver: the results
 * and every counter must equal a run without the reset. --hold-reset holds rst_ni low while the
 * photons stream: the driver's bounded wait (--wait-limit cycles) must fail, naming its state
 * (exit status 3 when it does, 1 when it does not).
 * --pipe-fast: the PipeFast = 1 model (the deep PREU pipeline; its hazard windows follow from it).
 * A failing run (without --trace) leaves the cycles around its first mismatch in
 * build/cosim/top_bench-fail-cN.fst (tb/lib/fail_trace.h), named in its last line.
 * Exit status 0 when every word matches, 1 on a mismatch, 2 on a usage error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "adiso_order.h"
#include "cosim_drv.h"
#include "bench_draw.h"
#include "fail_trace.h"
#include "top_bench_abank.h"

static uint64_t rng_state;
static uint32_t rnd(void) { return draw_u32(&rng_state); }
static float frand(float lo, float hi) { return lo + (hi - lo) * (float)(rnd() & 0xffffff) / 16777216.0f; }
static uint32_t fb(float x) { return fp32_to_bits(x); }

#define MAX_CAND 64

/* Stream photons [from, to) (candidates of photon p at cand + p * MAX_CAND, ncand[p] of them). */
static int stream(cosim_drv_t *drv, const preu_photon_t *ph, const uint32_t *cand, const int *ncand, int from, int to)
{
    for (int p = from; p < to; p++)
        if (cosim_drv_photon(drv, &ph[p], cand + (size_t)p * MAX_CAND, (size_t)ncand[p])) {
            fprintf(stderr, "top_bench: %s\n", cosim_drv_error(drv));
            return -1;
        }
    return 0;
}

/* Reset pree_top in mid-pass and start again: a fresh driver, the hit points reloaded. */
static cosim_drv_t *reset_and_reload(cosim_rtl_t *rtl, cosim_drv_t *drv, const cosim_drv_opts_t *dopt,
                                     const preu_hpw_t *init, const int32_t *pixel, size_t nhp)
{
    cosim_in_t *in = cosim_rtl_in(rtl);
    printf("top_bench: reset in mid-pass (idle_o %d, photons_done_o %u, %llu operations sent), hit points reloaded, "
           "every photon again\n", cosim_rtl_idle(rtl), cosim_rtl_photons_done(rtl),
           (unsigned long long)cosim_drv_ops_sent(drv));
    cosim_rtl_set_reset(rtl, 1);
    in->ph_valid = 0;
    in->cnt_en = 0;
    for (int j = 0; j < COSIM_MAX_PREU; j++) in->idx_we[j] = 0;
    for (int c = 0; c < 2; c++) cosim_rtl_tick(rtl);
    cosim_rtl_set_reset(rtl, 0);
    cosim_drv_free(drv);
    drv = cosim_drv_new(rtl, dopt);
    if (drv) cosim_drv_load_hp(drv, init, pixel, nhp);
    return drv;
}

/* A failing run without --trace runs itself again (tb/lib/fail_trace.h) with a trace of the
 * cycles around its first mismatch: the last operation on the first differing hit point, or
 * else the radiance pass. (After --reset-at the cycle is the second run's.) */
static void leave_fail_trace(int argc, char **argv, const cosim_drv_t *drv, int first_hp, int win)
{
    if (!fail_trace_wanted()) return;
    uint64_t first = UINT64_MAX, from, to;
    if (first_hp >= 0) first = cosim_drv_hp_cycle(drv, (uint32_t)first_hp);
    if (first != UINT64_MAX) fail_trace_window(first, 32, (uint64_t)win + 32, &from, &to);
    else cosim_drv_radiance_cycles(drv, &from, &to), first = from;
    char path[4096], win_arg[64];
    fail_trace_path(path, sizeof path, NULL, first);
    snprintf(win_arg, sizeof win_arg, "%llu:%llu", (unsigned long long)from, (unsigned long long)to);
    const char *extra[] = {"--trace", path, "--trace-window", win_arg};
    if (fail_trace_rerun(argc, argv, extra, 4, path) == 0)
        printf("top_bench: first mismatch at cycle %llu; cycles %llu..%llu traced in %s\n", (unsigned long long)first,
               (unsigned long long)from, (unsigned long long)to, path);
    else
        printf("top_bench: first mismatch at cycle %llu; the traced rerun wrote no %s\n", (unsigned long long)first, path);
}

/* The bench's options (the usage above) and its scenario. */
typedef struct {
    int preu, photons, nhp, reorder, dp, pf, reset_at, hold_reset;
    double gap, stall, alpha;
    uint64_t wait_limit, seed;
    const char *scenario, *trace;
    unsigned long long win_from, win_to;
    draw_scenario_t sc;
    int one, dense, abank;
} bench_opts_t;

/* Parses the command line into *o; 0, or 2 (a usage error, said on stderr). */
static int parse_args(int argc, char **argv, bench_opts_t *o)
{
    *o = (bench_opts_t){.preu = 4, .photons = 3000, .nhp = 2000, .reorder = 1, .reset_at = -1, .alpha = 0.7,
                        .seed = 1, .scenario = "random", .win_to = UINT64_MAX};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--no-reorder")) { o->reorder = 0; continue; }
        if (!strcmp(a, "--pipe-fast")) { o->pf = 1; continue; }
        if (!strcmp(a, "--hold-reset")) { o->hold_reset = 1; continue; }
        if (!v) { fprintf(stderr, "top_bench: %s needs a value\n", a); return 2; }
        i++;
        if (!strcmp(a, "--preu")) o->preu = atoi(v);
        else if (!strcmp(a, "--scenario")) o->scenario = v;
        else if (!strcmp(a, "--datapath")) o->dp = atoi(v);
        else if (!strcmp(a, "--alpha")) o->alpha = atof(v);
        else if (!strcmp(a, "--photons")) o->photons = atoi(v);
        else if (!strcmp(a, "--hp")) o->nhp = atoi(v);
        else if (!strcmp(a, "--gap")) o->gap = atof(v);
        else if (!strcmp(a, "--stall")) o->stall = atof(v);
        else if (!strcmp(a, "--reset-at")) o->reset_at = atoi(v);
        else if (!strcmp(a, "--wait-limit")) o->wait_limit = strtoull(v, NULL, 0);
        else if (!strcmp(a, "--seed")) o->seed = strtoull(v, NULL, 0);
        else if (!strcmp(a, "--trace")) o->trace = v;
        else if (!strcmp(a, "--trace-window")) {
            if (sscanf(v, "%llu:%llu", &o->win_from, &o->win_to) != 2 || o->win_to < o->win_from) {
                fprintf(stderr, "top_bench: --trace-window %s is not FIRST:LAST\n", v);
                return 2;
            }
        }
        else { fprintf(stderr, "top_bench: unknown option %s\n", a); return 2; }
    }
    o->abank = !strcmp(o->scenario, "abank");
    if (draw_scenario(o->abank ? "random" : o->scenario, &o->sc)) {
        fprintf(stderr, "top_bench: unknown scenario %s\n", o->scenario);
        return 2;
    }
    o->one = o->sc == DRAW_ONE, o->dense = o->sc == DRAW_DENSE;
    if (o->nhp < 1 || o->nhp > (1 << COSIM_HPAW) || o->photons < 0) { fprintf(stderr, "top_bench: bad sizes\n"); return 2; }
    if ((o->dp != 0 && o->dp != 1) || !(o->alpha > 0 && o->alpha <= 1)) {
        fprintf(stderr, "top_bench: bad --datapath or --alpha\n");
        return 2;
    }
    if (o->abank) o->reorder = 0;   /* its own host streams the candidates as drawn */
    if (o->abank && (o->stall > 0 || o->reset_at >= 0 || o->hold_reset)) {
        fprintf(stderr, "top_bench: abank takes no faults but --gap\n");
        return 2;
    }
    return 0;
}

/* The synthetic work: hit points (the model state of the chosen datapath, and the words loaded
 * into the RTL), their pixels, and the photons with their candidate lists (photon p's at
 * cands + p * MAX_CAND); the model is updated in photon order as they are drawn. */
typedef struct {
    preu_hp_t *hp;
    preu_shp_t *sp;
    preu_hpw_t *init;
    int32_t *pixel;
    preu_photon_t *phs;
    uint32_t *cands;
    int *ncand, npix;
} bench_work_t;

static void free_work(bench_work_t *w)
{
    free(w->hp); free(w->sp); free(w->init); free(w->pixel); free(w->phs); free(w->cands); free(w->ncand);
}

/* Hit points in the unit cube; dense: 40 per pixel, else 3 per pixel. */
static void make_hit_points(const bench_opts_t *o, bench_work_t *w)
{
    const int per_px = o->dense ? 40 : 3;
    w->npix = (o->nhp + per_px - 1) / per_px;
    for (int i = 0; i < o->nhp; i++) {
        preu_hp_t *h = &w->hp[i];
        for (int c = 0; c < 3; c++) {
            h->pos[c] = fb(frand(0, 1));
            h->f[c] = fb(frand(0, 1));
            h->tau[c] = 0;
        }
        h->r2 = fb(o->one ? 4.0f : frand(0.01f, 0.2f));
        h->n = 0;
        memcpy(w->sp[i].pos, h->pos, sizeof h->pos);
        memcpy(w->sp[i].f, h->f, sizeof h->f);
        preu_stable_init(&w->sp[i], (double)fp32_from_bits(h->r2));
        w->pixel[i] = i / per_px;
        if (o->dp) preu_hpw_from_stable(&w->init[i], &w->sp[i]);
        else preu_hpw_from_paper(&w->init[i], h);
    }
}

/* Allocates and draws the work; -1 when out of memory. */
static int make_work(const bench_opts_t *o, uint32_t alpha32, uint32_t kappa32, bench_work_t *w, mis_stream_t *mis)
{
    const size_t np = (size_t)(o->photons ? o->photons : 1), nh = (size_t)o->nhp;
    *w = (bench_work_t){.hp = calloc(nh, sizeof *w->hp), .sp = calloc(nh, sizeof *w->sp),
                        .init = calloc(nh, sizeof *w->init), .pixel = calloc(nh, sizeof *w->pixel),
                        .phs = malloc(np * sizeof *w->phs), .cands = malloc(np * MAX_CAND * sizeof *w->cands),
                        .ncand = malloc(np * sizeof *w->ncand)};
    if (!w->hp || !w->sp || !w->init || !w->pixel || !w->phs || !w->cands || !w->ncand) return -1;
    if (o->abank && mis_init(mis, (size_t)o->photons, MAX_CAND)) return -1;
    make_hit_points(o, w);
    for (int p = 0; p < o->photons; p++) {
        preu_photon_t ph;
        uint32_t *cand = w->cands + (size_t)p * MAX_CAND;
        for (int c = 0; c < 3; c++) { ph.pos[c] = fb(frand(0, 1)); ph.phi[c] = fb(frand(0, 2)); }
        size_t n = draw_candidates(&rng_state, o->abank ? DRAW_RANDOM : o->sc, p, (uint32_t)o->nhp, cand);
        for (size_t k = 0; k < n; k++) {
            if (o->dp) preu_stable_update(&w->sp[cand[k]], &ph, kappa32);
            else preu_update(&w->hp[cand[k]], &ph, alpha32);
        }
        if (o->abank) mis_add(mis, o->preu, &ph, cand, n, &rng_state);
        w->phs[p] = ph;
        w->ncand[p] = (int)n;
    }
    return 0;
}

/* Every hit point's words read back against the model's; the mismatches (the first 20 printed),
 * and in *first_hp the first differing hit point (-1: none). */
static unsigned long long compare_hit_points(cosim_drv_t *drv, const bench_opts_t *o, const bench_work_t *w,
                                             int *first_hp)
{
    unsigned long long bad = 0;
    *first_hp = -1;
    for (int i = 0; i < o->nhp; i++) {
        preu_hpw_t h, m;
        uint32_t px;
        cosim_drv_read_hp(drv, (uint32_t)i, &h, &px);
        if (o->dp) preu_hpw_from_stable(&m, &w->sp[i]);
        else preu_hpw_from_paper(&m, &w->hp[i]);
        int differ = px != (uint32_t)w->pixel[i] || memcmp(h.pos, m.pos, sizeof h.pos) ||
                     memcmp(h.f, m.f, sizeof h.f) || memcmp(h.st, m.st, (size_t)preu_state_words(o->dp) * sizeof h.st[0]);
        if (!differ) continue;
        if (*first_hp < 0) *first_hp = i;
        if (bad < 20) {
            printf("MISMATCH hit point %d (px RTL %u model %d): state words RTL/model", i, px, w->pixel[i]);
            for (int k = 0; k < preu_state_words(o->dp); k++) printf(" %08x/%08x", h.st[k], m.st[k]);
            printf("\n");
        }
        bad++;
    }
    return bad;
}

/* The radiance pass: the model in ADISO-REC's issue order against the RTL's pass; the
 * mismatches (printed while fewer than 20 in all), or -1 when the pass fails. */
static long long compare_radiance(cosim_drv_t *drv, cosim_rtl_t *rtl, const bench_opts_t *o, const bench_work_t *w,
                                  unsigned long long bad_before)
{
    const uint32_t ne = preu_n_emitted((uint64_t)o->photons > 0 ? (uint64_t)o->photons : 1);
    uint32_t *order = malloc((size_t)o->nhp * sizeof *order);
    uint32_t *Lm = calloc((size_t)w->npix * 3, sizeof *Lm), *Lr = calloc((size_t)w->npix * 3, sizeof *Lr);
    long long bad = -1;
    if (order && Lm && Lr) {
        adiso_order((uint32_t)o->nhp, o->preu, cosim_rtl_radiance_depth(rtl), order);
        for (int k = 0; k < o->nhp; k++) {
            uint32_t *L = Lm + 3 * (size_t)w->pixel[order[k]];
            if (o->dp) preu_stable_radiance(L, &w->sp[order[k]], ne);
            else preu_radiance(L, &w->hp[order[k]], ne);
        }
        if (cosim_drv_radiance(drv, (uint32_t)o->nhp, ne, (size_t)w->npix, Lr)) fprintf(stderr, "top_bench: %s\n", cosim_drv_error(drv));
        else bad = 0;
    }
    for (int j = 0; bad >= 0 && j < w->npix * 3; j++) {
        if (Lr[j] == Lm[j]) continue;
        if (bad_before + (unsigned long long)bad < 20)
            printf("MISMATCH pixel %d channel %d: RTL %08x model %08x\n", j / 3, j % 3, Lr[j], Lm[j]);
        bad++;
    }
    free(order); free(Lm); free(Lr);
    return bad;
}

/* The counters' checks (operations counted as sent; stage-A bank conflicts only in abank) and
 * the summary line; returns the mismatches. cnt: after the update pass, cnt2: after radiance. */
static unsigned long long report(const bench_opts_t *o, uint64_t sent, const uint64_t *cnt, const uint64_t *cnt2,
                                 unsigned long long bad)
{
    uint64_t ops = 0, rops = 0;
    for (int l = 0; l < o->preu; l++) { ops += cnt[CNT_OPS0 + l]; rops += cnt2[CNT_OPS0 + l]; }
    rops -= ops;
    if (ops != sent || rops != (uint64_t)o->nhp) {
        printf("MISMATCH operation counts: update %llu (sent %llu), radiance %llu (hit points %d)\n",
               (unsigned long long)ops, (unsigned long long)sent, (unsigned long long)rops, o->nhp);
        bad++;
    }
    if (o->abank && cnt[CNT_ABANK] == 0) {
        printf("MISMATCH abank: misplaced index entries caused no stage-A bank conflict in update mode\n");
        bad++;
    }
    if (!o->abank && cnt[CNT_ABANK] != 0) {   /* the driver's placement promises none */
        printf("MISMATCH abank: %llu stage-A bank conflict cycles in update mode with the driver's index placement\n",
               (unsigned long long)cnt[CNT_ABANK]);
        bad++;
    }
    printf("top_bench preu=%d datapath=%d pipe_fast=%d scenario=%s photons=%d hp=%d gap=%g reorder=%d: update %llu ops / %llu cycles "
           "(util %.4f; short cycles haz %llu dup %llu bank %llu abank %llu starve %llu), radiance %llu ops / %llu cycles "
           "(haz %llu dup %llu bank %llu abank %llu starve %llu): %s\n",
           o->preu, o->dp, o->pf, o->scenario, o->photons, o->nhp, o->gap, o->reorder, (unsigned long long)ops,
           (unsigned long long)cnt[CNT_CYC_UPD],
           cnt[CNT_CYC_UPD] ? (double)ops / (double)(o->preu * cnt[CNT_CYC_UPD]) : 0.0,
           (unsigned long long)cnt[CNT_HAZ], (unsigned long long)cnt[CNT_DUP], (unsigned long long)cnt[CNT_BANK],
           (unsigned long long)cnt[CNT_ABANK], (unsigned long long)cnt[CNT_STARVE],
           (unsigned long long)rops, (unsigned long long)cnt2[CNT_CYC_RAD],
           (unsigned long long)(cnt2[CNT_HAZ] - cnt[CNT_HAZ]), (unsigned long long)(cnt2[CNT_DUP] - cnt[CNT_DUP]),
           (unsigned long long)(cnt2[CNT_BANK] - cnt[CNT_BANK]), (unsigned long long)(cnt2[CNT_ABANK] - cnt[CNT_ABANK]),
           (unsigned long long)(cnt2[CNT_STARVE] - cnt[CNT_STARVE]), bad ? "FAIL" : "PASS");
    return bad;
}

int main(int argc, char **argv)
{
    bench_opts_t o;
    if (parse_args(argc, argv, &o)) return 2;
    rng_state = o.seed * 0x9E3779B97F4A7C15ull + 7;
    char err[256];
    cosim_rtl_t *rtl = cosim_rtl_new(o.preu, o.dp, o.pf, o.trace, err, sizeof err);
    if (!rtl) { fprintf(stderr, "top_bench: %s\n", err); return 2; }
    cosim_rtl_trace_window(rtl, o.win_from, o.win_to);
    const uint32_t alpha32 = preu_f32(o.alpha), kappa32 = preu_kappa(alpha32);
    cosim_rtl_in(rtl)->alpha = alpha32;
    cosim_rtl_in(rtl)->kappa = kappa32;
    cosim_drv_opts_t dopt = {.preu = o.preu, .datapath = o.dp, .hp_bank_w = cosim_rtl_hp_bank_w(rtl),
                             .reorder = o.reorder, .gap = o.gap, .stall = o.stall, .seed = o.seed,
                             .wait_limit = o.wait_limit};
    cosim_drv_t *drv = cosim_drv_new(rtl, &dopt);
    bench_work_t w;
    mis_stream_t mis;
    if (!drv || make_work(&o, alpha32, kappa32, &w, &mis)) { fprintf(stderr, "top_bench: out of memory\n"); return 2; }
    cosim_drv_load_hp(drv, w.init, w.pixel, (size_t)o.nhp);

    /* The photons, streamed to the RTL (the model took them in photon order above). */
    if (!o.abank && o.reset_at >= 0) {
        if (stream(drv, w.phs, w.cands, w.ncand, 0, o.reset_at < o.photons ? o.reset_at : o.photons)) return 1;
        if (!(drv = reset_and_reload(rtl, drv, &dopt, w.init, w.pixel, (size_t)o.nhp))) {
            fprintf(stderr, "top_bench: out of memory\n");
            return 2;
        }
    }
    if (o.hold_reset) cosim_rtl_set_reset(rtl, 1);   /* the PREE takes nothing: a wait must run out */
    if (!o.abank && stream(drv, w.phs, w.cands, w.ncand, 0, o.photons)) return o.hold_reset ? 3 : 1;
    if (o.hold_reset) { printf("top_bench: FAIL: no wait ran out with rst_ni held low\n"); return 1; }
    uint64_t sent = cosim_drv_ops_sent(drv);
    if (o.abank) {
        if (misplaced_stream(rtl, &mis, o.preu, o.gap, &rng_state)) { fprintf(stderr, "top_bench: the misplaced stream does not drain\n"); return 1; }
        sent = mis.ne;
    }
    if (cosim_drv_drain(drv)) { fprintf(stderr, "top_bench: %s\n", cosim_drv_error(drv)); return 1; }
    uint64_t cnt[COSIM_NCNT], cnt2[COSIM_NCNT];
    cosim_drv_counters(drv, cnt);

    int first_hp;
    unsigned long long bad = compare_hit_points(drv, &o, &w, &first_hp);
    long long rbad = compare_radiance(drv, rtl, &o, &w, bad);
    if (rbad < 0) return 1;
    cosim_drv_counters(drv, cnt2);
    bad = report(&o, sent, cnt, cnt2, bad + (unsigned long long)rbad);
    if (bad && !o.trace) leave_fail_trace(argc, argv, drv, first_hp, cosim_rtl_update_window(rtl));
    free_work(&w);
    if (o.abank) mis_free(&mis);
    cosim_drv_free(drv);
    cosim_rtl_free(rtl);
    return bad ? 1 : 0;
}
