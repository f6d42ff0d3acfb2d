// SPDX-License-Identifier: Apache-2.0
/* pree_be_uio.c: pree_drv's back end on a board (pree_be_uio.h): pree_axi's registers mmapped
 * from UIO or /dev/mem, the streams through Xilinx AXI DMA engines in simple mode, buffers in a
 * u-dma-buf region. */
#include "pree_be_uio.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#define REGS_SIZE 0x1000u
#define DMA_SIZE  0x10000u
#define REGION_MIN (96u * 1024u)

/* AXI DMA (PG021) channel registers, from the channel's base (MM2S 0x00, S2MM 0x30). */
#define DMACR   0x00u
#define DMASR   0x04u
#define DMA_ADDR 0x18u   /* MM2S_SA / S2MM_DA */
#define DMA_ADDR_MSB 0x1Cu
#define DMA_LEN 0x28u    /* MM2S_LENGTH / S2MM_LENGTH */
#define S2MM_OFF 0x30u
#define CR_RS    0x1u
#define CR_RESET 0x4u
#define SR_IDLE  0x2u
#define SR_ERRS  0x70u   /* DMAIntErr, DMASlvErr, DMADecErr */
#define SR_IOC   0x1000u
/* pree_axi's IRQ_STATUS and IRQ_EN (drv/pree_axi_regs.h). */
#include "pree_axi_regs.h"
#define R_IRQ_EN ((uint32_t)offsetof(pree_axi_regs_t, IRQ_EN))
#define R_IRQ_STATUS ((uint32_t)offsetof(pree_axi_regs_t, IRQ_STATUS))

typedef struct {
    volatile uint32_t *regs;   /* the channel's registers */
    void *map;                 /* the engine's mapping */
    size_t map_len;
    int busy;                  /* a transfer started and not yet seen complete */
    uint8_t *buf;              /* its region of the u-dma-buf, and the region's bus address */
    uint64_t phys;
} chan_t;

typedef struct {
    volatile uint32_t *regs;
    void *regs_map;
    int regs_fd, use_irq;
    chan_t ch[PREE_DMA_N];
    uint8_t *buf;
    size_t buf_size, region;
    int buf_fd;
    uint32_t *rx;              /* the armed receive: copied out when the S2MM channel completes */
    size_t rx_bytes;
    char err[256];
} uio_t;

static int fail(uio_t *u, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(u->err, sizeof u->err, fmt, ap);
    va_end(ap);
    return -1;
}

/* Map len bytes of a register block: map 0 of a UIO device, or /dev/mem at base. */
static void *map_block(uio_t *u, const pree_uio_map_t *m, size_t len, int *fd_out)
{
    const int is_uio = !strncmp(m->dev, "/dev/uio", 8);
    const int fd = open(m->dev, O_RDWR | O_SYNC);
    if (fd < 0) { fail(u, "%s: %s", m->dev, strerror(errno)); return NULL; }
    const long page = sysconf(_SC_PAGESIZE);
    if (!is_uio && m->base % (uint64_t)page) {
        close(fd);
        fail(u, "%s: base address 0x%llx not page-aligned", m->dev, (unsigned long long)m->base);
        return NULL;
    }
    void *p = mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_SHARED, fd, is_uio ? 0 : (off_t)m->base);
    if (p == MAP_FAILED) {
        fail(u, "%s: mmap: %s", m->dev, strerror(errno));
        close(fd);
        return NULL;
    }
    if (fd_out) *fd_out = fd;
    else close(fd);
    return p;
}

