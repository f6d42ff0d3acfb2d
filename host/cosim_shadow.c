// SPDX-License-Identifier: Apache-2.0
/* cosim_shadow.c: cycle model of pree_top's update issue path (see cosim_shadow.h). Each block
 * names the RTL block it mirrors. */
#include "cosim_shadow.h"

#include <stdlib.h>
#include <string.h>

#define IDX_MASK ((1u << COSIM_IDXAW) - 1u)

cosim_shadow_t *cosim_shadow_new(int preu, int hp_bank_w, int win, int ppc, int reg_flow)
{
    if (win < 1 || win > SHADOW_WIN_MAX) return NULL;   /* the in-flight rows are a fixed array */
    cosim_shadow_t *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    s->inf_cnt = calloc(1u << COSIM_HPAW, 1);
    if (!s->inf_cnt) { free(s); return NULL; }
    s->preu = preu;
    s->hp_bank_w = hp_bank_w;
    s->win = win;
    s->reg_flow = reg_flow != 0;
    aftso_rule_init(&s->buf, preu, 4 * ppc, ppc, 1);
    return s;
}

void cosim_shadow_free(cosim_shadow_t *s)
{
    if (!s) return;
    free(s->inf_cnt);
    free(s);
}

/* The lanes B issues from: R's, or with reg_flow the queue's head slot's (u_queue). */
static const shadow_lanes_t *live_lanes(const cosim_shadow_t *s)
{
    return s->reg_flow ? &s->q[s->head] : &s->r;
}

/* The index addresses of the offer stage A reads (u_offer): the buffer's slot 0, or the
 * controller's. */
static const uint32_t *read_refs(const cosim_shadow_t *s)
{
    return s->reg_flow ? s->o_ref[0] : s->ref;
}

void cosim_shadow_write_idx(cosim_shadow_t *s, uint32_t p, const uint32_t *hps, uint32_t n)
{
    for (uint32_t k = 0; k < n; k++) s->idx[(p + n - 1u - k) & IDX_MASK] = hps[k];
}

int cosim_shadow_eval(cosim_shadow_t *s)
{
    const int np = s->preu;
    const uint32_t all = (1u << np) - 1u;
    /* AFTSO-HpUOC offer: lane l takes the l-th hit point of the buffer in photon order. */
    aftso_rule_offer(&s->buf, &s->off);
    s->total = s->off.total;
    s->nvalid = s->off.nvalid;
    for (int l = 0; l < s->nvalid; l++) s->ref[l] = s->off.ref[l] & IDX_MASK;
    const uint32_t ctl_valid = (1u << s->nvalid) - 1u;
    /* The offer stage A reads (u_offer): the buffer's slot 0 (reg_flow), else the controller's. */
    const uint32_t o_valid = s->reg_flow ? s->o_valid[0] : ctl_valid;
    const uint32_t *o_ref = read_refs(s);
    /* Stage B (b_issue): a prefix of the live lanes (those A read last, or with reg_flow the
     * queue's head slot), each free of hazard, dup and bank. */
    const shadow_lanes_t *live = live_lanes(s);
    const uint32_t bpend = live->pend;
    const uint32_t *bhp = live->hp;
    uint32_t iss = 0;
    int pre = 1, cause = 0;
    for (int l = 0; l < np; l++) {
        int pend = (bpend >> l) & 1, haz = 0, dup = 0, bcf = 0;
        if (pend) {
            haz = s->inf_cnt[bhp[l]] != 0;
            uint32_t bl = pree_hp_bank(bhp[l], s->hp_bank_w);
            for (int m = 0; m < l; m++)
                if ((bpend >> m) & 1) {
                    if (bhp[m] == bhp[l]) dup = 1;
                    else if (pree_hp_bank(bhp[m], s->hp_bank_w) == bl) bcf = 1;
                }
        }
        int ok = pend && pre && !haz && !dup && !bcf;
        if (ok) iss |= 1u << l;
        if (pend && !ok && !cause) cause = haz ? CNT_HAZ : dup ? CNT_DUP : CNT_BANK;
        pre = pre && (!pend || ok);
    }
    s->iss = iss;
    /* a_go: B empties in this cycle; with reg_flow, R is empty or a slot of the queue is. */
    s->a_go = s->reg_flow ? !s->r.pend || !s->q[0].pend || !s->q[1].pend : (s->r.pend & ~iss) == 0;
    /* Stage A (a_lanes): read in lane order, one lane per index bank (ref mod NumPreu). */
    uint32_t a_valid = o_valid & ~s->a_done, a_rd = 0;
    pre = 1;
    for (int l = 0; l < np; l++) {
        int v = (a_valid >> l) & 1, conf = 0;
        for (int m = 0; m < l; m++)
            if (((a_valid >> m) & 1) && ((o_ref[m] ^ o_ref[l]) & (uint32_t)(np - 1)) == 0) conf = 1;
        int rd = s->a_go && v && !conf && pre;
        if (rd) a_rd |= 1u << l;
        pre = pre && (!v || rd);
    }
    s->a_valid = a_valid;
    s->a_rd = a_rd;
    /* a_all: every lane of the offer A holds is read. The controller is stalled until then, or
     * with reg_flow while the offer buffer is full. */
    s->a_all = (a_valid & ~a_rd) == 0;
    s->stall = s->reg_flow ? s->o_n == 2 : !s->a_all;
    /* Counter cause (stall_cause): the first blocked lane in B, else A's conflict, else starved. */
    if (iss != all && !cause) cause = live->a_short ? CNT_ABANK : CNT_STARVE;
    s->cause = cause;
    /* AFTSO-HpUOC ready: PhotonsPerCycle entries free after this cycle's whole departures. */
    s->ready = aftso_rule_ready(&s->buf, &s->off, s->stall);
    return s->ready;
}

