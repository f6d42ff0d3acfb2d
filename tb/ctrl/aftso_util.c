// SPDX-License-Identifier: Apache-2.0
/* aftso_util.c: PREU utilization of the AFTSO-HpUOC dispatch rule on a stream of photons.
 *
 * Usage: aftso_util [--preu N] [--buf D] [--early-ready 0|1] [--ppc K] [--np-file FILE | --geo MEAN --photons K] [--seed S]
 *   --np-file FILE   N^P values, one per line (blank lines and '#' comments skipped)
 *   --early-ready B  the RTL's EarlyReady parameter (default 1)
 *   --geo MEAN       synthetic geometric N^P on {0,1,...} with this mean (default 32)
 *   --trace          print every cycle: buffer (id:rem), accuHP, lanes (id:ref_addr), input
 *                    (photon k gets id k and p_addr 100 * k, for readable examples)
 *   --write-np FILE  also write the N^P values used, one per line (to replay them elsewhere)
 * The photons arrive back to back (input valid every cycle) and nothing stalls downstream.
 * Utilization = hit-point operations / (N PREUs x cycles), the cycles counted from the first
 * accepted photon to the last dispatched operation. Prints one line of key=value figures.
 */
#include "aftso_model.h"
#include "ctrl_rng.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t *read_np_file(const char *path, size_t *count)
{
  FILE *f = fopen(path, "r");
  if (!f) { fprintf(stderr, "aftso_util: %s: %s\n", path, strerror(errno)); return NULL; }
  size_t cap = 1 << 16, n = 0;
  uint32_t *v = malloc(cap * sizeof *v);
  char line[128];
  while (v && fgets(line, sizeof line, f)) {
    char *p = line, *end;
    while (*p == ' ' || *p == '\t') p++;
    if (*p == '#' || *p == '\n' || *p == '\0') continue;
    errno = 0;
    unsigned long x = strtoul(p, &end, 10);
    if (end == p || errno || x > 0xffffffffUL) {
      fprintf(stderr, "aftso_util: %s: bad value '%s'\n", path, line);
      free(v); fclose(f); return NULL;
    }
    if (n == cap) { cap *= 2; uint32_t *nv = realloc(v, cap * sizeof *v); if (!nv) { free(v); v = NULL; break; } v = nv; }
    v[n++] = (uint32_t)x;
  }
  fclose(f);
  *count = n;
  return v;
}

/* One line of the --trace output. */
static void print_cycle(uint64_t cycle, const aftso_model *m, const aftso_out *out, const aftso_in *in)
{
  uint64_t accu = 0;
  printf("cycle %3llu | buffer", (unsigned long long)cycle);
  for (int i = 0; i < m->rule.buf_depth; i++) {
    if (i < m->rule.count) printf(" P%u:%u", m->id[m->rule.e[i].seq % AFTSO_MAX_BUF], m->rule.e[i].rem);
    else printf(" -");
  }
  printf(" | accuHP");
  for (int i = 0; i < m->rule.count; i++) { accu += m->rule.e[i].rem; printf(" %llu", (unsigned long long)accu); }
  printf(" | lanes");
  for (int l = 0; l < out->nvalid; l++) printf(" P%u:%u%s", out->id[l], out->ref_addr[l], out->last[l] ? "*" : "");
  if (in->valid) {
    printf(" | in");
    for (int k = 0; k < m->rule.ppc; k++) printf(" P%u N=%u", in->ph[k].id, in->ph[k].n);
    printf(" %s", out->ready ? "taken" : "held");
  }
  printf("\n");
}

