// SPDX-License-Identifier: Apache-2.0
/* adiso_vecgen.c: writes stimulus and expected-output vectors of the ADISO-REC C model for the
 * Icarus bench tb/ctrl/adiso_tb.v.
 *
 * Usage: adiso_vecgen --preu N --pipe P --seed S STIM EXP
 * STIM line (9 hex digits): flags {rst_n, start, stall, 0}, N.
 * EXP line: flags {busy, 0, 0, 0}, addr_valid (16 bits), then addr of group N-1 down to 0.
 * Passes: N = 0..40 and counts around 2^k and the group/leap boundaries, one pass aborted by a
 * new start, one window of N = 2^32 - 1; random stalls. Prints the number of cycles.
 */
#include "adiso_model.h"
#include "ctrl_hex.h"
#include "ctrl_rng.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static FILE *fs, *fe;
static adiso_model m;
static long cycles;

/* Write one cycle's vectors and clock the model. */
static void cycle(int preu, int rst_n, int start, uint32_t n, int stall)
{
  adiso_out out;
  adiso_eval(&m, &out);
  hex_field(fs, (uint64_t)(rst_n << 3 | start << 2 | stall << 1), 1);
  hex_field(fs, n, 8);
  fputc('\n', fs);
  unsigned valid = 0;
  for (int g = 0; g < preu; g++) valid |= (unsigned)out.valid[g] << g;
  hex_field(fe, (uint64_t)(out.busy << 3), 1);
  hex_field(fe, valid, 4);
  for (int g = preu - 1; g >= 0; g--) hex_field(fe, out.addr[g], 8);
  fputc('\n', fe);
  if (rst_n) adiso_step(&m, start, n, stall);
  cycles++;
}

int main(int argc, char **argv)
{
  int preu = 4, pipe = 12;
  uint64_t seed = 1;
  const char *stim_path = NULL, *exp_path = NULL;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--preu") && i + 1 < argc) preu = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--pipe") && i + 1 < argc) pipe = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--seed") && i + 1 < argc) seed = strtoull(argv[++i], NULL, 0);
    else if (!stim_path) stim_path = argv[i];
    else if (!exp_path) exp_path = argv[i];
    else { stim_path = NULL; break; }
  }
  if (!stim_path || !exp_path || preu < 1 || preu > 16 || (preu & (preu - 1)) || pipe < 1) {
    fprintf(stderr, "usage: %s --preu N(power of two <= 16) --pipe P --seed S STIM EXP\n", argv[0]);
    return 2;
  }
  fs = fopen(stim_path, "w");
  fe = fopen(exp_path, "w");
  if (!fs || !fe) { perror("adiso_vecgen"); return 1; }
  adiso_init(&m, preu, pipe);
  uint64_t rng = seed;

  uint32_t list[128];
  int count = 0;
  for (uint32_t n = 0; n <= 40; n++) list[count++] = n;
  uint32_t unit = 1u << adiso_shift(preu, pipe);  /* smallest N with leaping value 1 */
  const uint32_t more[] = {unit - 1, unit, unit + 1, 2 * unit - 1, 2 * unit + 3, 3 * unit + 2,
                           5 * unit + (uint32_t)preu - 1, 1000, 1023, 1025, 2047, 2049};
  for (size_t k = 0; k < sizeof more / sizeof more[0]; k++) list[count++] = more[k];

  cycle(preu, 0, 0, 0, 0);
  cycle(preu, 0, 0, 0, 0);
  for (int k = 0; k < count; k++) {
    uint32_t n = list[k];
    int stalls = k & 1;
    cycle(preu, 1, 1, n, 0);
    if (k == count - 3) {  /* abort this pass after a few cycles with a new start */
      for (int c = 0; c < 5; c++) cycle(preu, 1, 0, n, 0);
      cycle(preu, 1, 1, n + 7, 0);
      n += 7;
    }
    adiso_out out;
    for (;;) {
      adiso_eval(&m, &out);
      if (!out.busy) break;
      cycle(preu, 1, 0, n, stalls && ctrl_rng_unit(&rng) < 0.2);
    }
    cycle(preu, 1, 0, n, 0);
  }
  /* Huge N: a window of 300 cycles (leap + lv needs 33 bits). */
  cycle(preu, 1, 1, 0xffffffffu, 0);
  for (int c = 0; c < 300; c++) cycle(preu, 1, 0, 0xffffffffu, ctrl_rng_unit(&rng) < 0.2);

  if (fclose(fs) || fclose(fe)) { perror("adiso_vecgen"); return 1; }
  printf("%ld\n", cycles);
  return 0;
}
