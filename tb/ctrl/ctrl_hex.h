// SPDX-License-Identifier: Apache-2.0
/* ctrl_hex.h: writes fixed-width hex vector lines for the Icarus benches ($readmemh format).
 * A line is built from fields, most significant first; each field is a whole number of hex
 * digits, so the Verilog side can slice it with constant part-selects.
 */
#ifndef CTRL_HEX_H
#define CTRL_HEX_H

#include <stdint.h>
#include <stdio.h>

/* Append value v as `digits` hex digits (digits <= 16). */
static inline void hex_field(FILE *f, uint64_t v, int digits)
{
  for (int d = digits - 1; d >= 0; d--) fputc("0123456789abcdef"[(v >> (4 * d)) & 15u], f);
}

#endif
