// SPDX-License-Identifier: Apache-2.0
/* cosim_axi.c: the PREE host protocol through the AXI4 wrapper (rtl/pree_axi.v,
 * docs/integration.md): the cosim_drv.h API on a Verilated pree_axi (cosim_axi_rtl.h), linked
 * into build/pree-cosim-axi-<d><n> in place of cosim_drv.c.
 *
 * Hit points go in on s_axis_hp, photons on s_axis_ph (PhotonsPerCycle slots a beat: with the
 * scheduler, one group of its model's photons a beat, the group it took in one cycle; without it,
 * consecutive photons) and their candidates, concatenated, on
 * s_axis_cand; results come back on m_axis after a command (CMD register). With a gap
 * probability P (--gap), every stream is throttled at random: a beat is offered in a cycle with
 * probability 1 - P (and, once offered, held until taken, as AXI4-Stream requires), m_axis and
 * the AXI4-Lite responses are accepted with probability 1 - P, and candidate beats carry a
 * random number of candidates in random lanes. With the scheduler (the default) the photons and
 * each photon's candidates come in its order; without it, in photon and engine order. */
#include "cosim_drv.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cosim_axi_rtl.h"
#include "cosim_sched.h"
#include "cosim_shadow.h"

/* Register byte addresses (docs/integration.md, "Register map"). */
enum { R_VERSION = 0x000, R_CONFIG0 = 0x004, R_STATUS = 0x018, R_CTRL = 0x010, R_CMD = 0x014, R_IRQ_EN = 0x01c, R_IRQ_STATUS = 0x020,
       R_ERR = 0x024, R_NE = 0x030, R_ALPHA = 0x034, R_KAPPA = 0x038, R_N_HIT = 0x03c,
       R_HP_PTR = 0x040, R_HP_COUNT = 0x044, R_PX_BASE = 0x048, R_PX_COUNT = 0x04c,
       R_PH_IN = 0x050, R_CAND_IN = 0x058,
       R_CNT0 = 0x100 };
enum { CMD_RAD = 1, CMD_HP_READ = 2, CMD_PX_CLEAR = 3, CMD_PX_READ = 4 };
enum { IRQ_BATCH = 1, IRQ_CMD = 2 };

#define PQ_CAP     1024u              /* queued photons (power of two) */
#define CQ_CAP     (1u << 16)         /* queued candidates (power of two) */
#define MAX_CAND   2048u              /* candidates of one photon (the wrapper: 4096 - NumPreu) */
#define HP_BLOCK   256u               /* hit points read back per command */
#define WAIT_LIMIT 10000000u

/* A queued photon; first: it starts a scheduler group (the photons the model took in one cycle,
 * which go in one beat). */
typedef struct { preu_photon_t ph; uint32_t n; int last, first; } photon_entry_t;

struct cosim_drv {
    cosim_rtl_t *rtl;
    cosim_axi_in_t *in;
    cosim_drv_opts_t opt;
    char err[256];
    uint64_t rng, ops, cand_sent, ph_sent;
    photon_entry_t pq[PQ_CAP];
    uint64_t pq_head, pq_tail;
    uint32_t cq[CQ_CAP];
    uint64_t cq_head, cq_tail;
    uint32_t cand_take;                /* candidates in the beat on offer */
    int ppc;                           /* photon slots a beat (the wrapper's PhotonsPerCycle) */
    int ph_take;                       /* photons in the beat on offer */
    int flowing;                       /* a photon beat offered since the stream (re)started */
    uint64_t lead_from;                /* cq_head then: the candidates' lead counts from it */
    uint32_t alpha, kappa;
    int started, hung;
    /* m_axis receiver: expected beats of the running read command. */
    int rx_user;
    uint32_t rx_n, rx_got;
    preu_hpw_t rx_hp[HP_BLOCK];
    uint32_t rx_pixel[HP_BLOCK];
    uint32_t *rx_px;
    uint32_t blk_base, blk_n;          /* the hit points in rx_hp */
    uint32_t hp_loaded;                /* hit points [0, hp_loaded) loaded: the wrapper reads no others */
    int irq;                           /* irq_o in the last cycle */
    cosim_sched_t *sched;
};

static int emit(void *user, const preu_photon_t *ph, const uint32_t *hps, uint32_t n, int first, uint64_t cycle,
                uint32_t *p);