/* A number from a sysfs file of the u-dma-buf device. */
static int sysfs_number(uio_t *u, const char *dev, const char *attr, uint64_t *v)
{
    const char *name = strrchr(dev, '/');
    char path[256];
    snprintf(path, sizeof path, "/sys/class/u-dma-buf/%s/%s", name ? name + 1 : dev, attr);
    FILE *f = fopen(path, "r");
    if (!f) return fail(u, "%s: %s", path, strerror(errno));
    unsigned long long x;
    const int ok = fscanf(f, "%lli", &x) == 1;
    fclose(f);
    if (!ok) return fail(u, "%s: not a number", path);
    *v = x;
    return 0;
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static const char *chan_name(int c)
{
    static const char *const names[] = {"s_axis_hp DMA (MM2S)", "s_axis_ph DMA (MM2S)", "s_axis_cand DMA (MM2S)", "m_axis DMA (S2MM)"};
    return names[c];
}

/* 1 when the channel has no transfer in flight, 0 while it has, -1 on a DMA error. */
static int chan_done(uio_t *u, int c)
{
    chan_t *ch = &u->ch[c];
    if (!ch->busy) return 1;
    const uint32_t sr = ch->regs[DMASR / 4];
    if (sr & SR_ERRS) {
        return fail(u, "%s: DMASR 0x%08x (a DMA error)", chan_name(c), sr);
    }
    if (!(sr & (SR_IDLE | SR_IOC))) return 0;
    ch->regs[DMASR / 4] = SR_IOC;
    ch->busy = 0;
    if (c == PREE_DMA_M && u->rx) {
        memcpy(u->rx, ch->buf, u->rx_bytes);
        u->rx = NULL;
    }
    return 1;
}

/* Wait until a channel is done or deadline_ms (now_ms) passes: 1 done, 0 timeout, -1 error. */
static int chan_wait(uio_t *u, int c, double deadline_ms)
{
    for (;;) {
        const int r = chan_done(u, c);
        if (r) return r;
        if (now_ms() > deadline_ms) return 0;
        const struct timespec pause = {0, 20000};
        nanosleep(&pause, NULL);
    }
}

static void chan_start(chan_t *ch, uint64_t phys, size_t bytes)
{
    ch->regs[DMACR / 4] = CR_RS;
    ch->regs[DMA_ADDR / 4] = (uint32_t)phys;
    ch->regs[DMA_ADDR_MSB / 4] = (uint32_t)(phys >> 32);
    ch->busy = 1;
    ch->regs[DMA_LEN / 4] = (uint32_t)bytes;   /* starts the transfer */
}

static int reg_read(void *ctx, uint32_t off, uint32_t *v)
{
    uio_t *u = ctx;
    if (off >= REGS_SIZE || off % 4) return fail(u, "register offset 0x%x outside the block", off);
    *v = u->regs[off / 4];
    return 0;
}

static int reg_write(void *ctx, uint32_t off, uint32_t v)
{
    uio_t *u = ctx;
    if (off >= REGS_SIZE || off % 4) return fail(u, "register offset 0x%x outside the block", off);
    u->regs[off / 4] = v;
    return 0;
}

static int submit(void *ctx, int stream, const uint32_t *words, size_t n, unsigned beat_words, int last)
{
    uio_t *u = ctx;
    (void)beat_words;   /* the width converter makes the beats */
    (void)last;         /* MM2S ends every transfer with TLAST (pree_be_uio.h) */
    if (stream < 0 || stream > PREE_STREAM_CAND) return fail(u, "no stream %d", stream);
    const size_t bytes = n * sizeof *words;
    if (bytes > u->region) return fail(u, "%s: %zu bytes, more than its u-dma-buf region (%zu)", chan_name(stream), bytes, u->region);
    if (!bytes) return 0;
    const int r = chan_wait(u, stream, now_ms() + 10000.0);
    if (r <= 0) return r < 0 ? -1 : fail(u, "%s: the previous transfer did not end in 10 s", chan_name(stream));
    chan_t *ch = &u->ch[stream];
    memcpy(ch->buf, words, bytes);
    chan_start(ch, ch->phys, bytes);
    return 0;
}

static int receive(void *ctx, uint32_t *words, size_t nbeats, unsigned beat_words, int user)
{
    uio_t *u = ctx;
    (void)user;   /* tuser does not cross the DMA */
    const size_t bytes = nbeats * beat_words * sizeof *words;
    if (bytes > u->region) return fail(u, "%s: %zu bytes, more than its u-dma-buf region (%zu)", chan_name(PREE_DMA_M), bytes, u->region);
    if (u->ch[PREE_DMA_M].busy) return fail(u, "%s: a receive is still armed", chan_name(PREE_DMA_M));
    u->rx = words;
    u->rx_bytes = bytes;
    chan_start(&u->ch[PREE_DMA_M], u->ch[PREE_DMA_M].phys, bytes);
    return 0;
}

/* irq_o: the UIO interrupt, or IRQ_STATUS & IRQ_EN polled. 1, 0 timeout, -1 error. */
static int irq_wait(uio_t *u, double deadline_ms)
{
    for (;;) {
        if (u->regs[R_IRQ_STATUS / 4] & u->regs[R_IRQ_EN / 4]) return 1;
        const double left = deadline_ms - now_ms();
        if (left <= 0) return 0;
        if (u->use_irq) {
            const int32_t on = 1;   /* re-enable (uio_pdrv_genirq masks it when it fires) */
            if (write(u->regs_fd, &on, sizeof on) != sizeof on) return fail(u, "UIO interrupt enable: %s", strerror(errno));
            struct pollfd p = {.fd = u->regs_fd, .events = POLLIN};
            const int r = poll(&p, 1, left > 1000 ? 1000 : (int)left + 1);
            if (r < 0 && errno != EINTR) return fail(u, "UIO interrupt: %s", strerror(errno));
            int32_t count;
            if (r > 0 && read(u->regs_fd, &count, sizeof count) != sizeof count)
                return fail(u, "UIO interrupt read: %s", strerror(errno));
        } else {
            const struct timespec pause = {0, 20000};
            nanosleep(&pause, NULL);
        }
    }
}

static int wait_for(void *ctx, int irq, unsigned timeout_ms)
{
    uio_t *u = ctx;
    const double deadline = now_ms() + timeout_ms;
    for (int c = 0; c < PREE_DMA_N; c++) {
        const int r = chan_wait(u, c, deadline);
        if (r <= 0) return r;
    }
    return irq ? irq_wait(u, deadline) : 1;
}

static const char *error(void *ctx) { return ((uio_t *)ctx)->err; }

static void close_be(void *ctx)
{
    uio_t *u = ctx;
    for (int c = 0; c < PREE_DMA_N; c++)
        if (u->ch[c].map) munmap(u->ch[c].map, u->ch[c].map_len);
    if (u->regs_map) munmap(u->regs_map, REGS_SIZE);
    if (u->buf) munmap(u->buf, u->buf_size);
    if (u->regs_fd >= 0) close(u->regs_fd);
    if (u->buf_fd >= 0) close(u->buf_fd);
    free(u);
}

/* Reset a channel and set it running. */
static int chan_reset(uio_t *u, int c)
{
    chan_t *ch = &u->ch[c];
    ch->regs[DMACR / 4] = CR_RESET;
    const double deadline = now_ms() + 100.0;
    while (ch->regs[DMACR / 4] & CR_RESET)
        if (now_ms() > deadline) return fail(u, "%s: reset does not complete", chan_name(c));
    ch->regs[DMACR / 4] = CR_RS;
    return 0;
}

int pree_be_uio_open(pree_backend_t *be, const pree_uio_config_t *cfg, char *err, size_t errlen)
{
    uio_t *u = calloc(1, sizeof *u);
    if (!u) { snprintf(err, errlen, "out of memory"); return -1; }
    u->regs_fd = u->buf_fd = -1;
    int ok = 1;
    u->regs_map = map_block(u, &cfg->regs, REGS_SIZE, &u->regs_fd);
    ok = u->regs_map != NULL;
    u->regs = u->regs_map;
    u->use_irq = cfg->use_irq && ok && !strncmp(cfg->regs.dev, "/dev/uio", 8);
    for (int c = 0; c < PREE_DMA_N && ok; c++) {
        u->ch[c].map = map_block(u, &cfg->dma[c], DMA_SIZE, NULL);
        ok = u->ch[c].map != NULL;
        u->ch[c].map_len = DMA_SIZE;
        if (ok) u->ch[c].regs = (volatile uint32_t *)u->ch[c].map + (c == PREE_DMA_M ? S2MM_OFF / 4 : 0);
    }
    uint64_t phys = cfg->buf_phys, size = cfg->buf_size;
    if (ok && !phys) ok = !sysfs_number(u, cfg->buf_dev, "phys_addr", &phys);
    if (ok && !size) ok = !sysfs_number(u, cfg->buf_dev, "size", &size);
    if (ok && size / PREE_DMA_N < REGION_MIN) {
        ok = !fail(u, "%s: %llu bytes, at least 4 x 96 KiB needed", cfg->buf_dev, (unsigned long long)size);
    }
    if (ok) {
        u->buf_fd = open(cfg->buf_dev, O_RDWR | O_SYNC);
        if (u->buf_fd < 0) ok = !fail(u, "%s: %s", cfg->buf_dev, strerror(errno));
    }
    if (ok) {
        u->buf = mmap(NULL, size, PROT_READ | PROT_WRITE, MAP_SHARED, u->buf_fd, 0);
        if (u->buf == MAP_FAILED) { u->buf = NULL; ok = !fail(u, "%s: mmap: %s", cfg->buf_dev, strerror(errno)); }
    }
    if (ok) {
        u->buf_size = size;
        u->region = size / PREE_DMA_N;
        for (int c = 0; c < PREE_DMA_N && ok; c++) {
            u->ch[c].buf = u->buf + c * u->region;
            u->ch[c].phys = phys + c * u->region;
            ok = !chan_reset(u, c);
        }
    }
    if (!ok) {
        snprintf(err, errlen, "%s", u->err);
        close_be(u);
        return -1;
    }
    *be = (pree_backend_t){.ctx = u, .reg_read = reg_read, .reg_write = reg_write, .submit = submit,
                           .receive = receive, .wait = wait_for, .error = error, .close = close_be};
    return 0;
}
