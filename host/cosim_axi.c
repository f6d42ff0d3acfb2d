// SPDX-License-Identifier: Apache-2.0
/* cosim_axi.c: the cosim_drv.h API through the AXI4 wrapper (rtl/pree_axi.v): the co-simulation
 * host speaks to pree_axi through its driver, pree_drv (drv/pree_drv.h), on the back end that the
 * program's model provides (cosim_axi_backend, cosim_axi_rtl.h): the Verilated wrapper
 * (drv/pree_be_verilated.h; build/pree-cosim-axi-<d><n>) or a simulated ULX3S behind its UART
 * (drv/pree_be_uart.h, host/postroute_uart.cpp; build/postroute/pree-cosim-uart-*); linked in
 * place of cosim_drv.c. The driver's sequence is the one a board's host runs: this file only
 * turns the co-simulation's calls into the driver's.
 *
 * Photons go as beats of PhotonsPerCycle slots: with the scheduler (the default), one group of
 * its model's photons a beat (the group it took in one cycle), and the photon stream starts once
 * the candidate stream has COSIM_LEAD_ENTRIES of lead (the back end's lead); without it,
 * consecutive photons. The counters count the engine's work only (PREE_CNT_WORK): a batch from
 * its first photon until its interrupt is taken, and the radiance pass's command. With a gap
 * probability P (--gap), every stream and AXI4-Lite channel of the back end is throttled at
 * random, and candidate beats carry a random number of candidates in random lanes. */
#include "cosim_drv.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cosim_axi_rtl.h"
#include "pree_drv.h"

#define MAX_CAND   2048u              /* candidates of one photon at most (else the build's 2^IdxAW - NumPreu) */
#define HP_BLOCK   1024u              /* hit points read back at a time */
#define CYCLES_MS  100000u            /* the back end's cycles a millisecond (a 100 MHz aclk) */

struct cosim_drv {
    pree_drv_t *drv;
    cosim_drv_opts_t opt;
    char err[256];
    int hung, ppc;
    uint64_t ops, cand_sent, ph_sent;
    pree_photon_t beat[COSIM_MAX_PPC];   /* the beat being gathered and its candidates */
    unsigned nbeat;
    uint32_t *cand;
    size_t ncand, cand_cap;
    uint32_t hp_loaded;                  /* hit points [0, hp_loaded) loaded: the wrapper reads no others */
    uint32_t max_cand, idx_mask;         /* the build's: candidates a photon (a longer one is split), 2^IdxAW - 1 */
    pree_hit_point_t *blk;               /* hit points read back: [blk_base, blk_base + blk_n) */
    uint32_t blk_base, blk_n;
    cosim_sched_t *sched;
};

static int emit(void *user, const preu_photon_t *ph, const uint32_t *hps, uint32_t n, int first, uint64_t cycle,
                uint32_t *p);

static int fail(cosim_drv_t *d, const char *msg)
{
    if (!d->hung) snprintf(d->err, sizeof d->err, "%s", msg);
    d->hung = 1;
    return -1;
}

/* A driver call's result: 0, or -1 with the driver's message. */
static int check(cosim_drv_t *d, int rc)
{
    return rc == PREE_OK ? (d->hung ? -1 : 0) : fail(d, pree_error(d->drv));
}

/* The gathered beat onto the streams. */
static int flush_beat(cosim_drv_t *d)
{
    if (d->hung || d->nbeat == 0) return d->hung ? -1 : 0;
    const int rc = pree_send_photons(d->drv, d->beat, d->cand, d->nbeat);
    d->nbeat = 0;
    d->ncand = 0;
    return check(d, rc);
}

/* One photon and its candidates into the beat being gathered; first: it starts a scheduler group
 * (the group before it has its own beat). */
static int send(cosim_drv_t *d, const preu_photon_t *ph, const uint32_t *hps, uint32_t n, int first)
{
    if ((d->sched && first) || d->nbeat == (unsigned)d->ppc)
        if (flush_beat(d)) return -1;
    if (d->ncand + n > d->cand_cap) {
        size_t cap = d->cand_cap ? 2 * d->cand_cap : 4096;
        while (cap < d->ncand + n) cap *= 2;
        uint32_t *c = realloc(d->cand, cap * sizeof *c);
        if (!c) return fail(d, "out of memory");
        d->cand = c;
        d->cand_cap = cap;
    }
    pree_photon_t *b = &d->beat[d->nbeat++];
    memcpy(b->pos, ph->pos, sizeof b->pos);
    memcpy(b->phi, ph->phi, sizeof b->phi);
    b->n_cand = n;
    memcpy(d->cand + d->ncand, hps, n * sizeof *hps);
    d->ncand += n;
    d->ops += n;
    d->cand_sent += n;
    d->ph_sent++;
    return 0;
}

