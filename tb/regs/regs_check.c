// SPDX-License-Identifier: Apache-2.0
/* regs_check.c: the RTL decodes exactly the generated register map. Through AXI4-Lite on the
 * Verilated pree_axi (the model of build/pree-cosim-axi-p4, drv/pree_be_verilated.c), against
 * the table generated from rtl/regs/pree_axi.rdl (tb/regs/pree_axi_regs_table.h):
 *   - every word address of the 4 KiB block: mapped registers read their reset values field by
 *     field (CONFIG0/CONFIG1: the parameters the model was built with, REGS_GPARAMS), bits
 *     outside the fields and unmapped addresses read 0;
 *   - RW fields: written with all ones, a pattern and zero, read back in their positions; RO
 *     registers: written with all ones, unchanged; WO (CMD): reads 0;
 *   - RW1C fields: each set by the event that sets it (a tlast photon, a command, an unknown
 *     command, a photon over the index table's room), exactly its bit, then kept by writing 0
 *     and cleared by writing 1;
 *   - STATUS's fields in their positions while a command, a radiance pass and a pending batch run;
 *   - the counters' region: LO/HI of counter k at 0x100 + 8k, counting when CTRL.CNT_EN is 1,
 *     counters 7 + NumPreu .. 31 reading 0.
 * One line per failure; exit 1 if any. Usage: regs_check */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pree_axi_regs_table.h"
#include "pree_be_verilated.h"

#define RAD_HP 1024   /* hit points of the radiance pass */

static pree_backend_t be;
static int failures;

static void bad(const char *fmt, const char *name, uint32_t off, uint32_t got, uint32_t want)
{
    printf("FAIL: ");
    printf(fmt, name, off, got, want);
    printf("\n");
    failures++;
}

static uint32_t rd(uint32_t off)
{
    uint32_t v = 0;
    if (be.reg_read(be.ctx, off, &v)) { fprintf(stderr, "regs_check: read 0x%03x: %s\n", off, be.error(be.ctx)); exit(1); }
    return v;
}

static void wr(uint32_t off, uint32_t v)
{
    if (be.reg_write(be.ctx, off, v)) { fprintf(stderr, "regs_check: write 0x%03x: %s\n", off, be.error(be.ctx)); exit(1); }
}

static const reg_desc_t *find(const char *name)
{
    for (size_t i = 0; i < REG_MAP_N; i++)
        if (!strcmp(reg_map[i].name, name)) return &reg_map[i];
    fprintf(stderr, "regs_check: the map has no register %s\n", name);
    exit(1);
}

static const reg_field_t *field(const reg_desc_t *r, const char *name)
{
    for (unsigned f = 0; f < r->nfields; f++)
        if (!strcmp(r->field[f].name, name)) return &r->field[f];
    fprintf(stderr, "regs_check: the map has no field %s.%s\n", r->name, name);
    exit(1);
}

static uint32_t mask(const reg_field_t *f) { return f->width == 32 ? 0xffffffffu : ((1u << f->width) - 1) << f->lsb; }
static uint32_t bit(const char *reg, const char *name) { return mask(field(find(reg), name)); }
static uint32_t offset(const char *reg) { return find(reg)->offset; }

/* The value a build-dependent field reads: the model's parameter (REGS_GPARAMS: -GName=value ...). */
static uint32_t param(const char *field_name)
{
    static const char *const names[][2] = {
        {"NUM_PREU", "NumPreu"}, {"HP_AW", "HpAW"}, {"PX_AW", "PxAW"}, {"IDX_AW", "IdxAW"},
        {"DATAPATH", "Datapath"}, {"HP_BANK_W", "HpBankW"}, {"PX_BANK_W", "PxBankW"},
        {"CNT_W", "CntW"}, {"PHOTONS_PER_CYCLE", "PhotonsPerCycle"}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        if (strcmp(names[i][0], field_name)) continue;
        char key[64];
        snprintf(key, sizeof key, "-G%s=", names[i][1]);
        const char *at = strstr(REGS_GPARAMS, key);
        if (at) return (uint32_t)strtoul(at + strlen(key), NULL, 0);
        if (!strcmp(field_name, "PHOTONS_PER_CYCLE")) return 1;   /* pree_axi's default */
    }
    fprintf(stderr, "regs_check: no expected value for the build field %s\n", field_name);
    exit(1);
}

