#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The quick level of the formal suite (docs/formal.md): every job whose .sby says
# "# level: quick", prove and cover, through scripts/formal-run.sh and the pinned tools of
# make fpga-deps. Each task must PASS; a failure prints the counterexample's .vcd.
# cost: 70 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
run scripts/formal-run.sh quick
