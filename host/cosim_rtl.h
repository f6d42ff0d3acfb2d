// SPDX-License-Identifier: Apache-2.0
/* cosim_rtl.h: a C interface to the Verilated pree_top (rtl/pree_top.v), one model per PREU
 * count (1, 2, 4, 8, 16), datapath (0 paper, 1 stable) and PipeFast (0, 1), built by mk/cosim.mk with
 * the parameters below (the stable datapath's models only for the counts in
 * COSIM_STABLE_PREUS, the PipeFast = 1 models only for those in COSIM_FAST_PREUS).
 *
 * API
 *   cosim_rtl_new(preu, dp, pf, fst, err)  a model in reset state after two reset cycles; fst: FST
 *                                  trace file or NULL (no tracing). NULL + err when that model
 *                                  is not built or the trace cannot be opened.
 *   cosim_rtl_free(r)              close the trace, release the model
 *   cosim_rtl_in(r)                the input set applied at the next eval/tick (write it)
 *   cosim_rtl_tick(r)              apply the inputs, one rising clock edge, settle (traced)
 *   cosim_rtl_ph_ready/idle/photons_done, cosim_rtl_hp_rdata, cosim_rtl_px_rdata,
 *   cosim_rtl_counters             read outputs (after eval or tick)
 *   cosim_rtl_hp_bank_w            the model's HpBankW parameter
 *   cosim_rtl_update_window        its update hazard window (pree_top's WIN_UPD: 1 + the PREU's
 *                                  update latency, which follows from Datapath and PipeFast)
 *   cosim_rtl_radiance_depth       ADISO-REC's depth in it (pree_top's RAD_LAT, the PREU's radiance
 *                                  latency), which orders the radiance pass
 *   cosim_rtl_cycle                cycles run since reset (the trace's time: cycle n at 8n ns)
 *   cosim_rtl_trace_window(r, a, b)  dump only cycles a..b into the trace
 *   cosim_rtl_reg_flow             whether it has PipeFast 1's registered flow: A's offer register
 *                                  and B's queue (pree_top's REG_FLOW)
 *   cosim_rtl_ppc                  the model's PhotonsPerCycle parameter (photon slots of ph_*)
 *   cosim_rtl_config(preu, &hpb, &ppc)  HpBankW and PhotonsPerCycle of the build's pree_top with
 *                                  preu PREUs, whether or not that model is linked (-1: no such
 *                                  configuration); what `pree cosim --model-only` needs
 *   cosim_rtl_set_reset(r, on)     hold rst_ni low (on: asynchronous, at once) or release it
 * Inputs hold their values until changed; none of these can fail after cosim_rtl_new. */
#ifndef PREE_COSIM_RTL_H
#define PREE_COSIM_RTL_H

#include <stddef.h>
#include <stdint.h>
#include "pree_config.h"
#include "cosim_config.h"
#include "preu_state.h"

#ifdef __cplusplus
extern "C" {
#endif

/* pree_top parameters of the co-simulation builds: COSIM_HPAW (hit-point address bits), _IDXAW,
 * _PXAW, _CNTW, each PREU count's banks and photons a cycle (COSIM_HPB_n, _PXB_n, _PPC_n),
 * COSIM_MAX_PREU and COSIM_MAX_PPC come from the configuration table (pree_config.h, which
 * mk/config.mk matches); pree_top's default CtrW is the models' too. */
#define COSIM_CTRW  48   /* bits of each counter in cnt_o (pree_top's CtrW) */
#define COSIM_NCNT (7 + COSIM_MAX_PREU)

/* Counter numbers in pree_top's cnt_o. */
enum { CNT_CYC_UPD = 0, CNT_CYC_RAD, CNT_HAZ, CNT_DUP, CNT_BANK, CNT_ABANK, CNT_STARVE, CNT_OPS0 };

typedef struct {
    int mode, cnt_en, rad_start;
    uint32_t ne, n_hit;
    int ph_valid;                               /* one valid for every slot */
    uint32_t ph_pos[COSIM_MAX_PPC][3], ph_phi[COSIM_MAX_PPC][3];
    uint32_t ph_paddr[COSIM_MAX_PPC], ph_n[COSIM_MAX_PPC];   /* ph_n 0: an empty slot */
    int idx_we[COSIM_MAX_PREU];
    uint32_t idx_addr[COSIM_MAX_PREU], idx_data[COSIM_MAX_PREU];
    int hp_we, hp_re;
    uint32_t hp_addr, hp_pixel;
    preu_hpw_t hp_wdata;      /* position, weight, state words (the model's datapath layout) */
    uint32_t alpha, kappa;    /* run-time constants: change only while idle */
    int px_we, px_re;
    uint32_t px_addr, px_wdata[3];
} cosim_in_t;

typedef struct cosim_rtl cosim_rtl_t;

cosim_rtl_t *cosim_rtl_new(int preu, int datapath, int pipefast, const char *fst, char *err, size_t errlen);
void cosim_rtl_free(cosim_rtl_t *r);
cosim_in_t *cosim_rtl_in(cosim_rtl_t *r);
void cosim_rtl_tick(cosim_rtl_t *r);
int cosim_rtl_ph_ready(cosim_rtl_t *r);
int cosim_rtl_idle(cosim_rtl_t *r);
uint32_t cosim_rtl_photons_done(cosim_rtl_t *r);
void cosim_rtl_hp_rdata(cosim_rtl_t *r, preu_hpw_t *hp, uint32_t *pixel);
void cosim_rtl_px_rdata(cosim_rtl_t *r, uint32_t L[3]);
void cosim_rtl_counters(cosim_rtl_t *r, uint64_t cnt[COSIM_NCNT]);
int cosim_rtl_hp_bank_w(cosim_rtl_t *r);   /* log2 of the model's hit-point banks */
int cosim_rtl_update_window(cosim_rtl_t *r);   /* the update hazard window in cycles */
int cosim_rtl_radiance_depth(cosim_rtl_t *r);
uint64_t cosim_rtl_cycle(cosim_rtl_t *r);
void cosim_rtl_trace_window(cosim_rtl_t *r, uint64_t from, uint64_t to);
int cosim_rtl_reg_flow(cosim_rtl_t *r);    /* 1: A's offer register, B's queue (PipeFast 1) */
int cosim_rtl_ppc(cosim_rtl_t *r);         /* photons the model takes per cycle */
int cosim_rtl_config(int preu, int *hp_bank_w, int *ppc);
void cosim_rtl_set_reset(cosim_rtl_t *r, int on);

#ifdef __cplusplus
}
#endif

#endif
