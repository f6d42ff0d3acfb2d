/* aftso_model.c: cycle-level model of the AFTSO-HpUOC dispatcher, the same rule as the RTL.
 *
 * Dispatch rule (paper 000 Sec. IV.B, with the empty-flag case completed):
 *   accuHP_i = rem_0 + ... + rem_i over the valid entries;
 *   dispatch_i = accuHP_i >= Nset; buf_addr = first i with dispatch_i;
 *   entries before buf_addr go out whole (left side), entry buf_addr whole when accuHP <= Nset,
 *   else its first Nset - accuHP_{buf_addr-1} hit points (right side). When no flag is set the
 *   whole buffer goes out (a partial cycle). Lanes are filled in buffer (= photon) order; a
 *   photon's hit points leave with ref_addr = p_addr + rem - 1, p_addr + rem - 2, ...
 *   Fully dispatched entries are removed and the rest shift to the front; a new photon is
 *   written behind them. Photons with N^P = 0 are accepted and dropped.
 * Back-pressure: ready while an entry is free; with early_ready also when entry 0 leaves whole
 *   in this cycle (not stalled), so a full buffer still takes one photon per cycle.
 */
#include "aftso_model.h"

#include <string.h>

void aftso_init(aftso_model *m, int num_preu, int buf_depth, int data_words, int early_ready)
{
  memset(m, 0, sizeof *m);
  m->num_preu = num_preu;
  m->buf_depth = buf_depth;
  m->data_words = data_words;
  m->early_ready = early_ready;
}

/* accu[i] = accuHP_i, 64-bit because four 32-bit counts can exceed 2^32. */
static void accumulate(const aftso_model *m, uint64_t accu[AFTSO_MAX_BUF])
{
  uint64_t sum = 0;
  for (int i = 0; i < m->buf_depth; i++) {
    if (i < m->count) sum += m->buf[i].rem;
    accu[i] = sum;
  }
}

/* The input is accepted this cycle (see the back-pressure rule in the header). */
static int input_ready(const aftso_model *m, const uint64_t accu[AFTSO_MAX_BUF], int stall)
{
  if (m->count < m->buf_depth) return 1;
  return m->early_ready && !stall && accu[0] <= (uint64_t)m->num_preu;
}

void aftso_eval(const aftso_model *m, int stall, aftso_out *out)
{
  uint64_t accu[AFTSO_MAX_BUF];
  memset(out, 0, sizeof *out);
  accumulate(m, accu);
  uint64_t total = m->count ? accu[m->count - 1] : 0;
  out->ready = input_ready(m, accu, stall);
  out->empty = m->count == 0;
  out->nvalid = total < (uint64_t)m->num_preu ? (int)total : m->num_preu;
  /* Lane l takes the hit point number l of the buffer in photon order. */
  for (int l = 0; l < out->nvalid; l++) {
    int e = 0;
    while (accu[e] <= (uint64_t)l) e++;
    uint64_t before = e ? accu[e - 1] : 0;
    uint32_t t = (uint32_t)((uint64_t)l - before);
    const aftso_entry *b = &m->buf[e];
    out->ref_addr[l] = b->p_addr + b->rem - 1u - t;
    out->id[l] = b->id;
    memcpy(out->data[l], b->data, sizeof b->data);
    out->last[l] = t == b->rem - 1u;
  }
}

void aftso_step(aftso_model *m, const aftso_in *in, int stall)
{
  uint64_t accu[AFTSO_MAX_BUF];
  accumulate(m, accu);
  int accept = in->valid && input_ready(m, accu, stall);
  /* Count the entries that leave whole, then shift and trim the partial one. */
  int nfull = 0;
  if (!stall)
    while (nfull < m->count && accu[nfull] <= (uint64_t)m->num_preu) nfull++;
  if (nfull < m->count && !stall)
    m->buf[nfull].rem = (uint32_t)(accu[nfull] - (uint64_t)m->num_preu);
  for (int i = 0; i + nfull < m->count; i++) m->buf[i] = m->buf[i + nfull];
  m->count -= nfull;
  for (int i = m->count; i < m->buf_depth; i++) memset(&m->buf[i], 0, sizeof m->buf[i]);
  /* Append the accepted photon unless it affects no hit point. */
  if (accept && in->n != 0) {
    aftso_entry *b = &m->buf[m->count++];
    memset(b, 0, sizeof *b);
    memcpy(b->data, in->data, (size_t)m->data_words * sizeof in->data[0]);
    b->id = in->id;
    b->p_addr = in->p_addr;
    b->rem = in->n;
  }
}
