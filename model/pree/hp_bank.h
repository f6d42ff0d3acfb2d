// SPDX-License-Identifier: Apache-2.0
/* hp_bank.h: the hit-point bank hash of pree_top (rtl/pree_hp_bank.vh hp_bank()), once in C for the
 * co-simulation host (driver, cycle model, scheduler). The RTL keeps its own copy; the host's
 * cycle model predicting the RTL's bank-conflict counts exactly (the schedule check in
 * tests/checks/) checks the two against each other.
 *
 * pree_hp_bank(a, w): the bank of hit point a among 2^w banks: the low w bits XOR the next w
 * bits, so that hit points a multiple of 2^w apart (neighbours one image row apart) still
 * spread over the banks. */
#ifndef PREE_HP_BANK_H
#define PREE_HP_BANK_H

#include <stdint.h>

static inline uint32_t pree_hp_bank(uint32_t a, int w)
{
    return (a ^ (a >> w)) & ((1u << w) - 1u);
}

#endif
