// SPDX-License-Identifier: Apache-2.0
/* cosim_sched.c: the co-simulation host's photon scheduler (see cosim_sched.h). */
#include "cosim_sched.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cosim_shadow.h"

#define CAND_BITS   16                 /* a pending candidate's code: slot << CAND_BITS | k */
#define SCAN_PHOTONS 8                 /* eligible photons scored per choice at most */
#define SCAN_CANDS  64                 /* candidates tried per position of one photon at most */
#define NEVER       (-((int64_t)1 << 40))
#define GROUP_OPS   (1u << (COSIM_IDXAW - 1))   /* candidates of one cycle's photons at most */

typedef struct {
    preu_photon_t ph;
    uint32_t *hp;                      /* candidates (distinct hit points) */
    int32_t *link;                     /* next pending code on the same hit point, or -1 */
    int64_t max_last;                  /* the latest last[] of its hit points when last looked at */
    uint32_t n, cap;
    int deps;                          /* hit points on which an older pending photon comes first */
} slot_t;

struct cosim_sched {
    cosim_sched_opts_t opt;
    cosim_sched_emit_fn emit;
    void *user;
    cosim_shadow_t *sh;
    slot_t *slot;
    int *order, count;                 /* pending slots, oldest first */
    int *free_slot, nfree;
    int32_t *fifo_head, *fifo_tail;    /* per hit point: pending codes in photon order */
    int64_t *last;                     /* per hit point: latest (predicted) issue cycle */
    uint32_t tail[COSIM_MAX_PREU];     /* hit points of the last NumPreu operations streamed */
    int tail_pos;
    uint32_t *ord, *best_ord;          /* scratch: a candidate order, the best one so far */
    uint32_t *bk, *mult;               /* scratch: candidates' banks, candidates per bank */
    uint32_t scratch_cap;
    uint64_t photons, moved;
};

cosim_sched_t *cosim_sched_new(const cosim_sched_opts_t *opt, cosim_sched_emit_fn emit, void *user)
{
    cosim_sched_t *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    s->opt = *opt;
    if (s->opt.window < 1) s->opt.window = 1;
    if (s->opt.window > (1 << (31 - CAND_BITS)) - 1) s->opt.window = (1 << (31 - CAND_BITS)) - 1;
    s->emit = emit;
    s->user = user;
    const size_t nhp = (size_t)1 << COSIM_HPAW, w = (size_t)s->opt.window;
    if (s->opt.ppc < 1) s->opt.ppc = 1;
    if (s->opt.ppc > COSIM_MAX_PPC) s->opt.ppc = COSIM_MAX_PPC;
    s->sh = cosim_shadow_new(opt->preu, opt->hp_bank_w, opt->win, s->opt.ppc, opt->reg_flow);
    s->slot = calloc(w, sizeof *s->slot);
    s->order = malloc(w * sizeof *s->order);
    s->free_slot = malloc(w * sizeof *s->free_slot);
    s->fifo_head = malloc(nhp * sizeof *s->fifo_head);
    s->fifo_tail = malloc(nhp * sizeof *s->fifo_tail);
    s->last = malloc(nhp * sizeof *s->last);
    if (!s->sh || !s->slot || !s->order || !s->free_slot || !s->fifo_head || !s->fifo_tail || !s->last) {
        cosim_sched_free(s);
        return NULL;
    }
    for (size_t h = 0; h < nhp; h++) { s->fifo_head[h] = s->fifo_tail[h] = -1; s->last[h] = NEVER; }
    for (int i = 0; i < s->opt.window; i++) s->free_slot[i] = s->opt.window - 1 - i;
    s->nfree = s->opt.window;
    return s;
}

void cosim_sched_free(cosim_sched_t *s)
{
    if (!s) return;
    if (s->slot)
        for (int i = 0; i < s->opt.window; i++) { free(s->slot[i].hp); free(s->slot[i].link); }
    free(s->slot);
    free(s->order);
    free(s->free_slot);
    free(s->fifo_head);
    free(s->fifo_tail);
    free(s->last);
    free(s->ord);
    free(s->best_ord);
    free(s->bk);
    free(s->mult);
    cosim_shadow_free(s->sh);
    free(s);
}

