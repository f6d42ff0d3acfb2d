#!/usr/bin/env bash
# pree_fp32_mul #(.PipeFast(1)) as the ECP5 timing flow builds it (PREE_ECP5_DSP: its products in
# MULT18X18D primitives holding their own input and output registers, rtl/pree_fp32_dsp_mul.v),
# Icarus Verilog with the primitive's model tb/fpga/MULT18X18D.v: self-checking testbench over a
# vector file from tb/fp32/fp32_vecgen (directed list plus 20000 random), bit for bit against the
# C model, at the deep configuration's latency. Fails on any mismatch.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-iv-mul_ecp5