cosim_drv_t *cosim_drv_new(cosim_rtl_t *rtl, const cosim_drv_opts_t *opt)
{
    cosim_drv_t *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    d->opt = *opt;
    d->ppc = cosim_rtl_ppc(rtl);
    if (opt->schedule) {
        cosim_sched_opts_t so = {.preu = opt->preu, .hp_bank_w = opt->hp_bank_w,
                                 .win = cosim_rtl_update_window(rtl),
                                 .reg_flow = cosim_rtl_reg_flow(rtl),
                                 .reorder = opt->reorder, .window = opt->window, .ppc = d->ppc};
        d->sched = cosim_sched_new(&so, emit, d);
        if (!d->sched) { free(d); return NULL; }
    }
    pree_backend_t be;
    char err[256];
    if (cosim_axi_backend(&be, rtl, opt, err, sizeof err)) {
        fprintf(stderr, "pree cosim: %s\n", err);
        cosim_sched_free(d->sched);
        free(d);
        return NULL;
    }
    int rc = pree_open(&d->drv, &be);
    if (!d->drv) { cosim_sched_free(d->sched); free(d); return NULL; }
    if (check(d, rc)) return d;
    /* The build: the PREU count and datapath asked for (CONFIG0). */
    const pree_config_t *cfg = pree_config(d->drv);
    if (cfg->num_preu != (unsigned)opt->preu || cfg->datapath != (unsigned)(opt->datapath != 0)) {
        fail(d, "pree_axi: CONFIG0 does not match the build");
        return d;
    }
    d->max_cand = cfg->max_cand < MAX_CAND ? cfg->max_cand : MAX_CAND;
    d->idx_mask = (1u << cfg->idx_aw) - 1u;
    const uint64_t limit = opt->wait_limit ? opt->wait_limit : 10000000u;
    pree_set_timeout(d->drv, (unsigned)(10 * limit / CYCLES_MS));
    const pree_constants_t k = {.alpha = cosim_rtl_in(rtl)->alpha, .kappa = cosim_rtl_in(rtl)->kappa};
    rc = pree_set_constants(d->drv, &k);
    if (!rc) rc = pree_counters_enable(d->drv, PREE_CNT_WORK);
    check(d, rc);
    return d;
}

void cosim_drv_free(cosim_drv_t *d)
{
    if (!d) return;
    cosim_sched_free(d->sched);
    pree_close(d->drv);   /* the model stays the caller's */
    free(d->cand);
    free(d->blk);
    free(d);
}

const char *cosim_drv_error(const cosim_drv_t *d) { return d->err; }
uint64_t cosim_drv_ops_sent(const cosim_drv_t *d) { return d->ops; }
/* Not tracked through the wrapper: a failing AXI run names no trace window. */
uint64_t cosim_drv_hp_cycle(const cosim_drv_t *d, uint32_t i) { (void)d; (void)i; return UINT64_MAX; }
void cosim_drv_radiance_cycles(const cosim_drv_t *d, uint64_t *from, uint64_t *to) { (void)d; *from = *to = UINT64_MAX; }

void cosim_drv_counters(cosim_drv_t *d, uint64_t cnt[COSIM_NCNT])
{
    for (int k = 0; k < COSIM_NCNT; k++) cnt[k] = 0;
    if (!d->hung) check(d, pree_read_counters(d->drv, cnt, COSIM_NCNT));
}

void cosim_drv_load_hp(cosim_drv_t *d, const preu_hpw_t *hp, const int32_t *pixel, size_t n)
{
    if (d->hung) return;
    pree_hit_point_t *w = calloc(n ? n : 1, sizeof *w);
    if (!w) { fail(d, "out of memory"); return; }
    for (size_t i = 0; i < n; i++) {
        memcpy(w[i].state, hp[i].st, sizeof w[i].state);
        memcpy(w[i].pos, hp[i].pos, sizeof w[i].pos);
        memcpy(w[i].f, hp[i].f, sizeof w[i].f);
        w[i].pixel = (uint32_t)pixel[i];
    }
    check(d, pree_load_hit_points(d->drv, 0, w, n));
    free(w);
    if (n > d->hp_loaded) d->hp_loaded = (uint32_t)n;
}

