// SPDX-License-Identifier: Apache-2.0
/* adiso_model.c: ADISO-REC leaping addresses, Eq. 10, 12 and 13 of paper 000 written out as
 * the recurrences they are, one step per clock edge, as the RTL does.
 *
 *   leaping_value   = floor(N / 2^ceil(log2(Nset * Npip)))                       (10)
 *   leaping_addr_i,0 = start_addr_i,0 = size * i
 *   leaping_addr_i,j = start_addr_i,j            if leaping_addr_i,j-1 + lv >= end_i   (12)
 *                     leaping_addr_i,j-1 + lv   otherwise
 *   start_addr_i,j   = start_addr_i,j-1 + 1      if leaping_addr_i,j-1 + lv >= end_i   (13)
 *                     start_addr_i,j-1          otherwise
 * Group i stops after end_i - size*i addresses. Eq. 11's closed form is kept separately: it
 * equals Eq. 13 only when lv divides the group size (see docs/controllers.md).
 */
#include "adiso_model.h"

#include <string.h>

int adiso_shift(int nset, int npip)
{
  int s = 0;
  while ((1L << s) < (long)nset * npip) s++;
  return s;
}

uint32_t adiso_leaping_value(uint32_t n, int nset, int npip)
{
  return n >> adiso_shift(nset, npip);
}

void adiso_init(adiso_model *m, int nset, int npip)
{
  memset(m, 0, sizeof *m);
  m->nset = nset;
  m->npip = npip;
}

void adiso_eval(const adiso_model *m, adiso_out *out)
{
  memset(out, 0, sizeof *out);
  for (int i = 0; i < m->nset; i++) {
    out->valid[i] = m->rem[i] != 0;
    out->addr[i] = out->valid[i] ? m->leap[i] : 0;
    out->busy |= out->valid[i];
  }
}

static void load(adiso_model *m, uint32_t n)
{
  uint32_t lv = adiso_leaping_value(n, m->nset, m->npip);
  m->n = n;
  m->lv = lv ? lv : 1;
  m->size = n / (uint32_t)m->nset;
  for (int i = 0; i < m->nset; i++) {
    uint32_t base = m->size * (uint32_t)i;
    m->start[i] = base;
    m->leap[i] = base;
    m->end[i] = i == m->nset - 1 ? n : m->size * (uint32_t)(i + 1);
    m->rem[i] = m->end[i] - base;
  }
}

void adiso_step(adiso_model *m, int start, uint32_t n, int stall)
{
  if (start) { load(m, n); return; }
  if (stall) return;
  for (int i = 0; i < m->nset; i++) {
    if (!m->rem[i]) continue;
    m->rem[i]--;
    uint64_t next = (uint64_t)m->leap[i] + m->lv;
    if (next >= m->end[i]) {                 /* past the group: next residue class */
      m->start[i]++;
      m->leap[i] = m->start[i];
    } else {
      m->leap[i] = (uint32_t)next;
    }
  }
}

uint32_t adiso_eq11_start(const adiso_model *m, int i, uint32_t j)
{
  uint32_t per = (m->size + m->lv - 1) / m->lv;   /* ceil(size_group / leaping_value) */
  return m->size * (uint32_t)i + (per ? j / per : 0);
}
