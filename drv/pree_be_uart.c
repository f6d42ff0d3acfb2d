// SPDX-License-Identifier: Apache-2.0
/* pree_be_uart.c: pree_drv's back end over the UART bridge's byte protocol (see pree_be_uart.h and
 * rtl/board/pree_uart_bridge.v). Beats are sent most significant byte first: word i of a beat is
 * bits [32 i +: 32] of the stream's TDATA. */
#include "pree_be_uart.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pree_axi_regs.h"
#include "pree_wqueue.h"

#define OFF(r)      ((uint32_t)offsetof(pree_axi_regs_t, r))
#define GET(v, r, f) (((v) & PREE_AXI_REGS__##r##__##f##_bm) >> PREE_AXI_REGS__##r##__##f##_bp)
#define REPLY_MS    2000u   /* the channel's time a reply may take after its command */
#define MAX_BYTES   160u    /* the longest command or beat: 1 + 128 (a beat of 4 photon slots) */

typedef struct {
    pree_uart_chan_t ch;
    unsigned preu, hp_words, ph_words, cand_bytes;
    uint32_t irq_en;          /* the IRQ_EN last written */
    pree_wq_t q[3];           /* submitted: PREE_STREAM_HP, _PH (a beat, then its tlast), _CAND */
    pree_wq_t pend;           /* m_axis beats received before a receive() took them: flags, words */
    uint32_t *rx;             /* the armed m_axis buffer */
    size_t rx_n, rx_got;
    int rx_user, broken;
    char err[256];
} ub_t;

static int fail(ub_t *u, const char *msg)
{
    if (!u->broken) snprintf(u->err, sizeof u->err, "%s", msg);
    u->broken = 1;
    return -1;
}

static int push(ub_t *u, pree_wq_t *q, const uint32_t *w, size_t n)
{
    return pree_wq_push(q, w, n) ? fail(u, "out of memory") : 0;
}

/* nwords words as bytes, most significant first. */
static void to_bytes(const uint32_t *w, unsigned nwords, uint8_t *b)
{
    for (unsigned j = 0; j < 4 * nwords; j++) b[j] = (uint8_t)(w[nwords - 1 - j / 4] >> (8 * (3 - j % 4)));
}

static void from_bytes(const uint8_t *b, unsigned nwords, uint32_t *w)
{
    memset(w, 0, nwords * sizeof *w);
    for (unsigned j = 0; j < 4 * nwords; j++) w[nwords - 1 - j / 4] |= (uint32_t)b[j] << (8 * (3 - j % 4));
}

static int recv_all(ub_t *u, uint8_t *b, size_t n, uint64_t deadline)
{
    const long got = u->ch.recv(u->ch.ctx, b, n, deadline);
    if (got < 0) return fail(u, u->ch.error(u->ch.ctx));
    if ((size_t)got < n) return fail(u, "the bridge did not answer in time");
    return 0;
}

/* One m_axis beat (its flags byte read): into the armed buffer, or kept until one is armed. */
static int beat(ub_t *u, uint8_t flags, uint64_t deadline)
{
    uint8_t b[MAX_BYTES];
    uint32_t w[MAX_BYTES / 4 + 1];
    if (recv_all(u, b, 4 * u->hp_words, deadline)) return -1;
    w[0] = flags;
    from_bytes(b, u->hp_words, w + 1);
    if (u->rx_got >= u->rx_n) return push(u, &u->pend, w, u->hp_words + 1);
    const int user = flags & 1, last = (flags >> 1) & 1;
    if (user != u->rx_user || last != (u->rx_got + 1 == u->rx_n))
        return fail(u, "m_axis: a beat out of place (tuser, tlast or count)");
    memcpy(u->rx + u->rx_got * u->hp_words, w + 1, u->hp_words * sizeof *w);
    u->rx_got++;
    return 0;
}

/* The next byte that is not part of an m_axis beat (those go to beat()). */
static int reply_byte(ub_t *u, uint8_t *c, uint64_t deadline)
{
    for (;;) {
        if (recv_all(u, c, 1, deadline)) return -1;
        if ((*c & 0xfc) != 0x80) return 0;
        if (beat(u, *c, deadline)) return -1;
    }
}

/* A command and its reply (first byte in reply[0], then rn - 1 more). */
static int command(ub_t *u, const uint8_t *cmd, size_t n, uint8_t *reply, size_t rn)
{
    if (u->broken) return -1;
    if (u->ch.send(u->ch.ctx, cmd, n)) return fail(u, u->ch.error(u->ch.ctx));
    const uint64_t deadline = u->ch.now_ms(u->ch.ctx) + REPLY_MS;
    if (reply_byte(u, reply, deadline)) return -1;
    return rn > 1 ? recv_all(u, reply + 1, rn - 1, deadline) : 0;
}

static int unexpected(ub_t *u, const char *what, uint8_t c)
{
    char msg[96];
    snprintf(msg, sizeof msg, "%s: reply 0x%02x from the bridge (lost framing?)", what, c);
    return fail(u, msg);
}

