// SPDX-License-Identifier: Apache-2.0
/* pree_drv.c: the driver of pree_axi (pree_drv.h), over a back end. Register offsets and field
 * masks come from drv/pree_axi_regs.h, generated from the register map rtl/regs/pree_axi.rdl. */
#include "pree_drv.h"

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pree_axi_regs.h"

#define OFF(r) ((uint32_t)offsetof(pree_axi_regs_t, r))
#define BM(r, f) PREE_AXI_REGS__##r##__##f##_bm
#define GET(v, r, f) (((v) & BM(r, f)) >> PREE_AXI_REGS__##r##__##f##_bp)

enum { CMD_RAD = 1, CMD_HP_READ = 2, CMD_PX_CLEAR = 3, CMD_PX_READ = 4 };

/* Beats a command moves, photons and candidates a stream submission holds (the board back end's
 * DMA regions are sized for these: drv/pree_be_uio.c). */
#define READ_CHUNK   1024u
#define PH_CHUNK     512u
#define CAND_CHUNK   16384u

struct pree_drv {
    pree_backend_t be;
    pree_config_t cfg;
    unsigned timeout_ms;
    int cnt_work;        /* PREE_CNT_WORK: the driver switches CTRL.CNT_EN around the work */
    int counting;        /* CTRL.CNT_EN as last written */
    uint32_t *buf;       /* packing buffer */
    size_t cap;          /* its words */
    char err[256];
};

static int fail(pree_drv_t *d, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(d->err, sizeof d->err, fmt, ap);
    va_end(ap);
    return code;
}

static int io_fail(pree_drv_t *d, const char *what)
{
    return fail(d, PREE_E_IO, "%s: %s", what, d->be.error(d->be.ctx));
}

static int rd(pree_drv_t *d, uint32_t off, uint32_t *v)
{
    if (d->be.reg_read(d->be.ctx, off, v)) return fail(d, PREE_E_IO, "register read at 0x%03x: %s", off, d->be.error(d->be.ctx));
    return PREE_OK;
}

static int wr(pree_drv_t *d, uint32_t off, uint32_t v)
{
    if (d->be.reg_write(d->be.ctx, off, v)) return fail(d, PREE_E_IO, "register write at 0x%03x: %s", off, d->be.error(d->be.ctx));
    return PREE_OK;
}

/* The packing buffer with room for n words. */
static int room(pree_drv_t *d, size_t n)
{
    if (n <= d->cap) return PREE_OK;
    uint32_t *b = realloc(d->buf, n * sizeof *b);
    if (!b) return fail(d, PREE_E_NOMEM, "out of memory (%zu words)", n);
    d->buf = b;
    d->cap = n;
    return PREE_OK;
}

int pree_check_err(pree_drv_t *d)
{
    uint32_t e;
    int rc = rd(d, OFF(ERR), &e);
    if (rc || !e) return rc;
    if ((rc = wr(d, OFF(ERR), e))) return rc;
    return fail(d, PREE_E_HW, "ERR = 0x%x:%s%s", e,
                GET(e, ERR, CMD_REFUSED) ? " CMD_REFUSED (a command or constant while not idle, or an unknown command)" : "",
                GET(e, ERR, PH_TOO_BIG) ? " PH_TOO_BIG (a photon with too many candidates; the streams stall until reset)" : "");
}

/* Wait for the streams (and, with cause, for that interrupt, then clear it); ERR is checked. */
static int wait_for(pree_drv_t *d, uint32_t cause)
{
    for (;;) {
        const int r = d->be.wait(d->be.ctx, cause != 0, d->timeout_ms);
        if (r < 0) return io_fail(d, "wait");
        if (r == 0) {
            const int rc = pree_check_err(d);
            return rc ? rc : fail(d, PREE_E_TIMEOUT, "no %s in %u ms", cause ? "interrupt" : "stream progress", d->timeout_ms);
        }
        if (!cause) break;
        uint32_t st;
        int rc = rd(d, OFF(IRQ_STATUS), &st);
        if (!rc && st) rc = wr(d, OFF(IRQ_STATUS), st);   /* ours, and any stale cause */
        if (rc) return rc;
        if (st & cause) break;
    }
    return pree_check_err(d);
}

