#!/usr/bin/env bash
# The binary32 units through Yosys synth_xilinx (7-series): fails on a latch, a combinational
# loop (check -assert) or a Yosys error; writes build/fp32/synth/resources.md.
exec "$(dirname "$0")/../../scripts/fp32_check.sh" synth-fp32
