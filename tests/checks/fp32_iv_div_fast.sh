#!/usr/bin/env bash
# pree_fp32_div #(.PipeFast(1)) (the deep configuration, docs/fpga.md), Icarus Verilog: self-checking
# testbench over a vector file from tb/fp32/fp32_vecgen (directed list plus 20000 random), bit
# for bit against the C model, at the latency that mk/fp32.mk pins. Fails on any mismatch.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-iv-div_fast
