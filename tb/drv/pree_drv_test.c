// SPDX-License-Identifier: Apache-2.0
/* pree_drv_test.c: pree_drv on the Verilated pree_axi (4 PREUs, paper datapath: the model of
 * build/pree-cosim-axi-p4) against the C model, bit for bit. A generated case (hit points in a
 * small box, photons among them, each with a random set of distinct candidates; several hit
 * points a pixel): load the hit points and read them back, stream the photons and their
 * candidates in chunks, close the batch, read the hit points, the stream counts and the
 * counters, run the radiance pass and read the pixels; the model applies the same photons in
 * order (preu_update) and sums each pixel in the radiance pass's issue order (adiso_order).
 * Then the error paths: a photon with too many candidates (refused by the driver), a command
 * while a command runs (refused by the wrapper: ERR.CMD_REFUSED; the driver's own refusal while
 * not idle), an unknown command, and a photon over the index table's room sent past the driver
 * (ERR.PH_TOO_BIG, reported by the driver's wait). Prints one line per step; exit 1 on the first
 * difference. Usage: pree_drv_test [--gap P] [--seed S] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "adiso_order.h"
#include "pree_axi_regs.h"
#include "pree_be_verilated.h"
#include "pree_drv.h"
#include "preu_fp32.h"

#define NPREU  4
#define NHP    300
#define NPIX   64
#define NPH    700      /* more than one submission of the driver (512 photons) */
#define MAXC   12       /* candidates a photon at most (0 included) */
#define RAD_DEPTH 12    /* the PREU's radiance latency with PipeFast 0 (pree_axi's pree_top) */
#define OFF(r) ((uint32_t)offsetof(pree_axi_regs_t, r))

static uint64_t rng = 1;
static uint32_t rnd(uint32_t n)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(rng >> 33) % n;
}
static uint32_t f32(double x) { return preu_f32(x); }

static int failures;
static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "ok" : "FAIL", what);
    if (!ok) failures++;
}

static void die(pree_drv_t *d, const char *what, int rc)
{
    fprintf(stderr, "pree_drv_test: %s: %d (%s)\n", what, rc, pree_error(d));
    exit(1);
}

