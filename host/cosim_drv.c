// SPDX-License-Identifier: Apache-2.0
/* cosim_drv.c: the PREE host protocol on a Verilated pree_top (see cosim_drv.h). */
#include "cosim_drv.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cosim_reorder.h"
#include "cosim_sched.h"
#include "cosim_shadow.h"

#define IDX_DEPTH (1u << COSIM_IDXAW)
#define IQ_CAP    (2u * IDX_DEPTH)     /* queued index writes (power of two) */
#define PQ_CAP    1024u                /* queued photons (power of two) */
#define AQ_CAP    (2u * IDX_DEPTH)     /* allocated, unretired photons (power of two) */
#define MAX_CAND  (IDX_DEPTH / 2)      /* candidates of one photon */

typedef struct { uint32_t addr, hp; } idx_entry_t;
typedef struct {
    preu_photon_t ph;
    uint32_t paddr, n;
    uint64_t widx_end;                 /* the index-queue position after its entries */
    int first;                         /* it starts a scheduler group (one cycle's photons) */
    uint64_t model_cycle;              /* scheduled: the cycle the scheduler's model took it in */
} photon_entry_t;
typedef struct { uint64_t start, end; } alloc_entry_t;

struct cosim_drv {
    cosim_rtl_t *rtl;
    cosim_in_t *in;
    cosim_drv_opts_t opt;
    char err[256];
    idx_entry_t iq[IQ_CAP];
    uint64_t iq_head, iq_tail;         /* absolute counts: written, queued */
    photon_entry_t pq[PQ_CAP];
    uint64_t pq_head, pq_tail;
    alloc_entry_t aq[AQ_CAP];
    uint64_t aq_head, aq_tail;
    uint64_t alloc_end;                /* absolute index-table position after the last photon */
    uint64_t prev_p;                   /* absolute p of the last photon */
    uint32_t retired;                  /* photons_done_o seen so far */
    int ready;                         /* ph_ready_o after the last edge */
    int ppc;                           /* the model's photon slots (PhotonsPerCycle) */
    int closed;                        /* the scheduler has sent everything (drain) */
    uint64_t rng;
    uint64_t ops;
    cosim_reorder_t ro;                /* the unscheduled stream's candidate order */
    uint32_t *cand;                    /* reorder scratch */
    cosim_sched_t *sched;              /* photon scheduler, or NULL (photon order) */
    int started;                       /* a photon has been offered (since the last barrier) */
    uint64_t lead_from;                /* iq_head when the stream (re)started: the lead counts from it */
    uint64_t offset;                   /* scheduled: RTL cycle - model cycle of the first group */
    int have_offset;
    uint64_t groups_late, max_lag;     /* groups taken in another cycle than offset + the model's */
    int hung;                          /* a wait ran out (stuck): every later call fails */
    uint64_t *hp_cycle;                /* per hit point: cycle of its last operation's issue */
    size_t n_hp;
    uint64_t rad_from, rad_to;         /* the radiance pass's cycles */
};

static int emit(void *user, const preu_photon_t *ph, const uint32_t *hps, uint32_t n, int first, uint64_t cycle,
                uint32_t *p);

static uint64_t next_rand(cosim_drv_t *d)
{
    d->rng = d->rng * 6364136223846793005ull + 1442695040888963407ull;
    return d->rng >> 33;
}

cosim_drv_t *cosim_drv_new(cosim_rtl_t *rtl, const cosim_drv_opts_t *opt)
{
    cosim_drv_t *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    d->cand = malloc(MAX_CAND * sizeof *d->cand);
    if (!d->cand) { free(d); return NULL; }
    d->rtl = rtl;
    d->in = rtl ? cosim_rtl_in(rtl) : NULL;
    d->opt = *opt;
    d->ro = (cosim_reorder_t){.np = opt->preu, .bank_w = opt->hp_bank_w, .on = opt->reorder};
    d->rng = opt->seed * 2862933555777941757ull + 3037000493ull;
    d->ready = rtl ? cosim_rtl_ph_ready(rtl) : 0;
    d->ppc = rtl ? cosim_rtl_ppc(rtl) : opt->ppc;
    if (opt->schedule) {
        cosim_sched_opts_t so = {.preu = opt->preu, .hp_bank_w = opt->hp_bank_w,
                                 .win = rtl ? cosim_rtl_update_window(rtl) : opt->win,
                                 .reg_flow = rtl ? cosim_rtl_reg_flow(rtl) : opt->reg_flow,
                                 .reorder = opt->reorder, .window = opt->window, .ppc = d->ppc};
        d->sched = cosim_sched_new(&so, emit, d);
        if (!d->sched) { cosim_drv_free(d); return NULL; }
    }
    return d;
}

