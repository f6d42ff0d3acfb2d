#!/usr/bin/env bash
# pree_wacc (the stable datapath's wide accumulator add), Icarus Verilog: self-checking testbench
# over a vector file from tb/fp32/fp32_vecgen (directed list plus 20000 random). Fails on any
# mismatch.
# level: quick
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-iv-wacc