void cosim_sched_stats(const cosim_sched_t *s, cosim_sched_stats_t *st)
{
    st->photons = s->photons;
    st->moved = s->moved;
    memcpy(st->cnt, s->sh->cnt, sizeof st->cnt);
}

/* Cost, in lane-cycles, of issuing hit point h in cycle c beside the banks gb[0..ng). */
static int64_t op_cost(const cosim_sched_t *s, uint32_t h, int64_t c, const uint32_t *gb, int ng)
{
    const int64_t np = s->opt.preu;
    int64_t cost = 0, d = c - s->last[h];
    const int64_t W = s->opt.win;
    if (d <= W) cost += np * (d < 0 ? W + 1 : W + 1 - d);
    uint32_t b = pree_hp_bank(h, s->opt.hp_bank_w);
    for (int i = 0; i < ng; i++)
        if (gb[i] == b) { cost += np; break; }
    return cost;
}

/* Score photon sl streamed behind L buffered operations whose first issues in cycle base;
 * writes its candidate order to s->ord. */
static int64_t score(cosim_sched_t *s, slot_t *sl, int64_t L, int64_t base)
{
    const int np = s->opt.preu;
    uint32_t gb[COSIM_MAX_PREU];
    int ng = 0;
    /* The last L mod NumPreu operations streamed share the photon's first issue cycle. */
    for (int i = (int)(L % np); i > 0; i--)
        gb[ng++] = pree_hp_bank(s->tail[(s->tail_pos + np - i) % np], s->opt.hp_bank_w);
    memcpy(s->ord, sl->hp, sl->n * sizeof *s->ord);
    int64_t cost = 0, max_last = NEVER;
    for (uint32_t k = 0; k < sl->n; k++)
        if (s->last[sl->hp[k]] > max_last) max_last = s->last[sl->hp[k]];
    sl->max_last = max_last;
    /* Each candidate's bank and how many of the candidates not yet placed share it: among
     * equally cheap candidates the one whose bank is most crowded goes first, which spreads
     * a bank's candidates over the issue cycles. */
    uint32_t *bk = s->bk, *mult = s->mult;
    const int crowd = s->opt.reorder && sl->n <= SCAN_CANDS;
    for (uint32_t k = 0; k < sl->n; k++) {
        bk[k] = pree_hp_bank(s->ord[k], s->opt.hp_bank_w);
        mult[k] = 1;
        if (crowd)
            for (uint32_t j = 0; j < k; j++)
                if (bk[j] == bk[k]) { mult[j]++; mult[k]++; }
    }
    for (uint32_t k = 0; k < sl->n; k++) {
        int64_t q = L + (int64_t)k, c = base + q / np;
        if (q % np == 0) ng = 0;
        uint32_t pick = k;
        int64_t best = op_cost(s, s->ord[k], c, gb, ng);
        if (s->opt.reorder)
            for (uint32_t j = k + 1; j < sl->n && j < k + SCAN_CANDS; j++) {
                if (best == 0 && !crowd) break;
                int64_t cj = op_cost(s, s->ord[j], c, gb, ng);
                if (cj < best || (cj == best && mult[j] > mult[pick])) { best = cj; pick = j; }
            }
        uint32_t t = s->ord[k]; s->ord[k] = s->ord[pick]; s->ord[pick] = t;
        t = bk[k]; bk[k] = bk[pick]; bk[pick] = t;
        t = mult[k]; mult[k] = mult[pick]; mult[pick] = t;
        if (crowd)
            for (uint32_t j = k + 1; j < sl->n; j++) mult[j] -= bk[j] == bk[k];
        gb[ng++] = bk[k];
        cost += best;
    }
    /* Lanes left empty in its first cycle (AFTSO-HpUOC then offers fewer than NumPreu). */
    int64_t have = L + (int64_t)sl->n;
    if (have < np) cost += 4 * (np - have);
    return cost;
}

