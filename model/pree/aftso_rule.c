// SPDX-License-Identifier: Apache-2.0
/* aftso_rule.c: the AFTSO-HpUOC accumulate-and-dispatch rule (see aftso_rule.h). */
#include "aftso_rule.h"

#include <string.h>

void aftso_rule_init(aftso_rule_t *b, int num_preu, int buf_depth, int ppc, int early_ready)
{
    memset(b, 0, sizeof *b);
    b->num_preu = num_preu;
    b->buf_depth = buf_depth;
    b->ppc = ppc;
    b->early_ready = early_ready;
}

void aftso_rule_offer(const aftso_rule_t *b, aftso_rule_offer_t *o)
{
    const uint64_t np = (uint64_t)b->num_preu;
    uint64_t sum = 0;
    o->nwhole = 0;
    for (int i = 0; i < b->buf_depth; i++) {
        if (i < b->count) sum += b->e[i].rem;
        o->accu[i] = sum;
        if (i < b->count && sum <= np) o->nwhole = i + 1;
    }
    o->total = sum;
    o->nvalid = sum < np ? (int)sum : b->num_preu;
    for (int l = 0, e = 0; l < o->nvalid; l++) {
        while (o->accu[e] <= (uint64_t)l) e++;
        uint32_t t = (uint32_t)((uint64_t)l - (e ? o->accu[e - 1] : 0));
        o->ent[l] = e;
        o->ref[l] = b->e[e].p_addr + b->e[e].rem - 1u - t;
        o->last[l] = t == b->e[e].rem - 1u;
    }
}

int aftso_rule_ready(const aftso_rule_t *b, const aftso_rule_offer_t *o, int stall)
{
    int leaving = b->early_ready && !stall ? o->nwhole : 0;
    return b->buf_depth - b->count + leaving >= b->ppc;
}

int aftso_rule_edge(aftso_rule_t *b, const aftso_rule_offer_t *o, int stall, int take,
                    const uint32_t *n, const uint32_t *p_addr)
{
    if (!stall) {
        const int nfull = o->nwhole;
        if (nfull < b->count) b->e[nfull].rem = (uint32_t)(o->accu[nfull] - (uint64_t)b->num_preu);
        memmove(b->e, b->e + nfull, (size_t)(b->count - nfull) * sizeof b->e[0]);
        b->count -= nfull;
    }
    int added = 0;
    for (int k = 0; take && k < b->ppc; k++)
        if (n[k] != 0) {
            b->e[b->count++] = (aftso_rule_ent_t){p_addr[k], n[k], b->seq_next++};
            added++;
        }
    return added;
}