static int reg_write(void *ctx, uint32_t off, uint32_t val)
{
    ub_t *u = ctx;
    const uint8_t cmd[7] = {'W', (uint8_t)(off >> 8), (uint8_t)off, (uint8_t)(val >> 24), (uint8_t)(val >> 16),
                            (uint8_t)(val >> 8), (uint8_t)val};
    uint8_t r;
    if (command(u, cmd, sizeof cmd, &r, 1)) return -1;
    if (r == 'e') return fail(u, "AXI4-Lite write: error response");
    if (r != 'b') return unexpected(u, "AXI4-Lite write", r);
    if (off == OFF(IRQ_EN)) u->irq_en = val;
    return 0;
}

static int reg_read(void *ctx, uint32_t off, uint32_t *val)
{
    ub_t *u = ctx;
    const uint8_t cmd[3] = {'R', (uint8_t)(off >> 8), (uint8_t)off};
    uint8_t r[5];
    if (command(u, cmd, sizeof cmd, r, 5)) return -1;
    if (r[0] == 'e') return fail(u, "AXI4-Lite read: error response");
    if (r[0] != 'r') return unexpected(u, "AXI4-Lite read", r[0]);
    *val = (uint32_t)r[1] << 24 | (uint32_t)r[2] << 16 | (uint32_t)r[3] << 8 | r[4];
    return 0;
}

/* A stream command: op and nbytes of payload; the bridge answers 'a' once the stream took it. */
static int stream_cmd(ub_t *u, uint8_t op, const uint8_t *pay, size_t nbytes)
{
    uint8_t cmd[MAX_BYTES], r;
    cmd[0] = op;
    memcpy(cmd + 1, pay, nbytes);
    if (command(u, cmd, nbytes + 1, &r, 1)) return -1;
    return r == 'a' ? 0 : unexpected(u, "stream beat", r);
}

/* k candidates as one beat of s_axis_cand: {tkeep, tdata} right-aligned in cand_bytes bytes. */
static int send_cand(ub_t *u, const uint32_t *c, unsigned k)
{
    uint8_t le[MAX_BYTES] = {0}, be[MAX_BYTES];
    for (unsigned j = 0; j < k; j++) {
        for (unsigned i = 0; i < 4; i++) le[4 * j + i] = (uint8_t)(c[j] >> (8 * i));
        const unsigned bit = 32 * u->preu + 4 * j;    /* lane j's four keep bits */
        le[bit / 8] |= (uint8_t)(0xf << (bit % 8));
    }
    for (unsigned i = 0; i < u->cand_bytes; i++) be[i] = le[u->cand_bytes - 1 - i];
    return stream_cmd(u, 'C', be, u->cand_bytes);
}

/* Everything that may go: hit points; each photon beat once its candidates are queued (they go
 * first). */
static int pump(ub_t *u)
{
    uint8_t b[MAX_BYTES];
    pree_wq_t *hp = &u->q[PREE_STREAM_HP], *ph = &u->q[PREE_STREAM_PH], *cq = &u->q[PREE_STREAM_CAND];
    while (!u->broken && pree_wq_avail(hp)) {
        to_bytes(hp->w + hp->head, u->hp_words, b);
        if (stream_cmd(u, 'H', b, 4 * u->hp_words)) return -1;
        hp->head += u->hp_words;
    }
    while (!u->broken && pree_wq_avail(ph)) {
        const uint32_t *w = ph->w + ph->head;
        size_t need = 0;
        for (unsigned s = 0; s < u->ph_words / PREE_PH_SLOT_WORDS; s++) need += w[s * PREE_PH_SLOT_WORDS + 6];
        if (pree_wq_avail(cq) < need) break;
        for (size_t k = 0; k < need; k += u->preu) {
            const unsigned m = need - k < u->preu ? (unsigned)(need - k) : u->preu;
            if (send_cand(u, cq->w + cq->head, m)) return -1;
            cq->head += m;
        }
        to_bytes(w, u->ph_words, b);
        if (stream_cmd(u, w[u->ph_words] ? 'L' : 'P', b, 4 * u->ph_words)) return -1;
        ph->head += u->ph_words + 1;
    }
    return u->broken ? -1 : 0;
}

static int submit(void *ctx, int stream, const uint32_t *words, size_t n, unsigned beat_words, int last)
{
    ub_t *u = ctx;
    if (u->broken) return -1;
    const unsigned want = stream == PREE_STREAM_HP ? u->hp_words : stream == PREE_STREAM_PH ? u->ph_words : u->preu;
    if (stream < 0 || stream > 2 || beat_words != want || (stream != PREE_STREAM_CAND && n % want)) {
        snprintf(u->err, sizeof u->err, "stream %d: beats of %u words, this pree_axi takes %u", stream, beat_words, want);
        return -1;
    }
    if (stream == PREE_STREAM_PH) {   /* each beat followed by its tlast */
        for (size_t i = 0; i < n; i += want) {
            const uint32_t l = last && i + want == n;
            if (push(u, &u->q[stream], words + i, want) || push(u, &u->q[stream], &l, 1)) return -1;
        }
    } else if (push(u, &u->q[stream], words, n)) {
        return -1;
    }
    return pump(u);
}