void cosim_drv_free(cosim_drv_t *d)
{
    if (!d) return;
    cosim_sched_free(d->sched);
    free(d->cand);
    free(d->hp_cycle);
    free(d);
}

const char *cosim_drv_error(const cosim_drv_t *d) { return d->err; }
uint64_t cosim_drv_ops_sent(const cosim_drv_t *d) { return d->ops; }

void cosim_drv_counters(cosim_drv_t *d, uint64_t cnt[COSIM_NCNT]) { cosim_rtl_counters(d->rtl, cnt); }

/* Photons at the head of the queue to offer in this cycle, their entries written by its end:
 * up to PhotonsPerCycle consecutive ones; scheduled, exactly the next group of the scheduler
 * (the photons its model took in one cycle), and only once the group is complete and written. */
static int offer_count(const cosim_drv_t *d)
{
    const uint64_t avail = d->pq_tail - d->pq_head;
    int k = 0;
    while (k < d->ppc && (uint64_t)k < avail) {
        const photon_entry_t *p = &d->pq[(d->pq_head + (uint64_t)k) & (PQ_CAP - 1)];
        if (d->sched && k > 0 && p->first) return k;
        if (p->widx_end > d->iq_head) return d->sched ? 0 : k;
        k++;
    }
    if (d->sched && k < d->ppc && !d->closed) return 0;   /* more of the group may follow */
    return k;
}

/* The k head photons are taken in this cycle: each of their hit points' operations issues about
 * (its place in the photon) / NumPreu cycles later. The entries are still in the index queue
 * (they lie within the index table's window, a quarter of the queue). For cosim_drv_hp_cycle. */
static void note_issue(cosim_drv_t *d, int k)
{
    if (!d->hp_cycle) return;
    const uint64_t c = cosim_rtl_cycle(d->rtl);
    for (int j = 0; j < k; j++) {
        const photon_entry_t *p = &d->pq[(d->pq_head + (uint64_t)j) & (PQ_CAP - 1)];
        for (uint32_t i = 0; i < p->n; i++) {
            const uint32_t hp = d->iq[(p->widx_end - p->n + i) & (IQ_CAP - 1)].hp;
            if (hp < d->n_hp) d->hp_cycle[hp] = c + i / (uint32_t)d->opt.preu;
        }
    }
}

/* The head group is taken in this cycle: against the scheduler's model, it should be taken
 * a constant number of cycles later (the first group's), or the model's counts are not the
 * RTL's (docs/cosim.md, "The scheduler": the load port's lead). */
static void note_lag(cosim_drv_t *d)
{
    const uint64_t c = cosim_rtl_cycle(d->rtl), m = d->pq[d->pq_head & (PQ_CAP - 1)].model_cycle;
    if (!d->have_offset) { d->offset = c - m; d->have_offset = 1; return; }
    if (c - m == d->offset) return;
    d->groups_late++;
    const uint64_t lag = c - m > d->offset ? c - m - d->offset : d->offset - (c - m);
    if (lag > d->max_lag) d->max_lag = lag;
}

uint64_t cosim_drv_hp_cycle(const cosim_drv_t *d, uint32_t i)
{
    return d->hp_cycle && i < d->n_hp ? d->hp_cycle[i] : UINT64_MAX;
}

void cosim_drv_radiance_cycles(const cosim_drv_t *d, uint64_t *from, uint64_t *to)
{
    *from = d->rad_from;
    *to = d->rad_to;
}

