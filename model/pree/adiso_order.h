// SPDX-License-Identifier: Apache-2.0
/* adiso_order.h: the order in which the PREE's radiance pass (rtl/pree_top.v with ADISO-REC,
 * rtl/pree_adiso_rec.v) adds hit points to pixels, as a C function.
 *
 * The RTL issues ADISO-REC's leaping addresses step by step, lane 0 first within a step, and
 * its hazard logic keeps every pixel's additions in exactly that issue order. So a pixel's sum
 * in fp32 is reproduced by walking this sequence and adding each hit point to its pixel.
 *
 * API
 *   adiso_order(n, npreu, pipe, out)   fill out[0..n) with the addresses 0..n-1 in issue order
 *                                      for npreu groups (a power of two, 1..64) and a radiance
 *                                      pipeline of `pipe` stages (12 in the PREU); returns 0,
 *                                      or -1 (out unchanged) for an unsupported npreu.
 * The rule (paper 000 Eq. 10-13 with rtl/pree_adiso_rec.v's two corrections): lv = n >> ceil(
 * log2(npreu * pipe)), 1 when that is 0; size = n / npreu; group i covers [size*i, size*(i+1)),
 * the last group up to n; each group starts at its base and steps by lv, and past its end goes
 * to start + 1 (the next residue class). Every address appears exactly once. */
#ifndef PREE_ADISO_ORDER_H
#define PREE_ADISO_ORDER_H

#include <stdint.h>

int adiso_order(uint32_t n, int npreu, int pipe, uint32_t *out);

#endif
