// SPDX-License-Identifier: Apache-2.0
/* pree_be_uio.h: pree_drv's back end on a board (drv/pree_be_uio.c, Linux). pree_axi's AXI4-Lite
 * block is mapped from a UIO device (/dev/uioN, map 0; uio_pdrv_genirq or generic-uio in the
 * device tree) or from /dev/mem at its physical address. The streams go through Xilinx AXI DMA
 * engines (PG021) in simple (direct register) mode: three MM2S channels feed s_axis_hp,
 * s_axis_ph and s_axis_cand, one S2MM channel takes m_axis, each through an AXI4-Stream data
 * width converter from or to 32 bits (with TKEEP, so that a candidate transfer may end in a
 * partial beat). Buffers live in one physically contiguous u-dma-buf device (/dev/udmabufN,
 * opened O_SYNC: uncached), split into four equal regions, one a channel; it must hold at
 * least 4 x 96 KiB (the driver's largest transfer is 1024 beats of 17 words).
 *
 * The AXI DMA's MM2S asserts TLAST at the end of every transfer, so the photon stream carries a
 * tlast at the end of every submission, not only at a batch's end: each one makes a "batch
 * done" interrupt early, which pree_end_batch tells apart by STATUS.BATCH_PENDING.
 *
 * Waiting: for the channels, DMASR polled (Idle or IOC_Irq, errors reported); for the
 * interrupt, the UIO device's interrupt when regs is a /dev/uio device and use_irq is set
 * (read() after re-enabling with write(1)), else IRQ_STATUS & IRQ_EN polled through the mapping.
 *
 *   pree_be_uio_open(&be, &cfg, err, errlen)   0, or -1 with a one-line err naming the device */
#ifndef PREE_BE_UIO_H
#define PREE_BE_UIO_H

#include <stddef.h>
#include <stdint.h>
#include "pree_drv.h"

/* A register block: a UIO device (base ignored) or /dev/mem at a physical base address. */
typedef struct {
    const char *dev;
    uint64_t base;
} pree_uio_map_t;

/* Channels of pree_uio_config_t.dma. */
enum { PREE_DMA_HP, PREE_DMA_PH, PREE_DMA_CAND, PREE_DMA_M, PREE_DMA_N };

typedef struct {
    pree_uio_map_t regs;             /* pree_axi's AXI4-Lite block (4 KiB) */
    int use_irq;                     /* regs.dev a UIO device whose interrupt is irq_o */
    pree_uio_map_t dma[PREE_DMA_N];  /* the AXI DMA engine of each channel (64 KiB); [PREE_DMA_M]
                                        uses its S2MM channel, the others their MM2S */
    const char *buf_dev;             /* u-dma-buf device, e.g. /dev/udmabuf0 */
    uint64_t buf_phys;               /* its physical address and size; 0: read from */
    size_t buf_size;                 /* /sys/class/u-dma-buf/<name>/{phys_addr,size} */
} pree_uio_config_t;

int pree_be_uio_open(pree_backend_t *be, const pree_uio_config_t *cfg, char *err, size_t errlen);

#endif
