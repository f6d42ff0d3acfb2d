// SPDX-License-Identifier: Apache-2.0
/* pree_config.h: GENERATED from config/pree_config.json by scripts/pree_config.py (make config): do not edit.
 * The fp32 units' Stages (a unit's latency is Stages + InRegs), the PREU's latencies that
 * follow from them (the co-simulation models' parameters are in host/). */
#ifndef PREE_CONFIG_H
#define PREE_CONFIG_H

/* Each unit's Stages range and its default Stages with PipeFast 0 and 1. */
#define PREE_ADD_STAGES_MIN 1
#define PREE_ADD_STAGES_MAX 7
#define PREE_ADD_STAGES_PF0 2
#define PREE_ADD_STAGES_PF1 7
#define PREE_MUL_STAGES_MIN 1
#define PREE_MUL_STAGES_MAX 8
#define PREE_MUL_STAGES_PF0 2
#define PREE_MUL_STAGES_PF1 7
#define PREE_SQR_STAGES_MIN 1
#define PREE_SQR_STAGES_MAX 6
#define PREE_SQR_STAGES_PF0 2
#define PREE_SQR_STAGES_PF1 6
#define PREE_DIV_STAGES_MIN 2
#define PREE_DIV_STAGES_MAX 31
#define PREE_DIV_STAGES_PF0 4
#define PREE_DIV_STAGES_PF1 31
#define PREE_U2F_STAGES_MIN 1
#define PREE_U2F_STAGES_MAX 5
#define PREE_U2F_STAGES_PF0 2
#define PREE_U2F_STAGES_PF1 5
#define PREE_WACC_STAGES_MIN 1
#define PREE_WACC_STAGES_MAX 5
#define PREE_WACC_STAGES_PF0 2
#define PREE_WACC_STAGES_PF1 5

/* pree_top's update hazard window (WIN_UPD: 1 + the PREU's update latency) for a datapath
 * (0 paper, 1 stable) and PipeFast, and its radiance depth (RAD_LAT: ADISO-REC's depth). */
#define PREE_UPDATE_WINDOW(datapath, pipe_fast) \
    ((pipe_fast) ? ((datapath) ? 53 : 49) : ((datapath) ? 13 : 11))
#define PREE_RADIANCE_DEPTH(pipe_fast) ((pipe_fast) ? 64 : 12)

#endif
