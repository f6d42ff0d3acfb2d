#!/usr/bin/env bash
# pree_u64_to_f32 (unsigned 64-bit integer to binary32, round to nearest even), Icarus Verilog:
# self-checking testbench over a vector file from tb/fp32/fp32_vecgen (directed list plus 20000
# random). Fails on any mismatch.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-iv-u2f