static int require_idle(pree_drv_t *d, const char *what)
{
    uint32_t st;
    const int rc = rd(d, OFF(STATUS), &st);
    if (rc) return rc;
    if (!GET(st, STATUS, IDLE)) return fail(d, PREE_E_BUSY, "%s: pree_axi is not idle (STATUS 0x%x)", what, st);
    return PREE_OK;
}

/* With PREE_CNT_WORK: the counters on or off (a CTRL write when that changes them). */
static int count_work(pree_drv_t *d, int on)
{
    if (!d->cnt_work || d->counting == on) return PREE_OK;
    d->counting = on;
    return wr(d, OFF(CTRL), on ? BM(CTRL, CNT_EN) : 0);
}

/* A command and the wait for its interrupt; counted: with PREE_CNT_WORK, the counters on from
 * the command's write until its interrupt is taken. */
static int command(pree_drv_t *d, uint32_t cmd, const char *what, int counted)
{
    int rc = require_idle(d, what);
    if (!rc && counted) rc = count_work(d, 1);
    if (!rc) rc = wr(d, OFF(CMD), cmd);
    if (!rc) rc = wait_for(d, BM(IRQ_STATUS, CMD));
    if (!rc && counted) rc = count_work(d, 0);
    return rc;
}

int pree_open(pree_drv_t **out, const pree_backend_t *be)
{
    *out = NULL;
    pree_drv_t *d = calloc(1, sizeof *d);
    if (!d) { be->close(be->ctx); return PREE_E_NOMEM; }
    d->be = *be;
    d->timeout_ms = 10000;
    *out = d;
    uint32_t v, c0, c1;
    int rc = rd(d, OFF(VERSION), &v);
    if (!rc && GET(v, VERSION, MAJOR) != 2)
        rc = fail(d, PREE_E_VERSION, "VERSION 0x%08x: not a pree_axi of major version 2 (256-bit photon slots)", v);
    if (!rc) rc = rd(d, OFF(CONFIG0), &c0);
    if (!rc) rc = rd(d, OFF(CONFIG1), &c1);
    if (rc) return rc;
    pree_config_t *c = &d->cfg;
    c->version = v;
    c->num_preu = GET(c0, CONFIG0, NUM_PREU);
    c->hp_aw = GET(c0, CONFIG0, HP_AW);
    c->px_aw = GET(c0, CONFIG0, PX_AW);
    c->idx_aw = GET(c0, CONFIG0, IDX_AW);
    c->datapath = GET(c0, CONFIG0, DATAPATH);
    c->hp_bank_w = GET(c1, CONFIG1, HP_BANK_W);
    c->px_bank_w = GET(c1, CONFIG1, PX_BANK_W);
    c->cnt_w = GET(c1, CONFIG1, CNT_W);
    c->photons_per_cycle = GET(c1, CONFIG1, PHOTONS_PER_CYCLE);
    c->state_words = c->datapath ? 10 : 5;
    c->hp_words = c->state_words + 7;
    c->max_cand = (1u << c->idx_aw) - c->num_preu;
    if (c->num_preu == 0 || c->num_preu > 32 || c->photons_per_cycle == 0 || c->idx_aw > 24)
        return fail(d, PREE_E_VERSION, "CONFIG0 0x%08x / CONFIG1 0x%08x: not a build this driver knows", c0, c1);
    /* Stale causes and errors of an earlier user go; both interrupts on (the driver waits on them). */
    if ((rc = wr(d, OFF(IRQ_STATUS), 0xffffffffu)) || (rc = wr(d, OFF(ERR), 0xffffffffu))) return rc;
    return pree_irq_enable(d, BM(IRQ_EN, BATCH) | BM(IRQ_EN, CMD));
}

void pree_close(pree_drv_t *d)
{
    if (!d) return;
    d->be.close(d->be.ctx);
    free(d->buf);
    free(d);
}

