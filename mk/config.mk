# SPDX-License-Identifier: Apache-2.0
# config.mk: GENERATED from config/pree_config.json by scripts/pree_config.py (make config): do not edit.

# Each unit's module and Stages range (a unit's latency is Stages + InRegs).
FP32_STAGES_add := 1 2 3 4 5 6 7
FP32_STAGES_mul := 1 2 3 4 5 6 7 8
FP32_STAGES_sqr := 1 2 3 4 5 6
FP32_STAGES_div := 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31
FP32_STAGES_u2f := 1 2 3 4 5
FP32_STAGES_wacc := 1 2 3 4 5
FP32_TOP_add := pree_fp32_add
FP32_TOP_mul := pree_fp32_mul
FP32_TOP_sqr := pree_fp32_sqr
FP32_TOP_div := pree_fp32_div
FP32_TOP_u2f := pree_u64_to_f32
FP32_TOP_wacc := pree_wacc
FP32_TOP_cmp := pree_fp32_cmp
FP32_PIPELINED := add mul sqr div u2f wacc

# The fp32 bench configurations: <name> := <unit> <PipeFast> <Stages, or - for PipeFast's>
# <latency> [ecp5]. FP32_UNITS: built for the regression; FP32_FAST: the units' PipeFast 1
# forms; FP32_DEEP: built on demand.
FP32_CFG_add := add 0 - 2
FP32_CFG_mul := mul 0 - 2
FP32_CFG_sqr := sqr 0 - 2
FP32_CFG_div := div 0 - 4
FP32_CFG_cmp := cmp 0 - 0
FP32_CFG_div8 := div 0 8 8
FP32_CFG_wacc := wacc 0 - 2
FP32_CFG_u2f := u2f 0 - 2
FP32_CFG_add_fast := add 1 - 7
FP32_CFG_mul_fast := mul 1 - 7
FP32_CFG_sqr_fast := sqr 1 - 6
FP32_CFG_div_fast := div 1 - 31
FP32_CFG_wacc_fast := wacc 1 - 5
FP32_CFG_u2f_fast := u2f 1 - 5
FP32_CFG_div2 := div 0 2 2
FP32_CFG_div12 := div 0 12 12
FP32_CFG_div20 := div 0 20 20
FP32_CFG_mul_ecp5 := mul 1 - 7 ecp5
FP32_CFG_sqr_ecp5 := sqr 1 - 6 ecp5
FP32_UNITS := add mul sqr div cmp div8 wacc u2f
FP32_FAST := add_fast mul_fast sqr_fast div_fast wacc_fast u2f_fast
FP32_DEEP := add_fast mul_fast sqr_fast div_fast wacc_fast u2f_fast div2 div12 div20 mul_ecp5 sqr_ecp5

# The co-simulation models' pree_top parameters: widths, and per PREU count its banks and
# photons a cycle; the PREU counts with models; the regression's models (paper, stable and
# PipeFast 1 counts, further tags, and the AXI wrapper's).
COSIM_WIDTH_PARAMS := -GHpAW=18 -GIdxAW=12 -GPxAW=17 -GCntW=16
COSIM_HPB_1 := 4
COSIM_PXB_1 := 2
COSIM_PPC_1 := 1
COSIM_HPB_2 := 5
COSIM_PXB_2 := 3
COSIM_PPC_2 := 1
COSIM_HPB_4 := 6
COSIM_PXB_4 := 4
COSIM_PPC_4 := 1
COSIM_HPB_8 := 7
COSIM_PXB_8 := 5
COSIM_PPC_8 := 2
COSIM_HPB_16 := 8
COSIM_PXB_16 := 6
COSIM_PPC_16 := 4
COSIM_ALL_PREUS := 1 2 4 8 16
COSIM_DATAPATHS := p s
COSIM_PREUS := 4 8 16
COSIM_STABLE_PREUS ?= 4
COSIM_FAST_PREUS ?=
COSIM_EXTRA_TAGS := p4f
AXI_REGRESSION_TAGS := p4
AXI_QUICK_TAGS := p8 p16f
