#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The binary32 units through Yosys synth_xilinx (7-series): fails on a latch, a combinational
# loop (check -assert) or a Yosys error; writes build/fp32/synth/resources.md.
# cost: 254 (its seconds in a serial run; the runner starts costly checks first)
exec "$(dirname "$0")/../../scripts/fp32_check.sh" synth-fp32
