// SPDX-License-Identifier: Apache-2.0
/* pree_probe.c: board bring-up of pree_axi through pree_drv's UIO back end (build/drv/pree_probe).
 * Opens the register block and the DMA channels, prints VERSION, CONFIG0/1 and STATUS, and with
 * --loopback N loads N hit points of a known pattern from address 0 (s_axis_hp) and reads them
 * back (CMD 2, m_axis), comparing every word.
 *
 * Usage: pree_probe --regs DEV[@ADDR] --dma-hp DEV[@ADDR] --dma-ph DEV[@ADDR] --dma-cand DEV[@ADDR]
 *                   --dma-m DEV[@ADDR] --buf /dev/udmabufN [--irq] [--loopback N]
 * DEV is a /dev/uioN device (map 0), or /dev/mem with @ADDR the block's physical address (hex). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pree_be_uio.h"
#include "pree_drv.h"

static int map_arg(pree_uio_map_t *m, char *arg)
{
    char *at = strchr(arg, '@');
    m->dev = arg;
    m->base = 0;
    if (!at) return 0;
    *at = '\0';
    char *end;
    m->base = strtoull(at + 1, &end, 16);
    return *end != '\0';
}

int main(int argc, char **argv)
{
    pree_uio_config_t cfg;
    memset(&cfg, 0, sizeof cfg);
    long loop = 0;
    static const char *const dma_opt[PREE_DMA_N] = {"--dma-hp", "--dma-ph", "--dma-cand", "--dma-m"};
    for (int i = 1; i < argc; i++) {
        int bad = i + 1 >= argc && strcmp(argv[i], "--irq");
        int known = 0;
        if (!strcmp(argv[i], "--irq")) { cfg.use_irq = 1; continue; }
        if (!bad && !strcmp(argv[i], "--regs")) { bad = map_arg(&cfg.regs, argv[++i]); known = 1; }
        for (int c = 0; c < PREE_DMA_N && !bad && !known; c++)
            if (!strcmp(argv[i], dma_opt[c])) { bad = map_arg(&cfg.dma[c], argv[++i]); known = 1; }
        if (!bad && !known && !strcmp(argv[i], "--buf")) { cfg.buf_dev = argv[++i]; known = 1; }
        if (!bad && !known && !strcmp(argv[i], "--loopback")) {
            char *end;
            loop = strtol(argv[++i], &end, 10);
            bad = *end || loop < 1;
            known = 1;
        }
        if (bad || !known) {
            fprintf(stderr, "pree_probe: bad argument '%s' (usage: pree_probe --regs DEV[@ADDR] --dma-hp ... --dma-ph ... --dma-cand ... --dma-m ... --buf DEV [--irq] [--loopback N])\n", argv[i]);
            return 2;
        }
    }
    int missing = !cfg.regs.dev || !cfg.buf_dev;
    for (int c = 0; c < PREE_DMA_N; c++) missing |= !cfg.dma[c].dev;
    if (missing) {
        fprintf(stderr, "pree_probe: --regs, --dma-hp, --dma-ph, --dma-cand, --dma-m and --buf are all needed\n");
        return 2;
    }

    pree_backend_t be;
    char err[256];
    if (pree_be_uio_open(&be, &cfg, err, sizeof err)) {
        fprintf(stderr, "pree_probe: %s\n", err);
        return 1;
    }
    pree_drv_t *d;
    int rc = pree_open(&d, &be);
    if (rc) {
        fprintf(stderr, "pree_probe: %s\n", pree_error(d));
        pree_close(d);
        return 1;
    }
    const pree_config_t *c = pree_config(d);
    uint32_t st = 0;
    rc = pree_reg_read(d, 0x018, &st);
    printf("pree_axi %u.%u.%u: NumPreu %u, HpAW %u, PxAW %u, IdxAW %u, Datapath %u, HpBankW %u, PxBankW %u, CntW %u, PhotonsPerCycle %u; STATUS 0x%x\n",
           c->version >> 16 & 0xff, c->version >> 8 & 0xff, c->version & 0xff, c->num_preu, c->hp_aw, c->px_aw,
           c->idx_aw, c->datapath, c->hp_bank_w, c->px_bank_w, c->cnt_w, c->photons_per_cycle, st);
    if (!rc && loop > 0) {
        if ((uint64_t)loop > (1ull << c->hp_aw)) loop = (long)(1ull << c->hp_aw);
        pree_hit_point_t *hp = calloc((size_t)loop, sizeof *hp), *back = calloc((size_t)loop, sizeof *back);
        if (!hp || !back) { fprintf(stderr, "pree_probe: out of memory\n"); return 1; }
        for (long i = 0; i < loop; i++) {
            uint32_t *w = (uint32_t *)&hp[i];
            for (size_t k = 0; k < sizeof hp[i] / sizeof *w; k++) w[k] = (uint32_t)(i * 0x9e3779b9u + k * 0x85ebca6bu);
            for (unsigned k = c->state_words; k < 10; k++) hp[i].state[k] = 0;   /* not carried */
            hp[i].pixel &= (1u << c->px_aw) - 1;
        }
        rc = pree_load_hit_points(d, 0, hp, (size_t)loop);
        if (!rc) rc = pree_read_hit_points(d, 0, back, (size_t)loop);
        long diff = 0;
        for (long i = 0; i < loop && !rc; i++) diff += memcmp(&hp[i], &back[i], sizeof hp[i]) != 0;
        if (!rc) printf("loopback: %ld hit points written and read back, %ld differ\n", loop, diff);
        if (!rc && diff) rc = PREE_E_STREAM;
        free(hp);
        free(back);
    }
    if (rc && rc != PREE_E_STREAM) fprintf(stderr, "pree_probe: %s\n", pree_error(d));
    pree_close(d);
    return rc ? 1 : 0;
}
