#!/usr/bin/env bash
# pree_fp32_div #(.Stages(12)) (latency 12), Icarus Verilog: self-checking testbench over the directed list plus 20000 random vectors,
# bit for bit against model/pree/fp32_ops.h. Full level. Fails on any mismatch.
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-iv-div12