static uint64_t next_rand(cosim_drv_t *d)
{
    d->rng = d->rng * 6364136223846793005ull + 1442695040888963407ull;
    return d->rng >> 33;
}

/* 1 with the gap probability: this cycle, hold back (an offer, a ready). */
static int gap(cosim_drv_t *d)
{
    return d->opt.gap > 0 && (double)next_rand(d) / 2147483648.0 < d->opt.gap;
}

static int fail(cosim_drv_t *d, const char *msg)
{
    if (!d->hung) snprintf(d->err, sizeof d->err, "%s", msg);
    d->hung = 1;
    return -1;
}

/* One m_axis beat into the running read command's buffer. */
static void receive(cosim_drv_t *d, const cosim_axi_out_t *o)
{
    if (d->rx_got >= d->rx_n || o->m_user != d->rx_user || o->m_last != (d->rx_got + 1 == d->rx_n)) {
        fail(d, "m_axis: a beat out of place (tuser, tlast or count)");
        return;
    }
    if (d->rx_user) memcpy(d->rx_px + 3 * (size_t)d->rx_got, o->m_px, sizeof o->m_px);
    else { d->rx_hp[d->rx_got] = o->m_hp; d->rx_pixel[d->rx_got] = o->m_pixel; }
    d->rx_got++;
}

/* Offer the next candidate beat: up to NumPreu queued candidates (random count and lanes with
 * gaps), held until taken. */
static void offer_cand(cosim_drv_t *d)
{
    cosim_axi_in_t *in = d->in;
    const uint32_t np = (uint32_t)d->opt.preu, avail = (uint32_t)(d->cq_tail - d->cq_head);
    if (in->cand_valid || avail == 0 || gap(d)) return;
    uint32_t k = avail < np ? avail : np;
    if (d->opt.gap > 0) k = 1 + (uint32_t)(next_rand(d) % k);
    uint32_t keep = 0, placed = 0;
    for (uint32_t j = 0; j < np && placed < k; j++) {
        /* A lane stays empty at random while enough lanes remain for the rest. */
        if (d->opt.gap > 0 && np - j > k - placed && next_rand(d) % 4 == 0) continue;
        keep |= 1u << j;
        in->cand[j] = d->cq[(d->cq_head + placed++) & (CQ_CAP - 1)];
    }
    in->cand_keep = keep;
    in->cand_valid = 1;
    d->cand_take = k;
}

/* Photons for the next beat: up to PhotonsPerCycle queued ones, a batch's last one ending it;
 * scheduled, exactly the next group, once it is complete (the next group has begun, or the
 * batch ends). 0: none yet. */
static int beat_count(const cosim_drv_t *d)
{
    const uint64_t avail = d->pq_tail - d->pq_head;
    int k = 0;
    while (k < d->ppc && (uint64_t)k < avail) {
        const photon_entry_t *p = &d->pq[(d->pq_head + (uint64_t)k) & (PQ_CAP - 1)];
        if (d->sched && k > 0 && p->first) return k;
        k++;
        if (p->last) return k;
    }
    if (d->sched && k < d->ppc && (uint64_t)k == avail) return 0;   /* more of the group may follow */
    return k;
}

/* Offer the next photon beat: its slots in photon order, the rest empty (N^P = 0); tlast with
 * the batch's last photon. Held until taken. A scheduled stream starts once the candidate
 * stream has a lead (COSIM_LEAD_ENTRIES, or every queued candidate taken): the candidates then
 * stay ahead of the photons that need them (both move at the PREUs' rate), so each beat enters
 * the engine whole, in the cycle the scheduler's model took its group. */
static void offer_ph(cosim_drv_t *d)
{
    cosim_axi_in_t *in = d->in;
    if (in->ph_valid || gap(d)) return;
    if (d->sched && !d->flowing && d->cq_head != d->cq_tail &&
        d->cq_head - d->lead_from < COSIM_LEAD_ENTRIES(d->opt.preu))
        return;
    const int k = beat_count(d);
    if (k == 0) return;
    memset(in->ph, 0, sizeof in->ph);
    memset(in->ph_n, 0, sizeof in->ph_n);
    for (int s = 0; s < k; s++) {
        const photon_entry_t *p = &d->pq[(d->pq_head + (uint64_t)s) & (PQ_CAP - 1)];
        in->ph[s] = p->ph;
        in->ph_n[s] = p->n;
        in->ph_last = p->last;
    }
    in->ph_valid = 1;
    d->ph_take = k;
    d->flowing = 1;
}