int main(int argc, char **argv)
{
    double gap = 0;
    uint64_t seed = 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--gap") && i + 1 < argc) gap = atof(argv[++i]);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc) seed = strtoull(argv[++i], NULL, 10);
        else { fprintf(stderr, "usage: pree_drv_test [--gap P] [--seed S]\n"); return 2; }
    }
    rng = seed;

    /* The case and the model's hit points. */
    static preu_hp_t model[NHP];
    static pree_hit_point_t hp[NHP], got[NHP];
    for (int i = 0; i < NHP; i++) {
        preu_hp_t *m = &model[i];
        memset(m, 0, sizeof *m);
        for (int c = 0; c < 3; c++) {
            m->pos[c] = f32(rnd(1000) / 1000.0);
            m->f[c] = f32(0.1 + rnd(900) / 1000.0);
        }
        m->r2 = f32(0.04 + rnd(100) / 1000.0);
        hp[i].state[0] = m->tau[0]; hp[i].state[1] = m->tau[1]; hp[i].state[2] = m->tau[2];
        hp[i].state[3] = m->r2; hp[i].state[4] = m->n;
        memcpy(hp[i].pos, m->pos, sizeof m->pos);
        memcpy(hp[i].f, m->f, sizeof m->f);
        hp[i].pixel = (uint32_t)(i % NPIX);
    }
    static pree_photon_t ph[NPH];
    static uint32_t cand[NPH * MAXC];
    size_t ncand = 0, nonempty = 0;
    for (int k = 0; k < NPH; k++) {
        const uint32_t base = rnd(NHP);
        for (int c = 0; c < 3; c++) {
            ph[k].pos[c] = f32(rnd(1000) / 1000.0);
            ph[k].phi[c] = f32(rnd(1000) / 500.0);
        }
        ph[k].n_cand = rnd(MAXC + 1);
        for (uint32_t j = 0; j < ph[k].n_cand; j++) cand[ncand + j] = (base + 7 * j) % NHP;   /* distinct */
        ncand += ph[k].n_cand;
        nonempty += ph[k].n_cand != 0;
    }
    const uint32_t ne = preu_n_emitted(NPH);

    pree_backend_t be;
    char err[256];
    if (pree_be_verilated_open(&be, NPREU, 0, gap, seed, NULL, err, sizeof err)) {
        fprintf(stderr, "pree_drv_test: %s\n", err);
        return 1;
    }
    pree_drv_t *d;
    int rc = pree_open(&d, &be);
    if (rc) die(d, "pree_open", rc);
    const pree_config_t *cfg = pree_config(d);
    printf("pree_axi %u.%u.%u: %u PREUs, HpAW %u, PxAW %u, IdxAW %u, datapath %u, %u photon(s) a beat\n",
           cfg->version >> 16 & 0xff, cfg->version >> 8 & 0xff, cfg->version & 0xff, cfg->num_preu,
           cfg->hp_aw, cfg->px_aw, cfg->idx_aw, cfg->datapath, cfg->photons_per_cycle);
    check(cfg->num_preu == NPREU && cfg->datapath == 0 && cfg->hp_words == 12, "CONFIG0/1 as built (4 PREUs, paper)");

    const pree_constants_t k = {.ne = ne, .alpha = PREU_ALPHA, .kappa = 0, .n_hit = NHP};
    if ((rc = pree_set_constants(d, &k))) die(d, "constants", rc);
    if ((rc = pree_load_hit_points(d, 0, hp, NHP))) die(d, "load hit points", rc);
    if ((rc = pree_read_hit_points(d, 0, got, NHP))) die(d, "read hit points", rc);
    check(!memcmp(got, hp, sizeof hp), "hit points read back as loaded");

    /* The update pass: two calls, one batch. */
    if ((rc = pree_counters_enable(d, 1))) die(d, "CTRL", rc);
    size_t c0 = 0;
    for (int i = 0; i < NPH / 2; i++) c0 += ph[i].n_cand;
    if ((rc = pree_send_photons(d, ph, cand, NPH / 2))) die(d, "photons", rc);
    if ((rc = pree_send_photons(d, ph + NPH / 2, cand + c0, NPH - NPH / 2))) die(d, "photons", rc);
    if ((rc = pree_end_batch(d))) die(d, "end of batch", rc);
    if ((rc = pree_counters_enable(d, 0))) die(d, "CTRL", rc);
    size_t at = 0;
    for (int i = 0; i < NPH; i++) {
        const preu_photon_t mp = {{ph[i].pos[0], ph[i].pos[1], ph[i].pos[2]}, {ph[i].phi[0], ph[i].phi[1], ph[i].phi[2]}};
        for (uint32_t j = 0; j < ph[i].n_cand; j++) preu_update(&model[cand[at + j]], &mp, PREU_ALPHA);
        at += ph[i].n_cand;
    }

    uint32_t ph_in, ph_done, cand_in;
    if ((rc = pree_read_stream_counts(d, &ph_in, &ph_done, &cand_in))) die(d, "stream counts", rc);
    printf("PH_IN %u, PH_DONE %u, CAND_IN %u (sent %d photons with %zu candidates, %zu of them with some)\n",
           ph_in, ph_done, cand_in, NPH, ncand, nonempty);
    check(ph_in == nonempty && ph_done == nonempty && cand_in == ncand,
          "PH_IN = PH_DONE = photons with candidates (empty slots are not photons), CAND_IN = candidates");
    uint64_t cnt[PREE_NCNT_MAX], ops = 0;
    if ((rc = pree_read_counters(d, cnt, PREE_NCNT_MAX))) die(d, "counters", rc);
    for (int l = 0; l < NPREU; l++) ops += cnt[7 + l];
    printf("update cycles %llu, operations %llu, utilization %.2f%%\n", (unsigned long long)cnt[0],
           (unsigned long long)ops, cnt[0] ? 100.0 * (double)ops / (NPREU * (double)cnt[0]) : 0.0);
    check(ops == ncand && cnt[0] > 0 && cnt[1] == 0, "counters: operations = candidates, update cycles counted, no radiance cycles");

    if ((rc = pree_read_hit_points(d, 0, got, NHP))) die(d, "read hit points", rc);
    int diff = 0;
    for (int i = 0; i < NHP; i++) {
        const preu_hp_t *m = &model[i];
        const uint32_t st[5] = {m->tau[0], m->tau[1], m->tau[2], m->r2, m->n};
        diff += memcmp(got[i].state, st, sizeof st) || memcmp(got[i].pos, m->pos, sizeof m->pos) ||
                memcmp(got[i].f, m->f, sizeof m->f) || got[i].pixel != hp[i].pixel;
    }
    int accepted = 0;
    for (int i = 0; i < NHP; i++) accepted += model[i].n != 0;
    printf("%d of %d hit points differ from the model (%d accepted a photon)\n", diff, NHP, accepted);
    check(diff == 0 && accepted > NHP / 3, "hit points after the batch equal the model's, bit for bit");

    /* The radiance pass against the model's sums in the issue order. */
    if ((rc = pree_counters_enable(d, 1))) die(d, "CTRL", rc);
    if ((rc = pree_radiance(d, NHP, ne, 0, NPIX))) die(d, "radiance", rc);
    if ((rc = pree_counters_enable(d, 0))) die(d, "CTRL", rc);
    static uint32_t L[NPIX][3], Lm[NPIX][3], order[NHP];
    if ((rc = pree_read_pixels(d, 0, &L[0][0], NPIX))) die(d, "read pixels", rc);
    if (adiso_order(NHP, NPREU, RAD_DEPTH, order)) { fprintf(stderr, "adiso_order failed\n"); return 1; }
    for (int i = 0; i < NHP; i++) preu_radiance(Lm[hp[order[i]].pixel], &model[order[i]], ne);
    int pdiff = 0, lit = 0;
    for (int p = 0; p < NPIX; p++) {
        pdiff += memcmp(L[p], Lm[p], sizeof L[p]) != 0;
        lit += Lm[p][0] != 0;
    }
    printf("%d of %d pixels differ from the model (%d lit)\n", pdiff, NPIX, lit);
    check(pdiff == 0 && lit > 0, "pixels equal the model's, bit for bit");
    if ((rc = pree_read_counters(d, cnt, PREE_NCNT_MAX))) die(d, "counters", rc);
    check(cnt[1] > 0, "counters: radiance cycles counted");

    /* Error paths. */
    pree_photon_t big = {{0}, {0}, cfg->max_cand + 1};
    rc = pree_send_photons(d, &big, cand, 1);
    printf("a photon with %u candidates: %d (%s)\n", big.n_cand, rc, pree_error(d));
    check(rc == PREE_E_ARG, "the driver refuses a photon with more than 2^IdxAW - NumPreu candidates");

    /* A long clear, a second command at once: the wrapper refuses it (ERR.CMD_REFUSED); the
     * driver refuses its own command while not idle. */
    if ((rc = pree_reg_write(d, OFF(PX_BASE), 0)) || (rc = pree_reg_write(d, OFF(PX_COUNT), 4096)) ||
        (rc = pree_reg_write(d, OFF(CMD), 3)) || (rc = pree_reg_write(d, OFF(CMD), 4)))
        die(d, "raw commands", rc);
    rc = pree_clear_pixels(d, 0, 1);
    printf("a command while one runs: %d (%s)\n", rc, pree_error(d));
    check(rc == PREE_E_BUSY, "the driver refuses a command while STATUS.IDLE is 0");
    uint32_t st = 0;
    for (int i = 0; i < 100000 && !(st & PREE_AXI_REGS__STATUS__IDLE_bm); i++)
        if ((rc = pree_reg_read(d, OFF(STATUS), &st))) die(d, "STATUS", rc);
    rc = pree_check_err(d);
    printf("after it: %d (%s)\n", rc, pree_error(d));
    check(rc == PREE_E_HW && strstr(pree_error(d), "CMD_REFUSED"), "ERR.CMD_REFUSED for the command written while one ran");
    check(pree_check_err(d) == PREE_OK, "ERR cleared by the driver");
    if ((rc = pree_reg_write(d, OFF(IRQ_STATUS), 3))) die(d, "IRQ_STATUS", rc);
    if ((rc = pree_reg_write(d, OFF(CMD), 7))) die(d, "CMD", rc);
    rc = pree_check_err(d);
    check(rc == PREE_E_HW && strstr(pree_error(d), "CMD_REFUSED"), "ERR.CMD_REFUSED for an unknown command");

    /* Past the driver: a photon over the index table's room; the streams stall, the driver's wait
     * reports ERR. */
    uint32_t words[PREE_PH_SLOT_WORDS] = {0};
    words[6] = cfg->max_cand + 1;
    static uint32_t many[4096 + NPREU];
    for (uint32_t j = 0; j < cfg->max_cand + 1; j++) many[j] = j % NHP;
    if (be.submit(be.ctx, PREE_STREAM_PH, words, PREE_PH_SLOT_WORDS, PREE_PH_SLOT_WORDS, 0) ||
        be.submit(be.ctx, PREE_STREAM_CAND, many, cfg->max_cand + 1, NPREU, 0)) {
        fprintf(stderr, "pree_drv_test: submit: %s\n", be.error(be.ctx));
        return 1;
    }
    pree_set_timeout(d, 1);
    rc = pree_end_batch(d);
    printf("a photon with %u candidates past the driver: %d (%s)\n", cfg->max_cand + 1, rc, pree_error(d));
    check(rc == PREE_E_HW && strstr(pree_error(d), "PH_TOO_BIG"), "ERR.PH_TOO_BIG reported by the wait");

    printf("%llu cycles\n", (unsigned long long)pree_be_verilated_cycles(&be));
    pree_close(d);
    printf("%s\n", failures ? "FAIL" : "pass");
    return failures != 0;
}
