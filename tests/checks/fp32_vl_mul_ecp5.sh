#!/usr/bin/env bash
# pree_fp32_mul #(.PipeFast(1)) as the ECP5 timing flow builds it (PREE_ECP5_DSP, MULT18X18D
# primitives with their own registers, modelled by tb/fpga/MULT18X18D.v), Verilator bench: the
# directed list plus FP32_QUICK (1 million) random operations with random valid gaps, bit for bit
# against the C model. Full level: its Verilator model is built on demand. Fails on any mismatch.
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-vl-mul_ecp5