/* One clock cycle: offers on the input streams, readiness on the outputs, the edge, and the
 * bookkeeping of whatever moved. */
static const cosim_axi_out_t *cycle(cosim_drv_t *d)
{
    cosim_axi_in_t *in = d->in;
    offer_ph(d);
    offer_cand(d);
    in->m_ready = !gap(d);
    const cosim_axi_out_t *o = cosim_axi_tick(d->rtl);
    if (o->fired & AXI_PH) { in->ph_valid = 0; d->pq_head += (uint64_t)d->ph_take; }
    if (o->fired & AXI_CAND) { in->cand_valid = 0; d->cq_head += d->cand_take; }
    if (o->fired & AXI_M) receive(d, o);
    d->irq = o->irq;
    return o;
}

/* AXI4-Lite write and read, with random delays on every channel. */
static void lite_write(cosim_drv_t *d, uint32_t addr, uint32_t v)
{
    cosim_axi_in_t *in = d->in;
    int aw = 0, w = 0;
    uint64_t guard = 0;
    in->awaddr = addr;
    in->wdata = v;
    while (!d->hung) {
        if (!aw && !in->awvalid) in->awvalid = !gap(d);
        if (!w && !in->wvalid) in->wvalid = !gap(d);
        in->bready = aw && w && !gap(d);
        const cosim_axi_out_t *o = cycle(d);
        if (o->fired & AXI_AW) { in->awvalid = 0; aw = 1; }
        if (o->fired & AXI_W) { in->wvalid = 0; w = 1; }
        if (o->fired & AXI_B) { in->bready = 0; return; }
        if (++guard > WAIT_LIMIT) fail(d, "AXI4-Lite write: no response");
    }
}

static uint32_t lite_read(cosim_drv_t *d, uint32_t addr)
{
    cosim_axi_in_t *in = d->in;
    int ar = 0;
    uint64_t guard = 0;
    in->araddr = addr;
    while (!d->hung) {
        if (!ar && !in->arvalid) in->arvalid = !gap(d);
        in->rready = ar && !gap(d);
        const cosim_axi_out_t *o = cycle(d);
        if (o->fired & AXI_AR) { in->arvalid = 0; ar = 1; }
        if (o->fired & AXI_R) { in->rready = 0; return o->rdata; }
        if (++guard > WAIT_LIMIT) fail(d, "AXI4-Lite read: no response");
    }
    return 0;
}

/* Wait for an interrupt cause, then clear it. 0, or -1 on a timeout or a wrapper error. */
static int wait_irq(cosim_drv_t *d, uint32_t cause)
{
    uint64_t guard = 0;
    for (;;) {
        while (!d->irq && !d->hung) {
            cycle(d);
            if (++guard > WAIT_LIMIT) return fail(d, "the PREE made no progress (no interrupt)");
        }
        if (d->hung) return -1;
        uint32_t st = lite_read(d, R_IRQ_STATUS);
        if (st & cause) { lite_write(d, R_IRQ_STATUS, cause); break; }
        cycle(d);
    }
    if (lite_read(d, R_ERR)) return fail(d, "pree_axi: ERR register set");
    return d->hung ? -1 : 0;
}

/* Run a read command and collect its n beats into the receiver. */
static int read_cmd(cosim_drv_t *d, uint32_t cmd, int user, uint32_t n)
{
    d->rx_user = user;
    d->rx_n = n;
    d->rx_got = 0;
    lite_write(d, R_CMD, cmd);
    if (wait_irq(d, IRQ_CMD)) return -1;
    if (d->rx_got != n) return fail(d, "m_axis: fewer beats than asked for");
    return 0;
}

