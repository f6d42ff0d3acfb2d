// SPDX-License-Identifier: Apache-2.0
/* pree_be_verilated.c: pree_drv's back end on the Verilated pree_axi (host/cosim_axi_rtl.h, the
 * model objects of build/pree-cosim-axi-<d><n>): register reads and writes are AXI4-Lite
 * transactions, submitted beats wait in queues that are offered on the streams while the clock
 * runs (during every transaction and every wait), m_axis beats go to the armed buffer. With a gap
 * probability every offer is held back and every ready dropped at random, and candidate beats
 * carry a random number of candidates in random lanes (as `pree cosim --axi --gap`). With a
 * lead of L candidates, the photon stream starts (at the first beat and after each tlast) once
 * the candidate stream has moved L candidates since the photon stream stopped, or has none
 * waiting: the candidates stay ahead of the photons that need them. `pree cosim --axi` runs
 * pree_drv through this back end on its own model (pree_be_verilated_attach). */
#include "pree_be_verilated.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cosim_axi_rtl.h"
#include "pree_wqueue.h"

#define CYCLES_PER_MS 100000u   /* a 100 MHz aclk */
#define LITE_LIMIT    100000u   /* cycles an AXI4-Lite transaction may take */

typedef struct {
    cosim_rtl_t *rtl;
    cosim_axi_in_t *in;
    int preu, state_words, ppc;   /* ppc: photon slots a beat */
    double gap;
    uint64_t rng, cycles;
    int own_rtl;              /* close frees the model */
    pree_wq_t q[3];           /* PREE_STREAM_HP, _PH, _CAND */
    uint32_t lead;            /* candidates the photon stream waits for (0: none) */
    int flowing;              /* a photon beat offered since the stream (re)started */
    uint64_t cand_taken, lead_from;   /* candidates taken; the lead counts from lead_from */
    uint64_t *ph_last;        /* photon beat numbers with tlast, ascending */
    size_t nlast, last_head, last_cap;
    uint64_t ph_beats;        /* photon beats taken so far (the number of the queue's head) */
    uint32_t cand_take;       /* candidates in the beat on offer */
    uint32_t *rx;             /* the armed m_axis buffer */
    size_t rx_n, rx_got;
    unsigned rx_words;
    int rx_user, irq, broken;
    char err[256];
} vl_t;

static uint64_t next_rand(vl_t *v)
{
    v->rng = v->rng * 6364136223846793005ull + 1442695040888963407ull;
    return v->rng >> 33;
}

static int gap(vl_t *v) { return v->gap > 0 && (double)next_rand(v) / 2147483648.0 < v->gap; }

static int fail(vl_t *v, const char *msg)
{
    if (!v->broken) snprintf(v->err, sizeof v->err, "%s", msg);
    v->broken = 1;
    return -1;
}

static int push(vl_t *v, pree_wq_t *q, const uint32_t *w, size_t n)
{
    return pree_wq_push(q, w, n) ? fail(v, "out of memory") : 0;
}

/* One m_axis beat into the armed buffer, as the words of the stream's beat. */
static void receive(vl_t *v, const cosim_axi_out_t *o)
{
    if (v->rx_got >= v->rx_n || o->m_user != v->rx_user || o->m_last != (v->rx_got + 1 == v->rx_n)) {
        fail(v, "m_axis: a beat out of place (tuser, tlast or count)");
        return;
    }
    uint32_t *w = v->rx + v->rx_got * v->rx_words;
    const int s = v->state_words;
    memset(w, 0, v->rx_words * sizeof *w);
    if (o->m_user) {
        memcpy(w, o->m_px, sizeof o->m_px);
    } else {
        memcpy(w, o->m_hp.st, (size_t)s * sizeof *w);
        memcpy(w + s, o->m_hp.pos, sizeof o->m_hp.pos);
        memcpy(w + s + 3, o->m_hp.f, sizeof o->m_hp.f);
        w[s + 6] = o->m_pixel;
    }
    v->rx_got++;
}

/* 1 when the photon stream may offer a beat: it flows, or the candidates have their lead. */
static int led(vl_t *v)
{
    if (v->flowing || !v->lead) return 1;
    if (!pree_wq_avail(&v->q[PREE_STREAM_PH])) v->lead_from = v->cand_taken;   /* stopped: the lead counts from here */
    return !pree_wq_avail(&v->q[PREE_STREAM_CAND]) || v->cand_taken - v->lead_from >= v->lead;
}