/* Whether word address off holds register r's instance (its index in *i). */
static const reg_desc_t *at(uint32_t off, uint32_t *idx)
{
    for (size_t i = 0; i < REG_MAP_N; i++) {
        const reg_desc_t *r = &reg_map[i];
        for (uint32_t k = 0; k < r->count; k++)
            if (r->offset + k * r->stride == off) { *idx = k; return r; }
    }
    return NULL;
}

/* Reset values, field by field, of every word address. */
static void check_resets(void)
{
    int regs = 0;
    for (uint32_t off = 0; off < 0x1000; off += 4) {
        uint32_t k;
        const reg_desc_t *r = at(off, &k);
        const uint32_t v = rd(off);
        if (!r) {
            if (v) bad("%s 0x%03x reads 0x%08x, expected 0x%08x", "unmapped address", off, v, 0);
            continue;
        }
        regs++;
        uint32_t covered = 0;
        for (unsigned f = 0; f < r->nfields; f++) {
            const reg_field_t *fl = &r->field[f];
            const uint32_t m = mask(fl), got = (v & m) >> fl->lsb;
            const uint32_t want = fl->access == REG_WO ? 0 : fl->has_reset ? fl->reset : param(fl->name);
            covered |= m;
            if (got != want) {
                char name[96];
                snprintf(name, sizeof name, "%s[%u].%s", r->name, k, fl->name);
                bad("%s at 0x%03x reads 0x%x after reset, the map says 0x%x", name, off, got, want);
            }
        }
        if (v & ~covered) bad("%s at 0x%03x: bits 0x%08x outside its fields are set (0x%08x)", r->name, off, v & ~covered, v);
    }
    printf("ok: %d mapped word addresses and %d unmapped ones read as the map says after reset\n", regs, 1024 - regs);
}

/* RW fields in place, RO registers unchanged by writes, WO reads 0. */
static void check_access(void)
{
    int n = 0;
    for (size_t i = 0; i < REG_MAP_N; i++) {
        const reg_desc_t *r = &reg_map[i];
        uint32_t rw = 0, ro = 0;
        for (unsigned f = 0; f < r->nfields; f++) {
            if (r->field[f].access == REG_RW) rw |= mask(&r->field[f]);
            if (r->field[f].access == REG_RO) ro |= mask(&r->field[f]);
        }
        if (!rw && !ro) continue;   /* WO and RW1C: below */
        for (uint32_t k = 0; k < r->count; k++) {
            const uint32_t off = r->offset + k * r->stride, before = rd(off);
            const uint32_t pats[3] = {0xffffffffu, 0xa5c3f00fu, 0};
            for (int p = 0; p < 3; p++) {
                wr(off, pats[p]);
                const uint32_t want = (pats[p] & rw) | (before & ro), got = rd(off);
                if (got != want) bad("%s at 0x%03x reads 0x%08x after a write, the map says 0x%08x", r->name, off, got, want);
            }
            wr(off, before & rw);
            n++;
        }
    }
    printf("ok: %d RW and RO registers written with ones, a pattern and zero, read back as their access says\n", n);
}

static void photon(uint32_t n, int last)
{
    const uint32_t w[PREE_PH_SLOT_WORDS] = {0, 0, 0, 0, 0, 0, n, 0};
    if (be.submit(be.ctx, PREE_STREAM_PH, w, PREE_PH_SLOT_WORDS, PREE_PH_SLOT_WORDS, last)) { fprintf(stderr, "regs_check: %s\n", be.error(be.ctx)); exit(1); }
}