cosim_drv_t *cosim_drv_new(cosim_rtl_t *rtl, const cosim_drv_opts_t *opt)
{
    cosim_drv_t *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    d->rtl = rtl;
    d->in = cosim_axi_in(rtl);
    d->opt = *opt;
    d->rng = opt->seed * 2862933555777941757ull + 3037000493ull;
    d->ppc = cosim_rtl_ppc(rtl);
    if (opt->schedule) {
        cosim_sched_opts_t so = {.preu = opt->preu, .hp_bank_w = opt->hp_bank_w,
                                 .win = cosim_rtl_update_window(rtl),
                                 .reg_flow = cosim_rtl_reg_flow(rtl),
                                 .reorder = opt->reorder, .window = opt->window, .ppc = d->ppc};
        d->sched = cosim_sched_new(&so, emit, d);
        if (!d->sched) { free(d); return NULL; }
    }
    /* The build: version 2.x, the PREU count and datapath asked for (CONFIG0). */
    const uint32_t ver = lite_read(d, R_VERSION), c0 = lite_read(d, R_CONFIG0);
    if (ver >> 16 != 2 || (c0 & 0xff) != (uint32_t)opt->preu || (c0 >> 31) != (uint32_t)(opt->datapath != 0))
        fail(d, "pree_axi: VERSION or CONFIG0 does not match the build");
    d->alpha = cosim_rtl_in(rtl)->alpha;
    d->kappa = cosim_rtl_in(rtl)->kappa;
    lite_write(d, R_ALPHA, d->alpha);
    lite_write(d, R_KAPPA, d->kappa);
    lite_write(d, R_IRQ_EN, IRQ_BATCH | IRQ_CMD);
    return d;
}

void cosim_drv_free(cosim_drv_t *d)
{
    if (!d) return;
    cosim_sched_free(d->sched);
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
    for (int k = 0; k < 7 + d->opt.preu; k++) {
        uint64_t lo = lite_read(d, R_CNT0 + 8u * (uint32_t)k);
        cnt[k] = lo | (uint64_t)lite_read(d, R_CNT0 + 8u * (uint32_t)k + 4) << 32;
    }
}

void cosim_drv_load_hp(cosim_drv_t *d, const preu_hpw_t *hp, const int32_t *pixel, size_t n)
{
    cosim_axi_in_t *in = d->in;
    lite_write(d, R_HP_PTR, 0);
    uint64_t guard = 0;
    for (size_t i = 0; i < n && !d->hung;) {
        if (!in->hp_valid && !gap(d)) {
            in->hp = hp[i];
            in->hp_pixel = (uint32_t)pixel[i];
            in->hp_valid = 1;
        }
        if (cycle(d)->fired & AXI_HP) { in->hp_valid = 0; i++; guard = 0; }
        if (++guard > WAIT_LIMIT) fail(d, "s_axis_hp: not taken");
    }
    if (lite_read(d, R_HP_PTR) != (uint32_t)n) fail(d, "HP_PTR does not count the hit points loaded");
    if (n > d->hp_loaded) d->hp_loaded = (uint32_t)n;
}

/* Queue one photon and its candidates (in stream order); clock while the queues are long. */
static void send(cosim_drv_t *d, const preu_photon_t *ph, const uint32_t *hps, uint32_t n, int last, int first)
{
    uint64_t guard = 0;
    while ((d->pq_tail - d->pq_head >= PQ_CAP / 2 || d->cq_tail - d->cq_head + n > CQ_CAP) && !d->hung) {
        cycle(d);
        if (++guard > WAIT_LIMIT) fail(d, "the photon streams are not taken");
    }
    if (!d->started) { d->started = 1; lite_write(d, R_CTRL, 1); }
    photon_entry_t *pe = &d->pq[d->pq_tail++ & (PQ_CAP - 1)];
    pe->ph = *ph;
    pe->n = n;
    pe->last = last;
    pe->first = first;
    for (uint32_t k = 0; k < n; k++) d->cq[d->cq_tail++ & (CQ_CAP - 1)] = hps[k];
    d->ops += n;
    d->cand_sent += n;
    d->ph_sent += n > 0;   /* PH_IN counts photons, not empty slots */
}

static int emit(void *user, const preu_photon_t *ph, const uint32_t *hps, uint32_t n, int first, uint64_t cycle,
                uint32_t *p)
{
    (void)cycle;   /* the wrapper's latency is not the top's: no lag is tracked */
    cosim_drv_t *d = user;
    send(d, ph, hps, n, 0, first);   /* a group goes in one beat */
    *p = (uint32_t)(-(int64_t)d->cand_sent) & ((1u << COSIM_IDXAW) - 1);   /* pree_axi's p_k */
    return d->hung ? -1 : 0;
}