uint64_t cosim_shadow_leftover(const cosim_shadow_t *s)
{
    return s->stall ? s->total : s->total - (uint64_t)s->nvalid;
}

void cosim_shadow_edge(cosim_shadow_t *s, int take, const uint32_t *n, const uint32_t *p)
{
    const int np = s->preu;
    /* Counters (counters block; the model counts from its first cycle). */
    s->cnt[CNT_CYC_UPD]++;
    if (s->cause) s->cnt[s->cause]++;
    /* In-flight window: drop the row issued win cycles ago, add this cycle's issues. */
    int *row_n = &s->inf_n[s->inf_pos];
    uint32_t *row = s->inf_hp[s->inf_pos];
    for (int k = 0; k < *row_n; k++) s->inf_cnt[row[k]]--;
    *row_n = 0;
    s->n_iss = 0;
    const uint32_t *bhp = live_lanes(s)->hp;
    for (int l = 0; l < np; l++)
        if ((s->iss >> l) & 1) {
            row[(*row_n)++] = bhp[l];
            s->inf_cnt[bhp[l]]++;
            s->iss_hp[s->n_iss++] = bhp[l];
            s->cnt[CNT_OPS0 + l]++;
        }
    s->inf_pos = (s->inf_pos + 1) % s->win;
    /* B's queue (pree_top_queue, reg_flow): R moves into the head slot when it is empty, else
     * into the other when that is; the head passes on once its lanes have all issued. */
    if (s->reg_flow) {
        shadow_lanes_t *h = &s->q[s->head], *o = &s->q[!s->head];
        shadow_lanes_t *to = !s->r.pend ? NULL : !h->pend ? h : !o->pend ? o : NULL;
        const int pass = h->pend && !(h->pend & ~s->iss);
        h->pend &= ~s->iss;
        if (to) *to = s->r;
        s->head ^= pass;
    }
    /* Stage B registers (R): the lanes A read (index-table data), or what is left pending. */
    if (s->a_go) {
        for (int l = 0; l < np; l++)
            if ((s->a_rd >> l) & 1) s->r.hp[l] = s->idx[read_refs(s)[l]];
        s->r.pend = s->a_rd;
        s->r.a_short = (s->a_valid & ~s->a_rd) != 0;
    } else if (!s->reg_flow) {
        s->r.pend &= ~s->iss;
    }
    s->a_done = s->a_all ? 0 : s->a_done | s->a_rd;
    /* Offer buffer (u_offer): slot 0 is left once A has read all of it and slot 1 moves up; the
     * controller's offer, taken while slot 1 is free, is stored when it has a lane. */
    if (s->reg_flow) {
        if (s->a_all && s->o_n > 0) {
            s->o_valid[0] = s->o_valid[1];
            memcpy(s->o_ref[0], s->o_ref[1], sizeof s->o_ref[0]);
            s->o_valid[1] = 0;
            s->o_n--;
        }
        if (!s->stall && s->nvalid > 0) {
            s->o_valid[s->o_n] = (1u << s->nvalid) - 1u;
            memcpy(s->o_ref[s->o_n], s->ref, sizeof s->o_ref[0]);
            s->o_n++;
        }
    }
    /* AFTSO-HpUOC edge: whole entries leave, the partial one is trimmed, the taken photons
     * are appended. */
    aftso_rule_edge(&s->buf, &s->off, s->stall, take, n, p);
    s->t++;
}

int cosim_shadow_idle(const cosim_shadow_t *s)
{
    if (s->buf.count || s->o_n || s->r.pend || s->q[0].pend || s->q[1].pend) return 0;
    for (int r = 0; r < s->win; r++)
        if (s->inf_n[r]) return 0;
    return 1;
}