static void settle(void)
{
    if (be.wait(be.ctx, 0, 10) != 1) { fprintf(stderr, "regs_check: the streams did not drain\n"); exit(1); }
}

/* A W1C field: set by its event, exactly its bit; kept by writing 0, cleared by writing 1. */
static void check_w1c(const char *reg, const char *name, void (*event)(void))
{
    const uint32_t off = offset(reg), m = bit(reg, name);
    event();
    uint32_t v = rd(off);
    if (v != m) bad("%s at 0x%03x reads 0x%08x after its event, expected 0x%08x", name, off, v, m);
    wr(off, 0);
    if ((v = rd(off)) != m) bad("%s at 0x%03x reads 0x%08x after writing 0, expected 0x%08x", name, off, v, m);
    wr(off, m);
    if ((v = rd(off))) bad("%s at 0x%03x reads 0x%08x after writing 1, expected 0x%08x", name, off, v, 0);
    printf("ok: %s.%s set by its event alone, kept by 0, cleared by 1\n", reg, name);
}

static void ev_batch(void) { photon(0, 1); settle(); for (int i = 0; i < 10; i++) rd(offset("VERSION")); }
static void ev_cmd(void) { wr(offset("PX_COUNT"), 0); wr(offset("CMD"), 3); for (int i = 0; i < 4; i++) rd(offset("VERSION")); }
static void ev_refused(void) { wr(offset("CMD"), 7); }
static void ev_too_big(void)
{
    const uint32_t idx_aw = param("IDX_AW"), np = param("NUM_PREU");
    photon((1u << idx_aw) - np + 1, 0);
    for (int i = 0; i < 4; i++) rd(offset("VERSION"));
}

/* STATUS in the states its fields name. */
static void check_status(void)
{
    const uint32_t st = offset("STATUS"), idle = bit("STATUS", "IDLE"), core = bit("STATUS", "CORE_IDLE");
    const uint32_t rad = bit("STATUS", "RADIANCE"), busy = bit("STATUS", "CMD_BUSY"), pend = bit("STATUS", "BATCH_PENDING");
    uint32_t v;
    wr(offset("PX_BASE"), 0);
    wr(offset("PX_COUNT"), 2048);
    wr(offset("CMD"), 3);   /* a long clear */
    if ((v = rd(st)) != (busy | core)) bad("%s at 0x%03x reads 0x%08x while a clear runs, expected 0x%08x", "STATUS", st, v, busy | core);
    while (!(rd(st) & idle)) {}
    wr(offset("IRQ_STATUS"), 0xffffffffu);
    /* RAD_HP hit points loaded (zeros, pixel 0: a wrapper may refuse a pass over unloaded ones). */
    static uint32_t hp[RAD_HP * 17];
    const unsigned hw = param("DATAPATH") ? 17 : 12;
    wr(offset("HP_PTR"), 0);
    if (be.submit(be.ctx, PREE_STREAM_HP, hp, (size_t)RAD_HP * hw, hw, 0)) { fprintf(stderr, "regs_check: %s\n", be.error(be.ctx)); exit(1); }
    settle();
    wr(offset("CTRL"), bit("CTRL", "CNT_EN"));
    wr(offset("N_HIT"), RAD_HP);
    wr(offset("CMD"), 1);   /* a radiance pass over them */
    v = rd(st);
    if ((v & ~core) != (busy | rad)) bad("%s at 0x%03x reads 0x%08x while the radiance pass runs, expected 0x%08x (and CORE_IDLE 0)", "STATUS", st, v, busy | rad);
    while (!(rd(st) & idle)) {}
    wr(offset("CTRL"), 0);
    wr(offset("IRQ_STATUS"), 0xffffffffu);
    photon(1, 1);           /* a batch whose photon waits for its candidate */
    for (int i = 0; i < 4; i++) rd(offset("VERSION"));
    if ((v = rd(st)) != (pend | core)) bad("%s at 0x%03x reads 0x%08x while a batch waits, expected 0x%08x", "STATUS", st, v, pend | core);
    const uint32_t c[4] = {0};
    if (be.submit(be.ctx, PREE_STREAM_CAND, c, 1, (unsigned)param("NUM_PREU"), 0)) { fprintf(stderr, "regs_check: %s\n", be.error(be.ctx)); exit(1); }
    settle();
    while (!(rd(st) & idle)) {}
    wr(offset("IRQ_STATUS"), 0xffffffffu);
    printf("ok: STATUS's fields in place while a clear, a radiance pass and a pending batch run\n");
}