static int grow_scratch(cosim_sched_t *s, uint32_t n)
{
    if (n <= s->scratch_cap) return 0;
    uint32_t cap = s->scratch_cap ? s->scratch_cap : 64;
    while (cap < n) cap *= 2;
    uint32_t *a = realloc(s->ord, cap * sizeof *a);
    if (!a) return -1;
    s->ord = a;
    uint32_t *b = realloc(s->best_ord, cap * sizeof *b);
    if (!b) return -1;
    s->best_ord = b;
    uint32_t *c = realloc(s->bk, cap * sizeof *c);
    if (!c) return -1;
    s->bk = c;
    uint32_t *m = realloc(s->mult, cap * sizeof *m);
    if (!m) return -1;
    s->mult = m;
    s->scratch_cap = cap;
    return 0;
}

/* Choose a photon of the group (the photons taken in one cycle) behind `queued` operations of
 * the group's earlier photons, among those with at most `budget` candidates (the oldest eligible
 * one always fits in the first pick, first = 1), and send it. The shadow model is in its
 * combinational phase. Returns 1 when taken, 0 when none fits, -1 on failure; *n_out and *p_out
 * describe the photon taken. */
static int take_one(cosim_sched_t *s, int64_t queued, uint32_t budget, int first, uint32_t *n_out, uint32_t *p_out)
{
    const int np = s->opt.preu;
    const int64_t L = (int64_t)cosim_shadow_leftover(s->sh) + queued;
    const int64_t base = (int64_t)s->sh->t + 2 + s->sh->stall;
    int best = -1, best_scored = 0, scanned = 0;
    int64_t best_cost = 0;
    for (int i = 0; i < s->count; i++) {
        slot_t *sl = &s->slot[s->order[i]];
        if (sl->deps || sl->n > budget) continue;
        /* A hit point issued (or due) within win cycles of the photon's last operation
         * means a hazard whatever the order (last[] only grows): count the least cost unscored. */
        int64_t d = base + (L + (int64_t)sl->n - 1) / np - sl->max_last, cost;
        const int64_t W = s->opt.win;
        int scored = d > W;
        if (scored) cost = score(s, sl, L, base);
        else cost = (int64_t)np * (d < 0 ? W + 1 : W + 1 - d);
        if (best < 0 || cost < best_cost) {
            best = i;
            best_cost = cost;
            best_scored = scored;
            if (scored) { uint32_t *t = s->best_ord; s->best_ord = s->ord; s->ord = t; }
        }
        if (cost == 0 || ++scanned >= SCAN_PHOTONS) break;
    }
    if (best < 0) return 0;
    const int si = s->order[best];
    slot_t *sl = &s->slot[si];
    if (!best_scored) {
        score(s, sl, L, base);
        uint32_t *t = s->best_ord; s->best_ord = s->ord; s->ord = t;
    }
    uint32_t p = 0;
    if (s->emit(s->user, &sl->ph, s->best_ord, sl->n, first, s->sh->t, &p)) return -1;
    cosim_shadow_write_idx(s->sh, p, s->best_ord, sl->n);
    /* Predicted issue cycles, and the tail of the stream. */
    for (uint32_t k = 0; k < sl->n; k++) {
        uint32_t h = s->best_ord[k];
        int64_t c = base + (L + (int64_t)k) / np;
        if (c > s->last[h]) s->last[h] = c;
        s->tail[s->tail_pos] = h;
        s->tail_pos = (s->tail_pos + 1) % np;
    }
    /* Leave the hit points' FIFOs: the next photon on each may become eligible. */
    for (uint32_t k = 0; k < sl->n; k++) {
        uint32_t h = sl->hp[k];
        int32_t next = sl->link[k];
        s->fifo_head[h] = next;
        if (next < 0) s->fifo_tail[h] = -1;
        else s->slot[next >> CAND_BITS].deps--;
    }
    s->moved += best != 0;
    s->photons++;
    memmove(s->order + best, s->order + best + 1, (size_t)(s->count - best - 1) * sizeof *s->order);
    s->count--;
    s->free_slot[s->nfree++] = si;
    *n_out = sl->n;
    *p_out = p;
    return 1;
}

