#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# pree_top under Icarus (tb/cosim/top_tb.v over tb/cosim/top_vecgen.c vectors): the host protocol
# with random, one-hit-point, dense-pixel, mixed and misplaced-index runs for 1, 2, 4, 8 and 16 PREUs,
# every hit-point and pixel word against the fp32 model; then the mutants of pree_top.v (hazard
# stall off, same-cycle duplicate check off) must fail with mismatches. Runs and mutants are
# listed in mk/top_icarus.mk (make sim-top-icarus).
# cost: 184 (its seconds in a serial run; the runner starts costly checks first)
set -u
cd "$(dirname "$0")/../.."
build=${BUILD:-build}
if ! make -s BUILD="$build" sim-top-icarus; then
  echo "FAIL; reproduce: make BUILD=$build sim-top-icarus"
  exit 1
fi
