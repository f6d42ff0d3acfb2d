#!/usr/bin/env bash
# pree_fp32_div #(.Stages(8)) (the divider's deeper configuration, latency 8), Icarus Verilog:
# self-checking testbench over a vector file from tb/fp32/fp32_vecgen (directed list plus 20000
# random). Fails on any mismatch.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-iv-div8