/* One clock cycle of the update stream: retire, write index entries, offer a photon. */
static void pump(cosim_drv_t *d)
{
    cosim_in_t *in = d->in;
    const int np = d->opt.preu;
    /* Retire the photons whose entries the PREE has read. */
    uint32_t done = cosim_rtl_photons_done(d->rtl);
    while (d->retired != done && d->aq_head != d->aq_tail) { d->aq_head++; d->retired++; }
    /* Up to NumPreu index entries in distinct banks (consecutive queue entries are). */
    uint32_t used = 0;
    int nw = 0;
    /* A stalled cycle writes fewer entries than the port takes (none to NumPreu - 1). */
    const int wmax = d->opt.stall > 0 && (double)next_rand(d) / 2147483648.0 < d->opt.stall
                   ? (int)(next_rand(d) % (uint64_t)np) : np;
    while (nw < wmax && d->iq_head != d->iq_tail) {
        const idx_entry_t *e = &d->iq[d->iq_head & (IQ_CAP - 1)];
        uint32_t b = 1u << (e->addr % (uint32_t)np);
        if (used & b) break;
        used |= b;
        in->idx_we[nw] = 1;
        in->idx_addr[nw] = e->addr;
        in->idx_data[nw] = e->hp;
        nw++;
        d->iq_head++;
    }
    for (int j = nw; j < np; j++) in->idx_we[j] = 0;
    /* The head photons once their entries are written (by the end of this cycle). */
    in->ph_valid = 0;
    int k = 0;
    if (d->pq_head != d->pq_tail) {
        int gap = d->opt.gap > 0 && (double)next_rand(d) / 2147483648.0 < d->opt.gap;
        /* Scheduled stream: the first photon waits until COSIM_LEAD_ENTRIES are written (or every
         * queued one), so that the load port (NumPreu entries a cycle, the RTL's rate at full
         * utilization) starts with a lead and the RTL then takes each group in the cycle the
         * scheduler's model took it (a constant offset). */
        int lead = !d->sched || d->started || d->iq_head == d->iq_tail ||
                   d->iq_head - d->lead_from >= COSIM_LEAD_ENTRIES(np);
        k = lead && !gap ? offer_count(d) : 0;
        for (int j = 0; j < d->ppc; j++) {
            const photon_entry_t *p = &d->pq[(d->pq_head + (uint64_t)j) & (PQ_CAP - 1)];
            in->ph_n[j] = j < k ? p->n : 0;
            if (j >= k) continue;
            memcpy(in->ph_pos[j], p->ph.pos, sizeof in->ph_pos[j]);
            memcpy(in->ph_phi[j], p->ph.phi, sizeof in->ph_phi[j]);
            in->ph_paddr[j] = p->paddr;
        }
        if (k) { d->started = 1; in->ph_valid = 1; }
    }
    /* ph_ready_o depends on the state only, so the value after the last edge holds now. */
    int take = in->ph_valid && d->ready;
    if (take) note_issue(d, k);
    if (take && d->sched) note_lag(d);
    cosim_rtl_tick(d->rtl);
    if (take) d->pq_head += (uint64_t)k;
    d->ready = cosim_rtl_ph_ready(d->rtl);
}

/* A wait (named by state) that has lasted the wait limit: the RTL is not making progress. Sets
 * the error, naming the wait and the stream's state (and d->hung, which every later call
 * reports), and returns 1. */
#define WAIT_LIMIT 10000000u
static int stuck(cosim_drv_t *d, uint64_t *guard, const char *state)
{
    if (d->hung) return 1;
    const uint64_t limit = d->opt.wait_limit ? d->opt.wait_limit : WAIT_LIMIT;
    if (++*guard < limit) return 0;
    snprintf(d->err, sizeof d->err, "the PREE made no progress for %llu cycles %s (ph_ready_o %d, idle_o %d; "
             "photons taken %llu of %llu queued, retired %u; index entries written %llu of %llu)",
             (unsigned long long)limit, state, cosim_rtl_ph_ready(d->rtl), cosim_rtl_idle(d->rtl),
             (unsigned long long)d->pq_head, (unsigned long long)d->pq_tail, d->retired,
             (unsigned long long)d->iq_head, (unsigned long long)d->iq_tail);
    d->hung = 1;
    return 1;
}

/* Place one photon (candidates in d->cand, in stream order) in the index table, queue its
 * entries and itself, and clock the model while the queues are long. Returns its p. */
