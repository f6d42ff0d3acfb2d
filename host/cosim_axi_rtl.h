// SPDX-License-Identifier: Apache-2.0
/* cosim_axi_rtl.h: the Verilated pree_axi (rtl/pree_axi.v) behind a C interface: the ports of one
 * clock cycle in, the handshakes that happened at its edge out. The AXI co-simulation program
 * (build/pree-cosim-axi-<d><n>, mk/cosim_axi.mk) links it in place of cosim_rtl.cpp: it also
 * provides cosim_rtl_new/free/in/hp_bank_w (cosim_rtl.h), so that cosim_main.c runs unchanged;
 * of cosim_in_t only alpha and kappa are read (by the AXI driver, host/cosim_axi.c).
 *
 * API
 *   cosim_axi_in(r)    the AXI inputs applied at the next tick (they hold until changed); the
 *                      photon beat's slots beyond the model's PhotonsPerCycle (cosim_rtl_ppc)
 *                      are not read
 *   cosim_axi_tick(r)  apply the inputs, settle with the clock low, note every handshake
 *                      (valid and ready both high) and the data it carried, then one rising edge;
 *                      returns the notes of that edge
 *   cosim_axi_backend(&be, r, opt, err, errlen)  the driver's back end on the model: the
 *                      Verilated wrapper (drv/pree_be_verilated.h, with opt's gaps and the
 *                      scheduler's lead); a board simulated behind its UART link
 *                      (host/postroute_uart.cpp) supplies its own. 0, or -1 with err */
#ifndef PREE_COSIM_AXI_RTL_H
#define PREE_COSIM_AXI_RTL_H

#include <stddef.h>
#include <stdint.h>
#include "cosim_drv.h"
#include "cosim_rtl.h"
#include "pree_drv.h"
#include "preu_fp32.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Handshake bits of cosim_axi_out_t.fired. */
enum { AXI_AW = 1, AXI_W = 2, AXI_B = 4, AXI_AR = 8, AXI_R = 16, AXI_PH = 32, AXI_CAND = 64,
       AXI_HP = 128, AXI_M = 256 };

typedef struct {
    int awvalid, wvalid, bready, arvalid, rready;     /* AXI4-Lite */
    uint32_t awaddr, wdata, araddr;
    int ph_valid, ph_last;                            /* s_axis_ph: slot s, N^P 0 empty */
    preu_photon_t ph[COSIM_MAX_PPC];
    uint32_t ph_n[COSIM_MAX_PPC];
    int cand_valid;                                   /* s_axis_cand: lane j when keep bit j */
    uint32_t cand_keep, cand[COSIM_MAX_PREU];
    int hp_valid;                                     /* s_axis_hp */
    preu_hpw_t hp;
    uint32_t hp_pixel;
    int m_ready;                                      /* m_axis */
} cosim_axi_in_t;

typedef struct {
    unsigned fired;          /* AXI_* handshakes at the last edge */
    uint32_t rdata;          /* R: the data */
    int m_user, m_last;      /* M: the beat */
    preu_hpw_t m_hp;
    uint32_t m_pixel, m_px[3];
    int irq;                 /* irq_o before the edge */
} cosim_axi_out_t;

cosim_axi_in_t *cosim_axi_in(cosim_rtl_t *r);
const cosim_axi_out_t *cosim_axi_tick(cosim_rtl_t *r);
int cosim_axi_backend(pree_backend_t *be, cosim_rtl_t *r, const cosim_drv_opts_t *opt, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
