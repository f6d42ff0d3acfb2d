// SPDX-License-Identifier: Apache-2.0
/* adiso_seq.c: prints the ADISO-REC leaping-address sequence of the C model for one N, and
 * counts where the closed form of Eq. 11 disagrees with the recurrence of Eq. 13.
 *
 * Usage: adiso_seq --n N [--preu P] [--pipe D] [--max-cycles C]
 * Output: the set-up (shift, leaping value, group bounds), one line per cycle with the address
 * of every group ('-' once a group is done, up to C cycles), then per group the number of j
 * with start_addr from Eq. 11 != start_addr from Eq. 13.
 */
#include "adiso_model.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
  int preu = 4, pipe = 12;
  long n = -1, max_cycles = 64;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--n") && i + 1 < argc) n = atol(argv[++i]);
    else if (!strcmp(argv[i], "--preu") && i + 1 < argc) preu = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--pipe") && i + 1 < argc) pipe = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--max-cycles") && i + 1 < argc) max_cycles = atol(argv[++i]);
    else n = -2;
  }
  if (n < 0 || n > 0xffffffffL || preu < 1 || preu > ADISO_MAX_SET || (preu & (preu - 1)) || pipe < 1) {
    fprintf(stderr, "usage: %s --n N [--preu P(power of two)] [--pipe D] [--max-cycles C]\n", argv[0]);
    return 2;
  }
  adiso_model m;
  adiso_out out;
  adiso_init(&m, preu, pipe);
  adiso_step(&m, 1, (uint32_t)n, 0);
  printf("N=%ld NumPreu=%d Npip=%d shift=%d leaping_value(Eq.10)=%u used=%u size_group=%u\n", n, preu, pipe,
         adiso_shift(preu, pipe), adiso_leaping_value((uint32_t)n, preu, pipe), m.lv, m.size);
  for (int g = 0; g < preu; g++) printf("  group %d: [%u, %u)\n", g, m.start[g], m.end[g]);

  /* Record start_addr per step for the Eq. 11 comparison while printing the sequence. */
  uint32_t *start_hist[ADISO_MAX_SET];
  uint32_t len[ADISO_MAX_SET];
  for (int g = 0; g < preu; g++) {
    len[g] = m.rem[g];
    start_hist[g] = malloc(((size_t)len[g] + 1) * sizeof(uint32_t));
    if (!start_hist[g]) return 1;
  }
  for (long c = 0;; c++) {
    adiso_eval(&m, &out);
    if (!out.busy) break;
    if (c < max_cycles) {
      printf("cycle %4ld:", c);
      for (int g = 0; g < preu; g++) {
        if (out.valid[g]) printf(" %6u", out.addr[g]);
        else printf(" %6s", "-");
      }
      printf("\n");
    } else if (c == max_cycles) {
      printf("...\n");
    }
    for (int g = 0; g < preu; g++)
      if (out.valid[g]) start_hist[g][len[g] - m.rem[g]] = m.start[g];
    adiso_step(&m, 0, (uint32_t)n, 0);
  }
  for (int g = 0; g < preu; g++) {
    uint32_t diff = 0;
    for (uint32_t j = 0; j < len[g]; j++) diff += adiso_eq11_start(&m, g, j) != start_hist[g][j];
    printf("group %d: Eq.11 closed form differs from Eq.13 at %u of %u steps\n", g, diff, len[g]);
    free(start_hist[g]);
  }
  return 0;
}