const char *pree_error(const pree_drv_t *d) { return d ? d->err : "out of memory"; }
const pree_config_t *pree_config(const pree_drv_t *d) { return &d->cfg; }
void pree_set_timeout(pree_drv_t *d, unsigned timeout_ms) { d->timeout_ms = timeout_ms; }
int pree_reg_read(pree_drv_t *d, uint32_t offset, uint32_t *value) { return rd(d, offset, value); }
int pree_reg_write(pree_drv_t *d, uint32_t offset, uint32_t value) { return wr(d, offset, value); }
int pree_irq_enable(pree_drv_t *d, uint32_t mask) { return wr(d, OFF(IRQ_EN), mask); }
int pree_counters_enable(pree_drv_t *d, int on)
{
    d->cnt_work = on == PREE_CNT_WORK;
    d->counting = on == 1;
    return wr(d, OFF(CTRL), d->counting ? BM(CTRL, CNT_EN) : 0);
}

int pree_set_constants(pree_drv_t *d, const pree_constants_t *c)
{
    int rc = require_idle(d, "constants");
    if (!rc) rc = wr(d, OFF(NE), c->ne);
    if (!rc) rc = wr(d, OFF(ALPHA), c->alpha);
    if (!rc) rc = wr(d, OFF(KAPPA), c->kappa);
    if (!rc) rc = wr(d, OFF(N_HIT), c->n_hit);
    return rc ? rc : pree_check_err(d);
}

int pree_load_hit_points(pree_drv_t *d, uint32_t first, const pree_hit_point_t *hp, size_t n)
{
    const unsigned sw = d->cfg.state_words, hw = d->cfg.hp_words;
    if ((uint64_t)first + n > (1ull << d->cfg.hp_aw))
        return fail(d, PREE_E_ARG, "hit points %u + %zu beyond the %u of HpAW %u", first, n, 1u << d->cfg.hp_aw, d->cfg.hp_aw);
    int rc = require_idle(d, "load hit points");
    if (!rc) rc = wr(d, OFF(HP_PTR), first);
    if (!rc) rc = room(d, (size_t)READ_CHUNK * hw);
    for (size_t i = 0; i < n && !rc; i += READ_CHUNK) {
        const size_t k = n - i < READ_CHUNK ? n - i : READ_CHUNK;
        for (size_t j = 0; j < k; j++) {
            uint32_t *w = d->buf + j * hw;
            const pree_hit_point_t *h = &hp[i + j];
            memcpy(w, h->state, sw * sizeof *w);
            memcpy(w + sw, h->pos, sizeof h->pos);
            memcpy(w + sw + 3, h->f, sizeof h->f);
            w[sw + 6] = h->pixel;
        }
        if (d->be.submit(d->be.ctx, PREE_STREAM_HP, d->buf, k * hw, hw, 0)) rc = io_fail(d, "s_axis_hp");
    }
    if (!rc) rc = wait_for(d, 0);
    uint32_t ptr;
    if (!rc) rc = rd(d, OFF(HP_PTR), &ptr);
    if (!rc && ptr != first + (uint32_t)n)
        rc = fail(d, PREE_E_STREAM, "HP_PTR reads %u after %zu hit points from %u", ptr, n, first);
    return rc;
}

size_t pree_pack_photons(const pree_config_t *cfg, const pree_photon_t *ph, size_t n, uint32_t *words)
{
    const size_t slots = cfg->photons_per_cycle, beat = slots * PREE_PH_SLOT_WORDS;
    const size_t beats = (n + slots - 1) / slots;
    memset(words, 0, beats * beat * sizeof *words);   /* empty slots: N^P = 0; reserved words 0 */
    for (size_t i = 0; i < n; i++) {
        uint32_t *w = words + (i / slots) * beat + (i % slots) * PREE_PH_SLOT_WORDS;
        memcpy(w, ph[i].pos, sizeof ph[i].pos);
        memcpy(w + 3, ph[i].phi, sizeof ph[i].phi);
        w[6] = ph[i].n_cand;
    }
    return beats * beat;
}