static uint64_t send(cosim_drv_t *d, const preu_photon_t *ph, size_t n, int first, uint64_t model_cycle)
{
    const uint32_t np = (uint32_t)d->opt.preu;
    /* Place it: p = prev_p - n (mod NumPreu), at or after the end of the last photon. */
    uint64_t target = (d->prev_p + (uint64_t)np * MAX_CAND - n) % np;
    uint64_t p = d->alloc_end + (target + np - d->alloc_end % np) % np;
    if (d->opt.model_only) {           /* placed only: the scheduler's model reads it */
        d->alloc_end = p + n;
        d->prev_p = p;
        d->ops += n;
        return p;
    }
    /* Wait for index-table space: everything from the oldest unretired photon on is in use. */
    uint64_t guard = 0;
    for (;;) {
        uint64_t low = d->aq_head != d->aq_tail ? d->aq[d->aq_head & (AQ_CAP - 1)].start : p;
        if (p + n - low <= IDX_DEPTH && d->aq_tail - d->aq_head < AQ_CAP &&
            d->pq_tail - d->pq_head < PQ_CAP)
            break;
        if (stuck(d, &guard, "waiting for index-table space")) return p;
        pump(d);
    }
    d->aq[d->aq_tail++ & (AQ_CAP - 1)] = (alloc_entry_t){p, p + n};
    d->alloc_end = p + n;
    d->prev_p = p;
    /* The k-th operation AFTSO-HpUOC emits reads ref = p + n - 1 - k. */
    for (size_t k = 0; k < n; k++) {
        idx_entry_t *e = &d->iq[d->iq_tail++ & (IQ_CAP - 1)];
        e->addr = (uint32_t)((p + n - 1 - k) & (IDX_DEPTH - 1));
        e->hp = d->cand[k];
    }
    photon_entry_t *pe = &d->pq[d->pq_tail++ & (PQ_CAP - 1)];
    pe->ph = *ph;
    pe->paddr = (uint32_t)(p & (IDX_DEPTH - 1));
    pe->n = (uint32_t)n;
    pe->widx_end = d->iq_tail;
    pe->first = first;
    pe->model_cycle = model_cycle;
    d->ops += n;
    d->in->cnt_en = 1;
    guard = 0;
    while ((d->pq_tail - d->pq_head >= PQ_CAP / 2 || d->iq_tail - d->iq_head >= COSIM_LEAD_ENTRIES(np)) &&
           !stuck(d, &guard, "waiting for the PREE to take queued photons"))
        pump(d);
    return p;
}

/* The scheduler's way out: candidates already in their stream order. */
static int emit(void *user, const preu_photon_t *ph, const uint32_t *hps, uint32_t n, int first, uint64_t cycle,
                uint32_t *p)
{
    cosim_drv_t *d = user;
    memcpy(d->cand, hps, n * sizeof *hps);
    *p = (uint32_t)(send(d, ph, n, first, cycle) & (IDX_DEPTH - 1));
    return d->hung ? -1 : 0;
}

/* Without the scheduler: the photon's candidates reordered against bank conflicts, then sent. */
static int send_direct(void *user, const preu_photon_t *ph, const uint32_t *hps, size_t n)
{
    cosim_drv_t *d = user;
    cosim_reorder(&d->ro, d->cand, hps, n);
    send(d, ph, n, 1, 0);
    return d->hung ? -1 : 0;
}

int cosim_drv_photon(cosim_drv_t *d, const preu_photon_t *ph, const uint32_t *hps, size_t n)
{
    if (cosim_sched_offer(d->sched, d->hung, MAX_CAND, ph, hps, n, send_direct, d, d->err, sizeof d->err)) return -1;
    return d->hung ? -1 : 0;
}

int cosim_drv_sched_stats(const cosim_drv_t *d, cosim_sched_stats_t *st)
{
    if (!d->sched) return -1;
    cosim_sched_stats(d->sched, st);
    st->lag_known = !d->opt.model_only;
    st->groups_late = d->groups_late;
    st->max_lag = d->max_lag;
    return 0;
}