static int receive_arm(void *ctx, uint32_t *words, size_t nbeats, unsigned beat_words, int user)
{
    ub_t *u = ctx;
    if (u->rx_got < u->rx_n) { snprintf(u->err, sizeof u->err, "m_axis: a receive is still armed"); return -1; }
    if (beat_words != u->hp_words) {
        snprintf(u->err, sizeof u->err, "m_axis: beats of %u words, this pree_axi sends %u", beat_words, u->hp_words);
        return -1;
    }
    u->rx = words;
    u->rx_n = nbeats;
    u->rx_got = 0;
    u->rx_user = user;
    while (!u->broken && pree_wq_avail(&u->pend) && u->rx_got < u->rx_n) {   /* beats that came first */
        uint32_t w[MAX_BYTES / 4 + 1];
        memcpy(w, u->pend.w + u->pend.head, (u->hp_words + 1) * sizeof *w);
        u->pend.head += u->hp_words + 1;
        const int user_b = w[0] & 1, last = (w[0] >> 1) & 1;
        if (user_b != u->rx_user || last != (u->rx_got + 1 == u->rx_n))
            return fail(u, "m_axis: a beat out of place (tuser, tlast or count)");
        memcpy(u->rx + u->rx_got++ * u->hp_words, w + 1, u->hp_words * sizeof *w);
    }
    return u->broken ? -1 : 0;
}

static int wait_for(void *ctx, int irq, unsigned timeout_ms)
{
    ub_t *u = ctx;
    const uint64_t deadline = u->ch.now_ms(u->ch.ctx) + timeout_ms;
    if (pump(u)) return -1;
    if (pree_wq_avail(&u->q[PREE_STREAM_PH])) return fail(u, "photon beats wait for candidates that were never submitted");
    while (u->rx_got < u->rx_n) {
        uint8_t c;
        const long got = u->ch.recv(u->ch.ctx, &c, 1, deadline);
        if (got < 0) return fail(u, u->ch.error(u->ch.ctx));
        if (got == 0) return 0;
        if ((c & 0xfc) != 0x80) return unexpected(u, "m_axis", c);
        if (beat(u, c, deadline)) return -1;
    }
    while (irq) {   /* no interrupt line: IRQ_STATUS polled */
        uint32_t st;
        if (reg_read(u, OFF(IRQ_STATUS), &st)) return -1;
        if (st & u->irq_en) break;
        if (u->ch.now_ms(u->ch.ctx) >= deadline) return 0;
    }
    return 1;
}

static const char *error(void *ctx) { return ((ub_t *)ctx)->err; }

static void close_be(void *ctx)
{
    ub_t *u = ctx;
    u->ch.close(u->ch.ctx);
    for (int s = 0; s < 3; s++) pree_wq_free(&u->q[s]);
    pree_wq_free(&u->pend);
    free(u);
}

int pree_be_uart_open(pree_backend_t *be, const pree_uart_chan_t *chan, char *err, size_t errlen)
{
    ub_t *u = calloc(1, sizeof *u);
    if (!u) { chan->close(chan->ctx); snprintf(err, errlen, "out of memory"); return -1; }
    u->ch = *chan;
    uint8_t junk[64];   /* what an earlier user left in the channel */
    while (u->ch.recv(u->ch.ctx, junk, sizeof junk, u->ch.now_ms(u->ch.ctx)) > 0) {}
    uint32_t c0, c1;
    if (reg_read(u, OFF(CONFIG0), &c0) || reg_read(u, OFF(CONFIG1), &c1)) {
        snprintf(err, errlen, "UART bridge: %s", u->err);
        close_be(u);
        return -1;
    }
    u->preu = GET(c0, CONFIG0, NUM_PREU);
    u->hp_words = (GET(c0, CONFIG0, DATAPATH) ? 10u : 5u) + 7u;
    u->ph_words = GET(c1, CONFIG1, PHOTONS_PER_CYCLE) * PREE_PH_SLOT_WORDS;
    u->cand_bytes = (36u * u->preu + 7u) / 8u;
    if (u->preu == 0 || u->ph_words == 0 || 1 + u->cand_bytes > MAX_BYTES || 1 + 4 * u->ph_words > MAX_BYTES) {
        snprintf(err, errlen, "UART bridge: CONFIG0 0x%08x / CONFIG1 0x%08x: not a pree_axi this back end knows", c0, c1);
        close_be(u);
        return -1;
    }
    *be = (pree_backend_t){.ctx = u, .reg_read = reg_read, .reg_write = reg_write, .submit = submit,
                           .receive = receive_arm, .wait = wait_for, .error = error, .close = close_be};
    return 0;
}