/* Photons [0, n) with their candidates cand[0, m) on the two streams; last: tlast. */
static int submit_photons(pree_drv_t *d, const pree_photon_t *ph, size_t n, const uint32_t *cand, size_t m, int last)
{
    const unsigned beat = d->cfg.photons_per_cycle * PREE_PH_SLOT_WORDS;
    int rc = room(d, ((n ? n : 1) + d->cfg.photons_per_cycle) * PREE_PH_SLOT_WORDS);
    if (rc) return rc;
    const pree_photon_t none = {{0}, {0}, 0};
    const size_t words = n ? pree_pack_photons(&d->cfg, ph, n, d->buf) : pree_pack_photons(&d->cfg, &none, 1, d->buf);
    if (d->be.submit(d->be.ctx, PREE_STREAM_PH, d->buf, words, beat, last)) return io_fail(d, "s_axis_ph");
    if (m && d->be.submit(d->be.ctx, PREE_STREAM_CAND, cand, m, d->cfg.num_preu, 0)) return io_fail(d, "s_axis_cand");
    return PREE_OK;
}

int pree_send_photons(pree_drv_t *d, const pree_photon_t *ph, const uint32_t *cand, size_t n)
{
    size_t total = 0;
    for (size_t i = 0; i < n; i++) {
        if (ph[i].n_cand > d->cfg.max_cand)
            return fail(d, PREE_E_ARG, "photon %zu: %u candidates, at most %u (2^IdxAW - NumPreu)", i, ph[i].n_cand, d->cfg.max_cand);
        for (uint32_t k = 0; k < ph[i].n_cand; k++)
            if (cand[total + k] >> d->cfg.hp_aw)
                return fail(d, PREE_E_ARG, "photon %zu: candidate %u beyond HpAW %u", i, cand[total + k], d->cfg.hp_aw);
        total += ph[i].n_cand;
    }
    /* Chunks, photons before their candidates: a back end may hold one submission a stream. */
    size_t i = 0, c = 0;
    if (n) {
        const int rc = count_work(d, 1);
        if (rc) return rc;
    }
    while (i < n) {
        size_t j = i, m = 0;
        while (j < n && j - i < PH_CHUNK && m + ph[j].n_cand <= CAND_CHUNK) m += ph[j++].n_cand;
        const int rc = submit_photons(d, ph + i, j - i, cand + c, m, 0);
        if (rc) return rc;
        i = j;
        c += m;
    }
    return PREE_OK;
}

/* A batch-done interrupt may be an earlier tlast's (a DMA ends every transfer with one): done
 * once STATUS shows no batch pending and all idle. */
int pree_end_batch(pree_drv_t *d)
{
    int rc = count_work(d, 1);
    if (!rc) rc = submit_photons(d, NULL, 0, NULL, 0, 1);
    while (!rc) {
        uint32_t st;
        rc = wait_for(d, BM(IRQ_STATUS, BATCH));
        if (!rc) rc = count_work(d, 0);
        if (!rc) rc = rd(d, OFF(STATUS), &st);
        if (!rc && !GET(st, STATUS, BATCH_PENDING) && GET(st, STATUS, IDLE)) break;
        if (!rc) rc = count_work(d, 1);   /* an earlier tlast's interrupt: the batch goes on */
    }
    return rc;
}

static int set_range(pree_drv_t *d, uint32_t base_off, uint32_t count_off, uint32_t first, uint32_t n)
{
    int rc = require_idle(d, "a command's range");
    if (!rc) rc = wr(d, base_off, first);
    if (!rc) rc = wr(d, count_off, n);
    return rc;
}

static int px_range(pree_drv_t *d, uint32_t first, size_t n)
{
    if ((uint64_t)first + n > (1ull << d->cfg.px_aw))
        return fail(d, PREE_E_ARG, "pixels %u + %zu beyond the %u of PxAW %u", first, n, 1u << d->cfg.px_aw, d->cfg.px_aw);
    return PREE_OK;
}

int pree_clear_pixels(pree_drv_t *d, uint32_t first, uint32_t n)
{
    int rc = px_range(d, first, n);
    if (!rc) rc = set_range(d, OFF(PX_BASE), OFF(PX_COUNT), first, n);
    return rc ? rc : command(d, CMD_PX_CLEAR, "clear pixels", 0);
}

int pree_radiance(pree_drv_t *d, uint32_t n_hit, uint32_t ne, uint32_t first, uint32_t npix)
{
    if ((uint64_t)n_hit > (1ull << d->cfg.hp_aw)) return fail(d, PREE_E_ARG, "N_HIT %u beyond HpAW %u", n_hit, d->cfg.hp_aw);
    int rc = pree_clear_pixels(d, first, npix);
    if (!rc) rc = wr(d, OFF(NE), ne);
    if (!rc) rc = wr(d, OFF(N_HIT), n_hit);
    if (!rc) rc = pree_check_err(d);
    return rc ? rc : command(d, CMD_RAD, "radiance pass", 1);
}