/* Counters: the radiance pass above counted cycles in counter 1; 7 + NumPreu .. 31 read 0. */
static void check_counters(void)
{
    const reg_desc_t *lo = find("CNT.LO"), *hi = find("CNT.HI");
    const uint32_t ncnt = 7 + param("NUM_PREU");
    for (uint32_t k = 0; k < lo->count; k++) {
        const uint32_t l = rd(lo->offset + k * lo->stride), h = rd(hi->offset + k * hi->stride);
        if (k >= ncnt && (l || h)) bad("%s at 0x%03x reads 0x%08x beyond the build's counters, expected 0x%08x", "CNT", lo->offset + k * lo->stride, l | h, 0);
        if (k == 1 && (l < RAD_HP / param("NUM_PREU") || h)) bad("%s at 0x%03x (radiance cycles) reads 0x%08x, expected at least 0x%08x", "CNT.LO", lo->offset + k * lo->stride, l, RAD_HP / param("NUM_PREU"));
    }
    printf("ok: counter 1 counted the radiance pass's cycles at 0x%03x; counters %u..%u read 0\n", lo->offset + lo->stride, ncnt, lo->count - 1);
}

int main(void)
{
    char err[256];
    if (pree_be_verilated_open(&be, (int)param("NUM_PREU"), (int)param("DATAPATH"), 0, 1, NULL, err, sizeof err)) {
        fprintf(stderr, "regs_check: %s\n", err);
        return 1;
    }
    printf("map: %zu registers (rtl/regs/pree_axi.rdl); model: pree_axi %s\n", REG_MAP_N, REGS_GPARAMS);
    check_resets();
    check_access();
    uint32_t v;
    if ((v = rd(offset("CMD")))) bad("%s at 0x%03x reads 0x%08x, expected 0x%08x", "CMD (WO)", offset("CMD"), v, 0);
    check_w1c("IRQ_STATUS", "BATCH", ev_batch);
    check_w1c("IRQ_STATUS", "CMD", ev_cmd);
    check_w1c("ERR", "CMD_REFUSED", ev_refused);
    wr(offset("IRQ_STATUS"), 0xffffffffu);
    check_status();
    check_counters();
    for (size_t i = 0; i < REG_MAP_N; i++)   /* every RW1C field has an event above */
        for (unsigned f = 0; f < reg_map[i].nfields; f++)
            if (reg_map[i].field[f].access == REG_RW1C &&
                strcmp(reg_map[i].field[f].name, "BATCH") && strcmp(reg_map[i].field[f].name, "CMD") &&
                strcmp(reg_map[i].field[f].name, "CMD_REFUSED") && strcmp(reg_map[i].field[f].name, "PH_TOO_BIG"))
                bad("%s (0x%03x): a RW1C field with no event in this check (%u, %u)", reg_map[i].field[f].name, reg_map[i].offset, 0, 0);
    check_w1c("ERR", "PH_TOO_BIG", ev_too_big);   /* last: the streams stall until reset */
    be.close(be.ctx);
    printf("%s\n", failures ? "FAIL" : "pass");
    return failures != 0;
}
