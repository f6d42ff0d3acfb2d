#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every unit at every supported Stages value (add 1-7, mul 1-8, sqr 1-6, div 2-31, wacc 1-5,
# u2f 1-5), Icarus Verilog, the directed list plus 5000 random vectors each, bit for bit against
# the C model at latency = Stages: the stage plans between the named configurations. Full level
# (about two minutes).
# cost: 119 (its seconds in a serial run; the runner starts costly checks first)
exec "$(dirname "$0")/../../scripts/fp32_check.sh" sim-fp32-stages
