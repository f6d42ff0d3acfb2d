// SPDX-License-Identifier: Apache-2.0
/* pree_be_verilated.h: pree_drv's back end on the Verilated pree_axi (drv/pree_be_verilated.c),
 * for tests and co-simulation. It links with a pree_axi model's C interface
 * (host/cosim_axi_rtl.cpp built for one PREU count and datapath, mk/cosim_axi.mk).
 *
 *   pree_be_verilated_open(&be, preu, datapath, gap, seed, fst, err, errlen)
 *       a model out of reset; gap: the probability of holding back an offer or a ready in a
 *       cycle (0: none), seed its generator; fst: a trace file or NULL. 0, or -1 with err
 *       (the model linked is another build, or the trace cannot be opened).
 *   pree_be_verilated_attach(&be, rtl, preu, datapath, gap, seed, lead)
 *       the same on a model the caller made (cosim_rtl_new) and frees after pree_close; lead:
 *       the photon stream starts, at its first beat and after each tlast, once the candidate
 *       stream has moved lead candidates or has none waiting (0: at once). 0, or -1 (no memory).
 *   pree_be_verilated_cycles(&be)   clock cycles run since the model left reset */
#ifndef PREE_BE_VERILATED_H
#define PREE_BE_VERILATED_H

#include <stddef.h>
#include <stdint.h>
#include "pree_drv.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cosim_rtl cosim_rtl_t;

int pree_be_verilated_open(pree_backend_t *be, int preu, int datapath, double gap, uint64_t seed,
                           const char *fst, char *err, size_t errlen);
int pree_be_verilated_attach(pree_backend_t *be, cosim_rtl_t *rtl, int preu, int datapath, double gap,
                             uint64_t seed, uint32_t lead);
uint64_t pree_be_verilated_cycles(const pree_backend_t *be);

#ifdef __cplusplus
}
#endif

#endif
