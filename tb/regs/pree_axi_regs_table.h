// SPDX-License-Identifier: Apache-2.0
/* pree_axi_regs_table.h: pree_axi's register map as a table (every register, its fields,
 * their software access and reset values), for the check that the RTL decodes exactly this
 * map (tb/regs/regs_check.c); generated from rtl/regs/pree_axi.rdl by scripts/regs_gen.py (make regs); do not edit. */
#ifndef PREE_AXI_REGS_TABLE_H
#define PREE_AXI_REGS_TABLE_H

#include <stdint.h>

enum { REG_RO, REG_WO, REG_RW, REG_RW1C };

typedef struct {
    const char *name;
    unsigned lsb, width, access;   /* access: REG_* */
    int has_reset;                 /* 0: the value is the build's (CONFIG0, CONFIG1) */
    uint32_t reset;
} reg_field_t;

typedef struct {
    const char *name;
    uint32_t offset, count, stride;   /* count registers at offset + i * stride */
    unsigned nfields;
    reg_field_t field[8];
} reg_desc_t;

static const reg_desc_t reg_map[] = {
    {"VERSION", 0x000u, 1, 0, 3, {{"PATCH", 0, 8, REG_RO, 1, 0x0u}, {"MINOR", 8, 8, REG_RO, 1, 0x0u}, {"MAJOR", 16, 8, REG_RO, 1, 0x2u}}},
    {"CONFIG0", 0x004u, 1, 0, 5, {{"NUM_PREU", 0, 8, REG_RO, 0, 0x0u}, {"HP_AW", 8, 5, REG_RO, 0, 0x0u}, {"PX_AW", 16, 5, REG_RO, 0, 0x0u}, {"IDX_AW", 24, 5, REG_RO, 0, 0x0u}, {"DATAPATH", 31, 1, REG_RO, 0, 0x0u}}},
    {"CONFIG1", 0x008u, 1, 0, 4, {{"HP_BANK_W", 0, 5, REG_RO, 0, 0x0u}, {"PX_BANK_W", 8, 5, REG_RO, 0, 0x0u}, {"CNT_W", 16, 5, REG_RO, 0, 0x0u}, {"PHOTONS_PER_CYCLE", 24, 8, REG_RO, 0, 0x0u}}},
    {"CTRL", 0x010u, 1, 0, 1, {{"CNT_EN", 0, 1, REG_RW, 1, 0x0u}}},
    {"CMD", 0x014u, 1, 0, 1, {{"CMD", 0, 3, REG_WO, 1, 0x0u}}},
    {"STATUS", 0x018u, 1, 0, 5, {{"IDLE", 0, 1, REG_RO, 1, 0x1u}, {"CORE_IDLE", 1, 1, REG_RO, 1, 0x1u}, {"RADIANCE", 2, 1, REG_RO, 1, 0x0u}, {"CMD_BUSY", 3, 1, REG_RO, 1, 0x0u}, {"BATCH_PENDING", 4, 1, REG_RO, 1, 0x0u}}},
    {"IRQ_EN", 0x01Cu, 1, 0, 2, {{"BATCH", 0, 1, REG_RW, 1, 0x0u}, {"CMD", 1, 1, REG_RW, 1, 0x0u}}},
    {"IRQ_STATUS", 0x020u, 1, 0, 2, {{"BATCH", 0, 1, REG_RW1C, 1, 0x0u}, {"CMD", 1, 1, REG_RW1C, 1, 0x0u}}},
    {"ERR", 0x024u, 1, 0, 2, {{"CMD_REFUSED", 0, 1, REG_RW1C, 1, 0x0u}, {"PH_TOO_BIG", 1, 1, REG_RW1C, 1, 0x0u}}},
    {"NE", 0x030u, 1, 0, 1, {{"VALUE", 0, 32, REG_RW, 1, 0x0u}}},
    {"ALPHA", 0x034u, 1, 0, 1, {{"VALUE", 0, 32, REG_RW, 1, 0x0u}}},
    {"KAPPA", 0x038u, 1, 0, 1, {{"VALUE", 0, 32, REG_RW, 1, 0x0u}}},
    {"N_HIT", 0x03Cu, 1, 0, 1, {{"VALUE", 0, 32, REG_RW, 1, 0x0u}}},
    {"HP_PTR", 0x040u, 1, 0, 1, {{"VALUE", 0, 32, REG_RW, 1, 0x0u}}},
    {"HP_COUNT", 0x044u, 1, 0, 1, {{"VALUE", 0, 32, REG_RW, 1, 0x0u}}},
    {"PX_BASE", 0x048u, 1, 0, 1, {{"VALUE", 0, 32, REG_RW, 1, 0x0u}}},
    {"PX_COUNT", 0x04Cu, 1, 0, 1, {{"VALUE", 0, 32, REG_RW, 1, 0x0u}}},
    {"PH_IN", 0x050u, 1, 0, 1, {{"VALUE", 0, 32, REG_RO, 1, 0x0u}}},
    {"PH_DONE", 0x054u, 1, 0, 1, {{"VALUE", 0, 32, REG_RO, 1, 0x0u}}},
    {"CAND_IN", 0x058u, 1, 0, 1, {{"VALUE", 0, 32, REG_RO, 1, 0x0u}}},
    {"CNT.LO", 0x100u, 32, 8, 1, {{"VALUE", 0, 32, REG_RO, 1, 0x0u}}},
    {"CNT.HI", 0x104u, 32, 8, 1, {{"VALUE", 0, 16, REG_RO, 1, 0x0u}}},
};

#define REG_MAP_N (sizeof reg_map / sizeof reg_map[0])

#endif
