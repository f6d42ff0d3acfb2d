// SPDX-License-Identifier: Apache-2.0
/* cosim_drv.h: the host side of the PREE: drives a Verilated pree_top (cosim_rtl.h) the way an
 * FPGA host would: loads the hit points, streams photons with their index-table entries,
 * runs the radiance pass and reads the memories back.
 *
 * API
 *   cosim_drv_new(rtl, opt)       a driver for a freshly reset model (NULL when out of memory);
 *                                 rtl NULL with opt->model_only: only photon placement and the
 *                                 scheduler run (cosim_drv_photon, cosim_drv_drain,
 *                                 cosim_drv_sched_stats, cosim_drv_ops_sent)
 *   cosim_drv_free(d)
 *   cosim_drv_load_hp(d, ...)     write n hit points (words + pixel) through the host port
 *   cosim_drv_photon(d, ph, hps, n)  queue one photon hit with its candidate hit points, in
 *                                 photon order; clocks the model as far as needed to keep the
 *                                 queues short. Returns 0, or -1 with a message in d->err.
 *                                 With schedule set, the photon goes to the scheduler
 *                                 (cosim_sched.h), which picks the stream order.
 *   cosim_drv_drain(d)            send everything queued and wait until the PREE is idle
 *   cosim_drv_barrier(d)          the same between two photon blocks: more photons may follow
 *                                 (the host reads hit points back in between; pree_axi: a batch)
 *   cosim_drv_read_hp(d, i, hp, pixel)  read hit point i back (one model cycle)
 *   cosim_drv_radiance(d, n_hit, ne, npix, L)  clear npix pixels, run the radiance pass over
 *                                 [0, n_hit) with N_emitted = ne, read the pixels into L;
 *                                 0, or -1 with a message when the PREE does not finish
 * Every wait for the RTL is bounded (opt.wait_limit, default 10 million cycles without the
 * awaited progress): the call then fails with a message naming the wait and the stream's state
 * (ph_ready_o, idle_o, photons taken and retired, entries queued), and so does every later call.
 *   cosim_drv_hp_cycle(d, i)      the cycle (cosim_rtl_cycle) in which hit point i's last operation
 *                                 issued, within a few cycles; UINT64_MAX when none did or it is
 *                                 not known (the AXI driver): where a failing run's trace looks
 *   cosim_drv_radiance_cycles(d, &from, &to)  the cycles of the last radiance pass
 *   cosim_drv_counters(d, cnt)    pree_top's counters now
 *   cosim_drv_sched_stats(d, st)  the scheduler's figures (-1 when not scheduling)
 *
 * Index table use (docs/pree_top.md, "Host protocol"): photon k's N^P entries sit at
 * p_k .. p_k + N^P - 1 (mod 2^IdxAW), with p_k chosen so that the refs AFTSO-HpUOC emits are
 * consecutive mod NumPreu across photons (p_k = p_(k-1) - N^P mod NumPreu): then any NumPreu
 * consecutive operations read distinct index banks and the load port writes NumPreu entries a
 * cycle without conflicts. With reorder set, each photon's candidates are ordered so that any
 * NumPreu consecutive operations use distinct hit-point banks where the candidates allow it
 * (the order inside one photon does not change any result). */
#ifndef PREE_COSIM_DRV_H
#define PREE_COSIM_DRV_H

/* The load port's lead, in index entries (candidates): in a scheduled stream the first photon
 * waits until this many (or every queued one) are written, and the host keeps this many queued
 * (docs/cosim.md, "The scheduler": what AFTSO-HpUOC buffers comes out of the lead; through
 * the wrapper, docs/integration.md, the candidate stream runs this far ahead of the photons).
 * 64 x NumPreu, and never below 4 PREUs' 256: a photon with more candidates than the lead,
 * written NumPreu a cycle, reaches the RTL later than the scheduler's model planned. */
#define COSIM_LEAD_ENTRIES(np) (64u * (uint32_t)((np) > 4 ? (np) : 4))

#include <stddef.h>
#include <stdint.h>
#include "cosim_rtl.h"
#include "cosim_sched.h"

typedef struct {
    int preu;          /* PREUs of the model */
    int datapath;      /* its PREU datapath: 0 paper, 1 stable */
    int hp_bank_w;     /* log2 of its hit-point banks */
    int reorder;       /* 1: order each photon's candidates for distinct banks */
    int schedule;      /* 1: photon order chosen by cosim_sched.h; 0: photon order */
    int window;        /* the scheduler's pending photons */
    double gap;        /* probability of an idle cycle on the photon input (0: none) */
    double stall;      /* probability of a cycle with fewer index writes than the load port takes,
                        * and of an idle cycle in the hit-point load (0: none) */
    uint64_t seed;     /* for the gaps and stalls */
    uint64_t wait_limit; /* cycles a wait may last without progress (0: 10 million) */
    int model_only;    /* 1: the scheduler and its cycle model only, no RTL (rtl = NULL;
                          needs schedule; the counters are the model's prediction) */
    int ppc;           /* with model_only: the top's PhotonsPerCycle (else the RTL's) */
    int win;           /* with model_only: its update hazard window (else the RTL's) */
    int reg_flow;      /* with model_only: whether it has PipeFast 1's registered flow (else the RTL's) */
} cosim_drv_opts_t;

typedef struct cosim_drv cosim_drv_t;


cosim_drv_t *cosim_drv_new(cosim_rtl_t *rtl, const cosim_drv_opts_t *opt);
void cosim_drv_free(cosim_drv_t *d);
const char *cosim_drv_error(const cosim_drv_t *d);
void cosim_drv_load_hp(cosim_drv_t *d, const preu_hpw_t *hp, const int32_t *pixel, size_t n);
int cosim_drv_photon(cosim_drv_t *d, const preu_photon_t *ph, const uint32_t *hps, size_t n);
int cosim_drv_drain(cosim_drv_t *d);
int cosim_drv_barrier(cosim_drv_t *d);
void cosim_drv_read_hp(cosim_drv_t *d, uint32_t i, preu_hpw_t *hp, uint32_t *pixel);
int cosim_drv_radiance(cosim_drv_t *d, uint32_t n_hit, uint32_t ne, size_t npix, uint32_t *L);
void cosim_drv_counters(cosim_drv_t *d, uint64_t cnt[COSIM_NCNT]);
uint64_t cosim_drv_ops_sent(const cosim_drv_t *d);
int cosim_drv_sched_stats(const cosim_drv_t *d, cosim_sched_stats_t *st);
uint64_t cosim_drv_hp_cycle(const cosim_drv_t *d, uint32_t i);
void cosim_drv_radiance_cycles(const cosim_drv_t *d, uint64_t *from, uint64_t *to);

#endif
