// SPDX-License-Identifier: Apache-2.0
/* pree_be_uart.h: pree_drv's back end over the board's UART link (drv/pree_be_uart.c): the byte
 * protocol of rtl/board/pree_uart_bridge.v (pree_ulx3s, docs/fpga_board.md) on a byte channel,
 * a serial port (pree_uart_tty_open: a ULX3S's FTDI port, 8N1) or a simulated board
 * (host/postroute_uart.cpp: a Verilated pree_ulx3s whose pins a UART model drives).
 *
 * One command at a time, each answered before the next goes (the bridge's rule); m_axis beats
 * arriving between replies are kept for receive(). Candidate beats go right before the photon
 * beat that needs them (their N^P), so that the index table never waits for a photon not yet
 * sent. The link carries no interrupt: wait() polls IRQ_STATUS against the IRQ_EN last
 * written.
 *
 *   pree_be_uart_open(&be, &chan, err, errlen)   reads CONFIG0/1 over the channel (the beat
 *       sizes); 0, or -1 with a one-line err; the back end owns the channel from then on
 *   pree_uart_tty_open(&chan, path, baud, err, errlen)   a serial port in raw 8N1 mode */
#ifndef PREE_BE_UART_H
#define PREE_BE_UART_H

#include <stddef.h>
#include <stdint.h>
#include "pree_drv.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A byte channel to the bridge. */
typedef struct {
    void *ctx;
    int (*send)(void *ctx, const uint8_t *b, size_t n);    /* 0, or -1 */
    /* Up to n bytes, waiting at most until now_ms() passes deadline_ms: the count received
     * (fewer at the deadline), or -1. */
    long (*recv)(void *ctx, uint8_t *b, size_t n, uint64_t deadline_ms);
    uint64_t (*now_ms)(void *ctx);                          /* the channel's clock */
    const char *(*error)(void *ctx);
    void (*close)(void *ctx);
} pree_uart_chan_t;

int pree_be_uart_open(pree_backend_t *be, const pree_uart_chan_t *chan, char *err, size_t errlen);
int pree_uart_tty_open(pree_uart_chan_t *chan, const char *path, unsigned baud, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