static int emit(void *user, const preu_photon_t *ph, const uint32_t *hps, uint32_t n, int first, uint64_t cycle,
                uint32_t *p)
{
    (void)cycle;   /* the wrapper's latency is not the top's: no lag is tracked */
    cosim_drv_t *d = user;
    send(d, ph, hps, n, first);   /* a group goes in one beat */
    *p = (uint32_t)(-(int64_t)d->cand_sent) & d->idx_mask;   /* pree_axi's p_k */
    return d->hung ? -1 : 0;
}

/* Without the scheduler: the photon in its own beat. */
static int send_direct(void *user, const preu_photon_t *ph, const uint32_t *hps, size_t n)
{
    cosim_drv_t *d = user;
    send(d, ph, hps, (uint32_t)n, 1);
    return d->hung ? -1 : 0;
}

int cosim_drv_photon(cosim_drv_t *d, const preu_photon_t *ph, const uint32_t *hps, size_t n)
{
    if (cosim_sched_offer(d->sched, d->hung, d->max_cand, ph, hps, n, send_direct, d, d->err, sizeof d->err)) return -1;
    return d->hung ? -1 : 0;
}

int cosim_drv_sched_stats(const cosim_drv_t *d, cosim_sched_stats_t *st)
{
    if (!d->sched) return -1;
    cosim_sched_stats(d->sched, st);
    return 0;
}

/* Everything gathered onto the streams, and the batch closed (pree_end_batch: a beat of empty
 * slots with TLAST, its interrupt once every photon is applied). */
int cosim_drv_barrier(cosim_drv_t *d)
{
    if (d->hung) return -1;
    if (d->sched && cosim_sched_flush(d->sched)) return fail(d, "photon scheduler: out of memory");
    if (flush_beat(d)) return -1;
    d->blk_n = 0;     /* hit points read back before are stale */
    return check(d, pree_end_batch(d->drv));
}

int cosim_drv_drain(cosim_drv_t *d)
{
    if (cosim_drv_barrier(d)) return -1;
    uint32_t ph_in, ph_done, cand_in;
    if (check(d, pree_read_stream_counts(d->drv, &ph_in, &ph_done, &cand_in))) return -1;
    if (ph_in != (uint32_t)d->ph_sent || ph_done != ph_in || cand_in != (uint32_t)d->cand_sent)
        return fail(d, "PH_IN, PH_DONE or CAND_IN differs from the photons and candidates sent");
    return 0;
}

void cosim_drv_read_hp(cosim_drv_t *d, uint32_t i, preu_hpw_t *hp, uint32_t *pixel)
{
    memset(hp, 0, sizeof *hp);
    *pixel = 0;
    if (i >= d->hp_loaded) fail(d, "a hit point read beyond those loaded");
    if (!d->blk && !(d->blk = malloc(HP_BLOCK * sizeof *d->blk))) fail(d, "out of memory");
    if (d->hung) return;
    if (i < d->blk_base || i >= d->blk_base + d->blk_n) {
        d->blk_base = i;
        d->blk_n = d->hp_loaded - i < HP_BLOCK ? d->hp_loaded - i : HP_BLOCK;
        if (check(d, pree_read_hit_points(d->drv, i, d->blk, d->blk_n))) { d->blk_n = 0; return; }
    }
    const pree_hit_point_t *b = &d->blk[i - d->blk_base];
    memcpy(hp->st, b->state, sizeof hp->st);
    memcpy(hp->pos, b->pos, sizeof hp->pos);
    memcpy(hp->f, b->f, sizeof hp->f);
    *pixel = b->pixel;
}

int cosim_drv_radiance(cosim_drv_t *d, uint32_t n_hit, uint32_t ne, size_t npix, uint32_t *L)
{
    if (d->hung) return -1;
    d->blk_n = 0;
    if (check(d, pree_radiance(d->drv, n_hit, ne, 0, (uint32_t)npix))) return -1;
    return check(d, pree_read_pixels(d->drv, 0, L, npix));
}
