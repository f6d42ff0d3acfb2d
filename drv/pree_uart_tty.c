// SPDX-License-Identifier: Apache-2.0
/* pree_uart_tty.c: the UART back end's byte channel on a serial port (pree_be_uart.h): a ULX3S's
 * FTDI port (/dev/ttyUSB0), raw 8N1 at the bridge's baud rate (1 Mbit/s by default). POSIX. */
#define _DEFAULT_SOURCE   /* cfmakeraw, CRTSCTS and the baud rates above 38400 (glibc, musl) */
#include "pree_be_uart.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

typedef struct {
    int fd;
    char err[160];
} tty_t;

static uint64_t now_ms(void *ctx)
{
    (void)ctx;
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (uint64_t)t.tv_sec * 1000u + (uint64_t)t.tv_nsec / 1000000u;
}

static int tty_send(void *ctx, const uint8_t *b, size_t n)
{
    tty_t *t = ctx;
    while (n) {
        const ssize_t k = write(t->fd, b, n);
        if (k < 0 && errno == EINTR) continue;
        if (k < 0) { snprintf(t->err, sizeof t->err, "serial port: write: %s", strerror(errno)); return -1; }
        b += k;
        n -= (size_t)k;
    }
    return 0;
}

static long tty_recv(void *ctx, uint8_t *b, size_t n, uint64_t deadline_ms)
{
    tty_t *t = ctx;
    size_t got = 0;
    while (got < n) {
        const uint64_t now = now_ms(ctx);
        struct pollfd p = {.fd = t->fd, .events = POLLIN};
        const int r = poll(&p, 1, now >= deadline_ms ? 0 : (int)(deadline_ms - now));
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) { snprintf(t->err, sizeof t->err, "serial port: poll: %s", strerror(errno)); return -1; }
        if (r == 0) break;
        const ssize_t k = read(t->fd, b + got, n - got);
        if (k < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (k <= 0) { snprintf(t->err, sizeof t->err, "serial port: read: %s", k ? strerror(errno) : "closed"); return -1; }
        got += (size_t)k;
    }
    return (long)got;
}

static const char *tty_error(void *ctx) { return ((tty_t *)ctx)->err; }

static void tty_close(void *ctx)
{
    tty_t *t = ctx;
    close(t->fd);
    free(t);
}

static speed_t speed_of(unsigned baud)
{
    switch (baud) {
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    case 1000000: return B1000000;
    case 2000000: return B2000000;
    case 3000000: return B3000000;
    default: return 0;
    }
}

int pree_uart_tty_open(pree_uart_chan_t *chan, const char *path, unsigned baud, char *err, size_t errlen)
{
    const speed_t sp = speed_of(baud);
    if (!sp) { snprintf(err, errlen, "%s: baud rate %u not supported", path, baud); return -1; }
    tty_t *t = calloc(1, sizeof *t);
    if (!t) { snprintf(err, errlen, "out of memory"); return -1; }
    t->fd = open(path, O_RDWR | O_NOCTTY | O_NONBLOCK);
    struct termios tio;
    if (t->fd < 0 || tcgetattr(t->fd, &tio)) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        if (t->fd >= 0) close(t->fd);
        free(t);
        return -1;
    }
    cfmakeraw(&tio);
    tio.c_cflag = (tio.c_cflag & ~(tcflag_t)(CSTOPB | PARENB | CRTSCTS | CSIZE)) | CS8 | CLOCAL | CREAD;
    cfsetispeed(&tio, sp);
    cfsetospeed(&tio, sp);
    if (tcsetattr(t->fd, TCSANOW, &tio) || tcflush(t->fd, TCIOFLUSH)) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        close(t->fd);
        free(t);
        return -1;
    }
    *chan = (pree_uart_chan_t){.ctx = t, .send = tty_send, .recv = tty_recv, .now_ms = now_ms,
                               .error = tty_error, .close = tty_close};
    return 0;
}
