// SPDX-License-Identifier: Apache-2.0
/* aftso_vecgen.c: writes stimulus and expected-output vectors of the AFTSO-HpUOC C model for
 * the Icarus bench tb/ctrl/aftso_tb.v.
 *
 * Usage: aftso_vecgen --preu N --early-ready B --seed S --cycles C STIM EXP
 * STIM line (73 hex digits): flags {rst_n, in_valid, stall, 0}, N^P, p_addr, id, data[191:0].
 * EXP line: flags {ready, empty, busy, 0}, lane_valid (16 bits), lane_last (16 bits), then per
 * lane from lane N-1 down to lane 0: ref_addr, id, data (invalid lanes all zero).
 * The run: 2 reset cycles, then random photons (zeros, ones, around N, large, geometric) with
 * random gaps and stalls, then a drain; C cycles in all. Prints the cycle count.
 */
#include "aftso_model.h"
#include "ctrl_hex.h"
#include "ctrl_rng.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WORDS 6

static uint32_t draw_n(uint64_t *rng, int preu, int huge)
{
  if (huge) return 0x40000000u + ctrl_rng_below(rng, 1000);  /* accuHP beyond 2^32 */
  uint32_t r = ctrl_rng_below(rng, 100);
  if (r < 15) return 0;
  if (r < 30) return 1;
  if (r < 50) return (uint32_t)preu - 1 + ctrl_rng_below(rng, 3);
  if (r < 60) return 20 * (uint32_t)preu + ctrl_rng_below(rng, 200);
  return ctrl_rng_geometric(rng, 8.0);
}

int main(int argc, char **argv)
{
  int preu = 4, early = 1;
  long total = 3000;
  uint64_t seed = 1;
  const char *stim_path = NULL, *exp_path = NULL;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--preu") && i + 1 < argc) preu = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--early-ready") && i + 1 < argc) early = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--seed") && i + 1 < argc) seed = strtoull(argv[++i], NULL, 0);
    else if (!strcmp(argv[i], "--cycles") && i + 1 < argc) total = atol(argv[++i]);
    else if (!stim_path) stim_path = argv[i];
    else if (!exp_path) exp_path = argv[i];
    else { stim_path = NULL; break; }
  }
  if (!stim_path || !exp_path || preu < 1 || preu > 16 || total < 10) {
    fprintf(stderr, "usage: %s --preu N(<=16) --early-ready B --seed S --cycles C STIM EXP\n", argv[0]);
    return 2;
  }
  FILE *fs = fopen(stim_path, "w"), *fe = fopen(exp_path, "w");
  if (!fs || !fe) { perror("aftso_vecgen"); return 1; }

  aftso_model m;
  aftso_out out;
  aftso_in in;
  aftso_init(&m, preu, 4, 1, WORDS, early);
  memset(&in, 0, sizeof in);
  uint64_t rng = seed;
  uint32_t next_id = 0;
  /* Phases: [2, 60%) random photons, [60%, 80%) no input (drain), [80%, 100%) huge photons. */
  for (long c = 0; c < total; c++) {
    int rst_n = c >= 2;
    int feeding = rst_n && (c < total * 6 / 10 || c >= total * 8 / 10);
    if (!in.valid && feeding && ctrl_rng_unit(&rng) >= 0.25) {
      in.valid = 1;
      in.ph[0].n = draw_n(&rng, preu, c >= total * 8 / 10);
      in.ph[0].p_addr = ctrl_rng_below(&rng, 4) ? (uint32_t)ctrl_rng_next(&rng) : 0xfffffff0u;
      in.ph[0].id = next_id++;
      for (int w = 0; w < WORDS; w++) in.ph[0].data[w] = (uint32_t)ctrl_rng_next(&rng);
    }
    int stall = rst_n && ctrl_rng_unit(&rng) < 0.2;
    aftso_eval(&m, stall, &out);

    hex_field(fs, (uint64_t)(rst_n << 3 | in.valid << 2 | stall << 1), 1);
    hex_field(fs, in.ph[0].n, 8);
    hex_field(fs, in.ph[0].p_addr, 8);
    hex_field(fs, in.ph[0].id, 8);
    for (int w = WORDS - 1; w >= 0; w--) hex_field(fs, in.ph[0].data[w], 8);
    fputc('\n', fs);

    unsigned valid = 0, last = 0;
    for (int l = 0; l < out.nvalid; l++) { valid |= 1u << l; last |= (unsigned)out.last[l] << l; }
    hex_field(fe, (uint64_t)(out.ready << 3 | out.empty << 2 | (!out.ready) << 1), 1);
    hex_field(fe, valid, 4);
    hex_field(fe, last, 4);
    for (int l = preu - 1; l >= 0; l--) {
      int v = l < out.nvalid;
      hex_field(fe, v ? out.ref_addr[l] : 0, 8);
      hex_field(fe, v ? out.id[l] : 0, 8);
      for (int w = WORDS - 1; w >= 0; w--) hex_field(fe, v ? out.data[l][w] : 0, 8);
    }
    fputc('\n', fe);

    if (rst_n) {
      int taken = in.valid && out.ready;
      aftso_step(&m, &in, stall);
      if (taken) in.valid = 0;
    }
  }
  if (fclose(fs) || fclose(fe)) { perror("aftso_vecgen"); return 1; }
  printf("%ld\n", total);
  return 0;
}