static void offer(vl_t *v)
{
    cosim_axi_in_t *in = v->in;
    pree_wq_t *q = &v->q[PREE_STREAM_PH];
    if (!in->ph_valid && led(v) && pree_wq_avail(q) && !gap(v)) {
        for (int s = 0; s < v->ppc; s++) {
            const uint32_t *w = q->w + q->head + (size_t)s * PREE_PH_SLOT_WORDS;
            memcpy(in->ph[s].pos, w, sizeof in->ph[s].pos);
            memcpy(in->ph[s].phi, w + 3, sizeof in->ph[s].phi);
            in->ph_n[s] = w[6];
        }
        in->ph_last = v->last_head < v->nlast && v->ph_last[v->last_head] == v->ph_beats;
        in->ph_valid = 1;
        v->flowing = 1;
    }
    q = &v->q[PREE_STREAM_HP];
    if (!in->hp_valid && pree_wq_avail(q) && !gap(v)) {
        const uint32_t *w = q->w + q->head;
        const int s = v->state_words;
        memset(&in->hp, 0, sizeof in->hp);
        memcpy(in->hp.st, w, (size_t)s * sizeof *w);
        memcpy(in->hp.pos, w + s, sizeof in->hp.pos);
        memcpy(in->hp.f, w + s + 3, sizeof in->hp.f);
        in->hp_pixel = w[s + 6];
        in->hp_valid = 1;
    }
    q = &v->q[PREE_STREAM_CAND];
    const uint32_t np = (uint32_t)v->preu, n = (uint32_t)(pree_wq_avail(q) < np ? pree_wq_avail(q) : np);
    if (!in->cand_valid && n && !gap(v)) {
        const uint32_t k = v->gap > 0 ? 1 + (uint32_t)(next_rand(v) % n) : n;
        uint32_t keep = 0, placed = 0;
        for (uint32_t j = 0; j < np && placed < k; j++) {
            /* A lane stays empty at random while enough lanes remain for the rest. */
            if (v->gap > 0 && np - j > k - placed && next_rand(v) % 4 == 0) continue;
            keep |= 1u << j;
            in->cand[j] = q->w[q->head + placed++];
        }
        in->cand_keep = keep;
        in->cand_valid = 1;
        v->cand_take = k;
    }
}

/* One clock cycle: offers, readiness, the edge, and the bookkeeping of what moved. */
static const cosim_axi_out_t *cycle(vl_t *v)
{
    cosim_axi_in_t *in = v->in;
    offer(v);
    in->m_ready = v->rx_got < v->rx_n && !gap(v);
    const cosim_axi_out_t *o = cosim_axi_tick(v->rtl);
    v->cycles++;
    if (o->fired & AXI_PH) {
        in->ph_valid = 0;
        v->q[PREE_STREAM_PH].head += (size_t)v->ppc * PREE_PH_SLOT_WORDS;
        if (in->ph_last) { v->last_head++; v->flowing = 0; }
        v->ph_beats++;
    }
    if (o->fired & AXI_HP) { in->hp_valid = 0; v->q[PREE_STREAM_HP].head += (size_t)v->state_words + 7; }
    if (o->fired & AXI_CAND) {
        in->cand_valid = 0;
        v->q[PREE_STREAM_CAND].head += v->cand_take;
        v->cand_taken += v->cand_take;
    }
    if (o->fired & AXI_M) receive(v, o);
    v->irq = o->irq;
    return o;
}

static int reg_write(void *ctx, uint32_t addr, uint32_t val)
{
    vl_t *v = ctx;
    cosim_axi_in_t *in = v->in;
    int aw = 0, w = 0;
    in->awaddr = addr;
    in->wdata = val;
    for (uint32_t guard = 0; !v->broken; guard++) {
        if (!aw && !in->awvalid) in->awvalid = !gap(v);
        if (!w && !in->wvalid) in->wvalid = !gap(v);
        in->bready = aw && w && !gap(v);
        const cosim_axi_out_t *o = cycle(v);
        if (o->fired & AXI_AW) { in->awvalid = 0; aw = 1; }
        if (o->fired & AXI_W) { in->wvalid = 0; w = 1; }
        if (o->fired & AXI_B) { in->bready = 0; return 0; }
        if (guard > LITE_LIMIT) return fail(v, "AXI4-Lite write: no response");
    }
    return -1;
}

static int reg_read(void *ctx, uint32_t addr, uint32_t *val)
{
    vl_t *v = ctx;
    cosim_axi_in_t *in = v->in;
    int ar = 0;
    in->araddr = addr;
    for (uint32_t guard = 0; !v->broken; guard++) {
        if (!ar && !in->arvalid) in->arvalid = !gap(v);
        in->rready = ar && !gap(v);
        const cosim_axi_out_t *o = cycle(v);
        if (o->fired & AXI_AR) { in->arvalid = 0; ar = 1; }
        if (o->fired & AXI_R) { in->rready = 0; *val = o->rdata; return 0; }
        if (guard > LITE_LIMIT) return fail(v, "AXI4-Lite read: no response");
    }
    return -1;
}