/* One cycle of the shadow model, taking up to PhotonsPerCycle pending photons (a group, which
 * the host offers in one cycle) when it is ready; a pick that finds no photon within the
 * group's candidate budget ends the group. */
static int step(cosim_sched_t *s)
{
    uint32_t n[COSIM_MAX_PPC] = {0}, p[COSIM_MAX_PPC] = {0};
    int take = cosim_shadow_eval(s->sh) && s->count > 0;
    if (take) {
        int group = s->count < s->opt.ppc ? s->count : s->opt.ppc;
        int64_t queued = 0;
        for (int k = 0; k < group; k++) {
            uint32_t budget = k ? GROUP_OPS - (uint32_t)queued : UINT32_MAX;
            int r = take_one(s, queued, budget, k == 0, &n[k], &p[k]);
            if (r < 0) return -1;
            if (r == 0) break;
            queued += n[k];
        }
    }
    const int64_t t = (int64_t)s->sh->t;
    cosim_shadow_edge(s->sh, take, n, p);
    for (int i = 0; i < s->sh->n_iss; i++)
        if (s->last[s->sh->iss_hp[i]] < t) s->last[s->sh->iss_hp[i]] = t;
    return 0;
}

int cosim_sched_add(cosim_sched_t *s, const preu_photon_t *ph, const uint32_t *hps, uint32_t n)
{
    if (n == 0) return 0;
    if (n >= (1u << CAND_BITS) || grow_scratch(s, n)) return -1;
    while (s->count == s->opt.window)
        if (step(s)) return -1;
    const int si = s->free_slot[--s->nfree];
    slot_t *sl = &s->slot[si];
    if (n > sl->cap) {
        uint32_t *hp = realloc(sl->hp, n * sizeof *hp);
        if (!hp) { s->nfree++; return -1; }
        sl->hp = hp;
        int32_t *link = realloc(sl->link, n * sizeof *link);
        if (!link) { s->nfree++; return -1; }
        sl->link = link;
        sl->cap = n;
    }
    sl->ph = *ph;
    sl->n = n;
    sl->deps = 0;
    sl->max_last = NEVER;
    memcpy(sl->hp, hps, n * sizeof *hps);
    for (uint32_t k = 0; k < n; k++) {
        uint32_t h = hps[k];
        int32_t code = (int32_t)((uint32_t)si << CAND_BITS | k);
        sl->link[k] = -1;
        if (s->fifo_tail[h] < 0) s->fifo_head[h] = code;
        else {
            int32_t tl = s->fifo_tail[h];
            s->slot[tl >> CAND_BITS].link[tl & ((1 << CAND_BITS) - 1)] = code;
            sl->deps++;
        }
        s->fifo_tail[h] = code;
    }
    s->order[s->count++] = si;
    return 0;
}

int cosim_sched_flush(cosim_sched_t *s)
{
    while (s->count > 0)
        if (step(s)) return -1;
    /* Run the model dry so that its counters cover the whole stream. */
    while (!cosim_shadow_idle(s->sh))
        if (step(s)) return -1;
    return 0;
}

int cosim_sched_offer(cosim_sched_t *s, int hung, size_t max_cand, const preu_photon_t *ph, const uint32_t *hps,
                      size_t n, cosim_direct_fn direct, void *user, char *err, size_t errlen)
{
    if (hung) return -1;
    for (size_t k = 0; k < n; k += max_cand) {   /* n 0: nothing for the PREE to do, not sent */
        const size_t m = n - k < max_cand ? n - k : max_cand;
        if (!s) {
            if (direct(user, ph, hps + k, m)) return -1;
        } else if (cosim_sched_add(s, ph, hps + k, (uint32_t)m)) {
            snprintf(err, errlen, "photon scheduler: out of memory");
            return -1;
        }
    }
    return 0;
}