int cosim_drv_photon(cosim_drv_t *d, const preu_photon_t *ph, const uint32_t *hps, size_t n)
{
    const int r = cosim_sched_offer(d->sched, d->hung, MAX_CAND, ph, hps, n, d->err, sizeof d->err);
    if (r < 0) return -1;
    if (r == 1) send(d, ph, hps, (uint32_t)n, 0, 1);
    return d->hung ? -1 : 0;
}

int cosim_drv_sched_stats(const cosim_drv_t *d, cosim_sched_stats_t *st)
{
    if (!d->sched) return -1;
    cosim_sched_stats(d->sched, st);
    return 0;
}

/* Everything queued, then a beat of empty slots (N^P = 0, dropped by the wrapper) with TLAST
 * closes the batch: its interrupt comes once every photon is applied. */
int cosim_drv_barrier(cosim_drv_t *d)
{
    if (d->hung) return -1;
    if (d->sched && cosim_sched_flush(d->sched)) return fail(d, "photon scheduler: out of memory");
    preu_photon_t none = {0};
    send(d, &none, NULL, 0, 1, 1);
    if (wait_irq(d, IRQ_BATCH)) return -1;
    lite_write(d, R_CTRL, 0);
    d->started = 0;   /* the next photon starts the counters again */
    d->flowing = 0;   /* and the next photons wait for the candidates' lead */
    d->lead_from = d->cq_head;
    d->blk_n = 0;     /* hit points read back before are stale */
    if (!(lite_read(d, R_STATUS) & 1)) return fail(d, "batch interrupt before STATUS.idle");
    return 0;
}

int cosim_drv_drain(cosim_drv_t *d)
{
    if (cosim_drv_barrier(d)) return -1;
    if (lite_read(d, R_PH_IN) != (uint32_t)d->ph_sent || lite_read(d, R_CAND_IN) != (uint32_t)d->cand_sent)
        return fail(d, "PH_IN or CAND_IN differs from the photons and candidates sent");
    /* An unknown command is refused and flagged in ERR (bit 0, write 1 to clear). */
    lite_write(d, R_CMD, 7);
    if (lite_read(d, R_ERR) != 1) return fail(d, "ERR does not flag an unknown command");
    lite_write(d, R_ERR, 1);
    return d->hung ? -1 : 0;
}

void cosim_drv_read_hp(cosim_drv_t *d, uint32_t i, preu_hpw_t *hp, uint32_t *pixel)
{
    if (i >= d->hp_loaded) fail(d, "a hit point read beyond those loaded");
    if (d->hung) { memset(hp, 0, sizeof *hp); *pixel = 0; return; }
    if (i < d->blk_base || i >= d->blk_base + d->blk_n) {
        const uint32_t cap = d->hp_loaded;
        d->blk_base = i;
        d->blk_n = cap - i < HP_BLOCK ? cap - i : HP_BLOCK;
        lite_write(d, R_HP_PTR, i);
        lite_write(d, R_HP_COUNT, d->blk_n);
        if (read_cmd(d, CMD_HP_READ, 0, d->blk_n)) d->blk_n = 0;
    }
    if (d->hung) { memset(hp, 0, sizeof *hp); *pixel = 0; return; }
    *hp = d->rx_hp[i - d->blk_base];
    *pixel = d->rx_pixel[i - d->blk_base];
}

int cosim_drv_radiance(cosim_drv_t *d, uint32_t n_hit, uint32_t ne, size_t npix, uint32_t *L)
{
    if (d->hung) return -1;
    d->blk_n = 0;
    lite_write(d, R_PX_BASE, 0);
    lite_write(d, R_PX_COUNT, (uint32_t)npix);
    lite_write(d, R_CMD, CMD_PX_CLEAR);
    if (wait_irq(d, IRQ_CMD)) return -1;
    lite_write(d, R_NE, ne);
    lite_write(d, R_N_HIT, n_hit);
    lite_write(d, R_CTRL, 1);
    lite_write(d, R_CMD, CMD_RAD);
    if (wait_irq(d, IRQ_CMD)) return -1;
    lite_write(d, R_CTRL, 0);
    d->rx_px = L;
    return read_cmd(d, CMD_PX_READ, 1, (uint32_t)npix);
}