int cosim_drv_drain(cosim_drv_t *d)
{
    if (d->hung) return -1;
    if (d->sched && cosim_sched_flush(d->sched)) {
        if (!d->hung) snprintf(d->err, sizeof d->err, "photon scheduler: out of memory");
        return -1;
    }
    d->closed = 1;
    if (d->opt.model_only) return 0;
    /* Each wait is bounded by the cycles since its last progress (a photon taken). */
    uint64_t guard = 0, taken = d->pq_head;
    while (d->pq_head != d->pq_tail || d->iq_head != d->iq_tail) {
        pump(d);
        if (d->pq_head != taken) { taken = d->pq_head; guard = 0; }
        if (stuck(d, &guard, "draining the photon stream")) return -1;
    }
    d->in->ph_valid = 0;
    for (int j = 0; j < d->opt.preu; j++) d->in->idx_we[j] = 0;
    guard = 0;
    while (!cosim_rtl_idle(d->rtl)) {
        cosim_rtl_tick(d->rtl);
        if (stuck(d, &guard, "waiting for idle_o after the update stream")) return -1;
    }
    d->in->cnt_en = 0;
    cosim_rtl_tick(d->rtl);
    return 0;
}

int cosim_drv_barrier(cosim_drv_t *d)
{
    const int rc = cosim_drv_drain(d);
    d->closed = 0;        /* the scheduler's groups wait for their photons again */
    d->started = 0;       /* the next photon waits for the load port's lead, as the first did */
    d->lead_from = d->iq_head;
    d->have_offset = 0;   /* and sets the model's lag anew (the read-back lies between) */
    return rc;
}

void cosim_drv_load_hp(cosim_drv_t *d, const preu_hpw_t *hp, const int32_t *pixel, size_t n)
{
    cosim_in_t *in = d->in;
    free(d->hp_cycle);
    d->n_hp = n;
    d->hp_cycle = malloc((n ? n : 1) * sizeof *d->hp_cycle);   /* NULL: not tracked */
    if (d->hp_cycle) memset(d->hp_cycle, 0xff, (n ? n : 1) * sizeof *d->hp_cycle);
    for (size_t i = 0; i < n; i++) {
        while (d->opt.stall > 0 && (double)next_rand(d) / 2147483648.0 < d->opt.stall) {
            in->hp_we = 0;   /* an idle cycle in the load */
            cosim_rtl_tick(d->rtl);
        }
        in->hp_we = 1;
        in->hp_addr = (uint32_t)i;
        in->hp_wdata = hp[i];
        in->hp_pixel = (uint32_t)pixel[i];
        cosim_rtl_tick(d->rtl);
    }
    in->hp_we = 0;
    cosim_rtl_tick(d->rtl);
}

void cosim_drv_read_hp(cosim_drv_t *d, uint32_t i, preu_hpw_t *hp, uint32_t *pixel)
{
    d->in->hp_re = 1;
    d->in->hp_addr = i;
    cosim_rtl_tick(d->rtl);
    d->in->hp_re = 0;
    cosim_rtl_hp_rdata(d->rtl, hp, pixel);
}

int cosim_drv_radiance(cosim_drv_t *d, uint32_t n_hit, uint32_t ne, size_t npix, uint32_t *L)
{
    cosim_in_t *in = d->in;
    /* Clear the pixel sums to +0. */
    in->px_we = 1;
    memset(in->px_wdata, 0, sizeof in->px_wdata);
    for (size_t p = 0; p < npix; p++) {
        in->px_addr = (uint32_t)p;
        cosim_rtl_tick(d->rtl);
    }
    in->px_we = 0;
    /* Switch to radiance mode (idle), start the pass, wait for idle. */
    in->mode = 1;
    cosim_rtl_tick(d->rtl);
    in->ne = ne;
    in->n_hit = n_hit;
    in->rad_start = 1;
    in->cnt_en = 1;
    d->rad_from = cosim_rtl_cycle(d->rtl);
    cosim_rtl_tick(d->rtl);
    in->rad_start = 0;
    uint64_t guard = 0;
    while (!cosim_rtl_idle(d->rtl)) {
        if (stuck(d, &guard, "waiting for idle_o after the radiance pass")) return -1;
        cosim_rtl_tick(d->rtl);
    }
    d->rad_to = cosim_rtl_cycle(d->rtl);
    in->cnt_en = 0;
    /* Read the pixels back. */
    for (size_t p = 0; p < npix; p++) {
        in->px_re = 1;
        in->px_addr = (uint32_t)p;
        cosim_rtl_tick(d->rtl);
        cosim_rtl_px_rdata(d->rtl, L + 3 * p);
    }
    in->px_re = 0;
    in->mode = 0;
    cosim_rtl_tick(d->rtl);
    return 0;
}
