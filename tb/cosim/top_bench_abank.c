// SPDX-License-Identifier: Apache-2.0
/* top_bench_abank.c: the top bench's abank scenario, a stream with misplaced index entries
 * (tb/cosim/top_bench_abank.h). */
#include "top_bench_abank.h"

#include <stdlib.h>
#include <string.h>
#include "bench_draw.h"

#define IDX_DEPTH (1u << COSIM_IDXAW)

int mis_init(mis_stream_t *m, size_t photons, size_t max_cand)
{
    memset(m, 0, sizeof *m);
    size_t pe = photons ? photons : 1, ee = pe * max_cand;
    m->e_addr = malloc(ee * sizeof *m->e_addr);
    m->e_hp = malloc(ee * sizeof *m->e_hp);
    m->e_need = malloc(ee * sizeof *m->e_need);
    m->ph = malloc(pe * sizeof *m->ph);
    m->p_addr = malloc(pe * sizeof *m->p_addr);
    m->p_n = malloc(pe * sizeof *m->p_n);
    m->p_eend = malloc(pe * sizeof *m->p_eend);
    m->p_start = malloc(pe * sizeof *m->p_start);
    return m->e_addr && m->e_hp && m->e_need && m->ph && m->p_addr && m->p_n && m->p_eend && m->p_start ? 0 : -1;
}

void mis_free(mis_stream_t *m)
{
    free(m->e_addr); free(m->e_hp); free(m->e_need); free(m->ph);
    free(m->p_addr); free(m->p_n); free(m->p_eend); free(m->p_start);
}

/* Place one photon at a random padding of 0..2P-1 entries after the previous one. */
void mis_add(mis_stream_t *m, int preu, const preu_photon_t *ph, const uint32_t *cand, size_t n, uint64_t *rng)
{
    if (n == 0) return;   /* dropped by the PREE anyway: not sent */
    uint64_t p = m->alloc_end + draw_u32(rng) % (2u * (uint32_t)preu);
    /* Entries p .. p+n-1 overwrite those of every photon that starts before p + n - depth. */
    while (m->oldest < m->nph && m->p_start[m->oldest] + IDX_DEPTH < p + n) m->oldest++;
    for (size_t k = 0; k < n; k++) {   /* the k-th operation reads entry p + n - 1 - k */
        m->e_addr[m->ne] = (uint32_t)((p + n - 1 - k) & (IDX_DEPTH - 1));
        m->e_hp[m->ne] = cand[k];
        m->e_need[m->ne] = (uint32_t)m->oldest;
        m->ne++;
    }
    m->ph[m->nph] = *ph;
    m->p_addr[m->nph] = (uint32_t)(p & (IDX_DEPTH - 1));
    m->p_n[m->nph] = (uint32_t)n;
    m->p_eend[m->nph] = m->ne;
    m->p_start[m->nph] = p;
    m->nph++;
    m->alloc_end = p + n;
}

/* Stream it into the RTL (docs/pree_top.md, "Host protocol"): each cycle up to P entries in
 * order, in distinct banks, once their photons_done condition holds; the head photon once its
 * entries are written, except in random gaps. Leaves the photon input idle afterwards. */
int misplaced_stream(cosim_rtl_t *rtl, const mis_stream_t *m, int preu, double gap, uint64_t *rng)
{
    cosim_in_t *in = cosim_rtl_in(rtl);
    size_t e = 0, p = 0;
    uint64_t guard = 0;
    int ready = cosim_rtl_ph_ready(rtl);
    in->cnt_en = 1;
    while (p < m->nph) {
        uint32_t done = cosim_rtl_photons_done(rtl), used = 0;
        int nw = 0;
        while (nw < preu && e < m->ne && m->e_need[e] <= done && !(used & 1u << (m->e_addr[e] % (uint32_t)preu))) {
            used |= 1u << (m->e_addr[e] % (uint32_t)preu);
            in->idx_we[nw] = 1;
            in->idx_addr[nw] = m->e_addr[e];
            in->idx_data[nw] = m->e_hp[e];
            nw++;
            e++;
        }
        for (int j = nw; j < preu; j++) in->idx_we[j] = 0;
        in->ph_valid = m->p_eend[p] <= e && !(gap > 0 && (double)draw_u32(rng) / 2147483648.0 < gap);
        memcpy(in->ph_pos[0], m->ph[p].pos, sizeof in->ph_pos[0]);
        memcpy(in->ph_phi[0], m->ph[p].phi, sizeof in->ph_phi[0]);
        in->ph_paddr[0] = m->p_addr[p];
        in->ph_n[0] = m->p_n[p];
        for (int j = 1; j < COSIM_MAX_PPC; j++) in->ph_n[j] = 0;   /* one photon a cycle */
        int take = in->ph_valid && ready;   /* ph_ready_o depends on the state only */
        cosim_rtl_tick(rtl);
        ready = cosim_rtl_ph_ready(rtl);
        if (take) p++;
        if (++guard > 100000000ull) return -1;
    }
    in->ph_valid = 0;
    for (int j = 0; j < preu; j++) in->idx_we[j] = 0;
    return 0;
}