/* A read command of n beats from first into the packing buffer. */
static int read_cmd(pree_drv_t *d, uint32_t cmd, uint32_t base_off, uint32_t count_off, uint32_t first, size_t n)
{
    const unsigned hw = d->cfg.hp_words;
    int rc = room(d, n * hw);
    if (!rc) rc = set_range(d, base_off, count_off, first, (uint32_t)n);
    if (!rc && d->be.receive(d->be.ctx, d->buf, n, hw, cmd == CMD_PX_READ)) rc = io_fail(d, "m_axis");
    return rc ? rc : command(d, cmd, cmd == CMD_PX_READ ? "read pixels" : "read hit points", 0);
}

int pree_read_hit_points(pree_drv_t *d, uint32_t first, pree_hit_point_t *hp, size_t n)
{
    const unsigned sw = d->cfg.state_words, hw = d->cfg.hp_words;
    if ((uint64_t)first + n > (1ull << d->cfg.hp_aw))
        return fail(d, PREE_E_ARG, "hit points %u + %zu beyond HpAW %u", first, n, d->cfg.hp_aw);
    for (size_t i = 0; i < n; i += READ_CHUNK) {
        const size_t k = n - i < READ_CHUNK ? n - i : READ_CHUNK;
        const int rc = read_cmd(d, CMD_HP_READ, OFF(HP_PTR), OFF(HP_COUNT), first + (uint32_t)i, k);
        if (rc) return rc;
        for (size_t j = 0; j < k; j++) {
            const uint32_t *w = d->buf + j * hw;
            pree_hit_point_t *h = &hp[i + j];
            memset(h->state, 0, sizeof h->state);
            memcpy(h->state, w, sw * sizeof *w);
            memcpy(h->pos, w + sw, sizeof h->pos);
            memcpy(h->f, w + sw + 3, sizeof h->f);
            h->pixel = w[sw + 6];
        }
    }
    return PREE_OK;
}

int pree_read_pixels(pree_drv_t *d, uint32_t first, uint32_t *rgb, size_t n)
{
    int rc = px_range(d, first, n);
    for (size_t i = 0; i < n && !rc; i += READ_CHUNK) {
        const size_t k = n - i < READ_CHUNK ? n - i : READ_CHUNK;
        rc = read_cmd(d, CMD_PX_READ, OFF(PX_BASE), OFF(PX_COUNT), first + (uint32_t)i, k);
        for (size_t j = 0; j < k && !rc; j++) memcpy(rgb + 3 * (i + j), d->buf + j * d->cfg.hp_words, 3 * sizeof *rgb);
    }
    return rc;
}

int pree_read_counters(pree_drv_t *d, uint64_t *cnt, size_t n)
{
    const size_t ncnt = 7 + d->cfg.num_preu;
    if (n < ncnt) return fail(d, PREE_E_ARG, "room for %zu counters, the build has %zu", n, ncnt);
    for (size_t k = 0; k < ncnt; k++) {
        uint32_t lo, hi;   /* LO first: reading it latches HI */
        const uint32_t at = OFF(CNT) + (uint32_t)(k * sizeof(pree_axi_regs__CNTx_t));
        int rc = rd(d, at + (uint32_t)offsetof(pree_axi_regs__CNTx_t, LO), &lo);
        if (!rc) rc = rd(d, at + (uint32_t)offsetof(pree_axi_regs__CNTx_t, HI), &hi);
        if (rc) return rc;
        cnt[k] = (uint64_t)(hi & BM(CNTX__HI, VALUE)) << 32 | lo;
    }
    return PREE_OK;
}

int pree_read_stream_counts(pree_drv_t *d, uint32_t *ph_in, uint32_t *ph_done, uint32_t *cand_in)
{
    int rc = rd(d, OFF(PH_IN), ph_in);
    if (!rc) rc = rd(d, OFF(PH_DONE), ph_done);
    if (!rc) rc = rd(d, OFF(CAND_IN), cand_in);
    return rc;
}
