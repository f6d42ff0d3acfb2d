// SPDX-License-Identifier: Apache-2.0
/* aftso_model.c: cycle-level model of the AFTSO-HpUOC dispatcher, the same rule as the RTL: the
 * rule of model/pree/aftso_rule.c (accumulate, dispatch, back-pressure, intake of PhotonsPerCycle
 * photons) with each photon's payload (data, id) carried to its lanes. */
#include "aftso_model.h"

#include <string.h>

void aftso_init(aftso_model *m, int num_preu, int buf_depth, int ppc, int data_words, int early_ready)
{
  memset(m, 0, sizeof *m);
  aftso_rule_init(&m->rule, num_preu, buf_depth, ppc, early_ready);
  m->data_words = data_words;
}

void aftso_eval(const aftso_model *m, int stall, aftso_out *out)
{
  aftso_rule_offer_t o;
  memset(out, 0, sizeof *out);
  aftso_rule_offer(&m->rule, &o);
  out->ready = aftso_rule_ready(&m->rule, &o, stall);
  out->empty = m->rule.count == 0;
  out->nvalid = o.nvalid;
  for (int l = 0; l < o.nvalid; l++) {
    uint32_t slot = m->rule.e[o.ent[l]].seq % AFTSO_MAX_BUF;
    out->ref_addr[l] = o.ref[l];
    out->id[l] = m->id[slot];
    memcpy(out->data[l], m->data[slot], sizeof m->data[slot]);
    out->last[l] = o.last[l];
  }
}

void aftso_step(aftso_model *m, const aftso_in *in, int stall)
{
  aftso_rule_offer_t o;
  uint32_t n[AFTSO_MAX_PPC], p[AFTSO_MAX_PPC];
  aftso_rule_offer(&m->rule, &o);
  const int take = in->valid && aftso_rule_ready(&m->rule, &o, stall);
  for (int k = 0; k < m->rule.ppc; k++) { n[k] = in->ph[k].n; p[k] = in->ph[k].p_addr; }
  const uint32_t seq0 = m->rule.seq_next;
  const int added = aftso_rule_edge(&m->rule, &o, stall, take, n, p);
  /* Payloads of the appended entries, in slot order (empty slots have none). */
  for (int k = 0, a = 0; a < added; k++) {
    if (in->ph[k].n == 0) continue;
    uint32_t slot = (seq0 + (uint32_t)a++) % AFTSO_MAX_BUF;
    m->id[slot] = in->ph[k].id;
    memset(m->data[slot], 0, sizeof m->data[slot]);
    memcpy(m->data[slot], in->ph[k].data, (size_t)m->data_words * sizeof in->ph[k].data[0]);
  }
}