static int submit(void *ctx, int stream, const uint32_t *words, size_t n, unsigned beat_words, int last)
{
    vl_t *v = ctx;
    if (v->broken) return -1;
    const unsigned want = stream == PREE_STREAM_HP ? (unsigned)v->state_words + 7
                        : stream == PREE_STREAM_PH ? (unsigned)v->ppc * PREE_PH_SLOT_WORDS : (unsigned)v->preu;
    if (stream < 0 || stream > 2 || beat_words != want || (stream != PREE_STREAM_CAND && n % want)) {
        snprintf(v->err, sizeof v->err, "stream %d: beats of %u words, this pree_axi takes %u", stream, beat_words, want);
        return -1;
    }
    if (stream == PREE_STREAM_PH && last && n) {   /* tlast on this submission's final beat */
        if (v->nlast == v->last_cap) {
            const size_t cap = v->last_cap ? 2 * v->last_cap : 16;
            uint64_t *nl = realloc(v->ph_last, cap * sizeof *nl);
            if (!nl) return fail(v, "out of memory");
            v->ph_last = nl;
            v->last_cap = cap;
        }
        v->ph_last[v->nlast++] = v->ph_beats + (pree_wq_avail(&v->q[PREE_STREAM_PH]) + n) / want - 1;
    }
    return push(v, &v->q[stream], words, n);
}

static int receive_arm(void *ctx, uint32_t *words, size_t nbeats, unsigned beat_words, int user)
{
    vl_t *v = ctx;
    if (v->rx_got < v->rx_n) { snprintf(v->err, sizeof v->err, "m_axis: a receive is still armed"); return -1; }
    if (beat_words != (unsigned)v->state_words + 7) {
        snprintf(v->err, sizeof v->err, "m_axis: beats of %u words, this pree_axi sends %d", beat_words, v->state_words + 7);
        return -1;
    }
    v->rx = words;
    v->rx_n = nbeats;
    v->rx_got = 0;
    v->rx_words = beat_words;
    v->rx_user = user;
    return v->broken ? -1 : 0;
}

static int drained(const vl_t *v)
{
    return !pree_wq_avail(&v->q[0]) && !pree_wq_avail(&v->q[1]) && !pree_wq_avail(&v->q[2]) && v->rx_got == v->rx_n;
}

static int wait_for(void *ctx, int irq, unsigned timeout_ms)
{
    vl_t *v = ctx;
    const uint64_t limit = v->cycles + (uint64_t)timeout_ms * CYCLES_PER_MS;
    while (!v->broken) {
        if (drained(v) && (!irq || v->irq)) return 1;
        if (v->cycles >= limit) return 0;
        cycle(v);
    }
    return -1;
}

static const char *error(void *ctx) { return ((vl_t *)ctx)->err; }

static void close_be(void *ctx)
{
    vl_t *v = ctx;
    if (v->own_rtl) cosim_rtl_free(v->rtl);
    for (int s = 0; s < 3; s++) pree_wq_free(&v->q[s]);
    free(v->ph_last);
    free(v);
}

int pree_be_verilated_attach(pree_backend_t *be, cosim_rtl_t *rtl, int preu, int datapath, double gap_p,
                             uint64_t seed, uint32_t lead)
{
    vl_t *v = calloc(1, sizeof *v);
    if (!v) return -1;
    v->rtl = rtl;
    v->in = cosim_axi_in(rtl);
    v->preu = preu;
    v->state_words = datapath ? 10 : 5;
    v->ppc = cosim_rtl_ppc(rtl);
    v->gap = gap_p;
    v->rng = seed * 2862933555777941757ull + 3037000493ull;
    v->lead = lead;
    *be = (pree_backend_t){.ctx = v, .reg_read = reg_read, .reg_write = reg_write, .submit = submit,
                           .receive = receive_arm, .wait = wait_for, .error = error, .close = close_be};
    return 0;
}

int pree_be_verilated_open(pree_backend_t *be, int preu, int datapath, double gap_p, uint64_t seed,
                           const char *fst, char *err, size_t errlen)
{
    cosim_rtl_t *rtl = cosim_rtl_new(preu, datapath, 0, fst, err, errlen);
    if (!rtl) return -1;
    if (pree_be_verilated_attach(be, rtl, preu, datapath, gap_p, seed, 0)) {
        cosim_rtl_free(rtl);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    ((vl_t *)be->ctx)->own_rtl = 1;
    return 0;
}

uint64_t pree_be_verilated_cycles(const pree_backend_t *be) { return ((const vl_t *)be->ctx)->cycles; }