int main(int argc, char **argv)
{
  int preu = 4, depth = 4, early = 1, ppc = 1;
  long photons = 1000000;
  double mean = 32.0;
  uint64_t seed = 1;
  const char *file = NULL, *write_np = NULL;
  int trace = 0;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--preu") && i + 1 < argc) preu = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--buf") && i + 1 < argc) depth = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--early-ready") && i + 1 < argc) early = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--ppc") && i + 1 < argc) ppc = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--np-file") && i + 1 < argc) file = argv[++i];
    else if (!strcmp(argv[i], "--trace")) trace = 1;
    else if (!strcmp(argv[i], "--write-np") && i + 1 < argc) write_np = argv[++i];
    else if (!strcmp(argv[i], "--geo") && i + 1 < argc) mean = atof(argv[++i]);
    else if (!strcmp(argv[i], "--photons") && i + 1 < argc) photons = atol(argv[++i]);
    else if (!strcmp(argv[i], "--seed") && i + 1 < argc) seed = strtoull(argv[++i], NULL, 0);
    else { fprintf(stderr, "usage: %s [--preu N] [--buf D] [--early-ready 0|1] [--ppc K] [--np-file FILE | --geo MEAN --photons K] [--seed S] [--trace] [--write-np FILE]\n", argv[0]); return 2; }
  }
  if (preu < 1 || preu > AFTSO_MAX_PREU || depth < 1 || depth > AFTSO_MAX_BUF || photons < 0 ||
      ppc < 1 || ppc > AFTSO_MAX_PPC || ppc > depth) {
    fprintf(stderr, "aftso_util: --preu 1..%d, --buf 1..%d, --ppc 1..min(%d, buf)\n", AFTSO_MAX_PREU, AFTSO_MAX_BUF, AFTSO_MAX_PPC);
    return 2;
  }
  uint32_t *np = NULL;
  size_t nphot = (size_t)photons;
  if (file) {
    np = read_np_file(file, &nphot);
    if (!np) return 1;
  } else {
    np = malloc((nphot ? nphot : 1) * sizeof *np);
    if (!np) return 1;
    for (size_t i = 0; i < nphot; i++) np[i] = ctrl_rng_geometric(&seed, mean);
  }
  if (write_np) {
    FILE *f = fopen(write_np, "w");
    if (!f) { fprintf(stderr, "aftso_util: %s: %s\n", write_np, strerror(errno)); free(np); return 1; }
    for (size_t i = 0; i < nphot; i++) fprintf(f, "%u\n", np[i]);
    if (fclose(f)) { fprintf(stderr, "aftso_util: %s: write failed\n", write_np); free(np); return 1; }
  }

  aftso_model m;
  aftso_out out;
  aftso_in in;
  aftso_init(&m, preu, depth, ppc, 1, early);
  memset(&in, 0, sizeof in);
  size_t next = 0;
  uint64_t ops = 0, cycles = 0, full_cycles = 0, busy_cycles = 0, want = 0;
  for (size_t i = 0; i < nphot; i++) want += np[i];
  /* Clock until every photon is in and the buffer has drained. */
  while (next < nphot || m.rule.count) {
    aftso_eval(&m, 0, &out);
    /* Up to ppc photons side by side, the rest of the slots empty. */
    in.valid = next < nphot;
    for (int k = 0; k < ppc; k++) {
      size_t i = next + (size_t)k;
      in.ph[k].n = i < nphot ? np[i] : 0;
      in.ph[k].p_addr = 100u * (uint32_t)i;
      in.ph[k].id = (uint32_t)i;
    }
    if (trace) print_cycle(cycles, &m, &out, &in);
    if (in.valid && out.ready) next = next + (size_t)ppc < nphot ? next + (size_t)ppc : nphot;
    if (!out.ready) busy_cycles++;
    ops += (uint64_t)out.nvalid;
    if (out.nvalid == preu) full_cycles++;
    cycles++;
    aftso_step(&m, &in, 0);
  }
  if (ops != want) { fprintf(stderr, "aftso_util: dispatched %llu of %llu operations\n", (unsigned long long)ops, (unsigned long long)want); return 1; }
  double util = cycles ? (double)ops / ((double)preu * (double)cycles) : 0.0;
  printf("preu=%d buf=%d early_ready=%d photons=%zu ops=%llu mean_np=%.3f cycles=%llu full_cycles=%llu busy_cycles=%llu utilization=%.6f%%\n",
         preu, depth, early, nphot, (unsigned long long)ops, nphot ? (double)ops / (double)nphot : 0.0,
         (unsigned long long)cycles, (unsigned long long)full_cycles, (unsigned long long)busy_cycles, 100.0 * util);
  free(np);
  return 0;
}
