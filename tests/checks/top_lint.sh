#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# verilator --lint-only -Wall on pree_top and everything below it, NumPreu 1, 2, 4, 8 and 16, both datapaths:
# the paper's configuration (PipeFast 0, PhotonsPerCycle 1) and the deep, wide one (PipeFast 1,
# PhotonsPerCycle NumPreu / 4 and at least 1, as the co-simulation builds).
# (Full level: it also lints the PREU and fp32 units as instantiated under the top.)
# cost: 180 (its seconds in a serial run; the runner starts costly checks first)
set -u
cd "$(dirname "$0")/../.."
srcs=$(grep -v '^//' rtl/pree.f | tr '\n' ' ')   # the RTL filelist
fail=0
for d in 0 1; do
  for p in 1 2 4 8 16; do
    w=$((p / 4)); [ "$w" -ge 1 ] || w=1
    for g in "-GPipeFast=0 -GPhotonsPerCycle=1" "-GPipeFast=1 -GPhotonsPerCycle=$w"; do
      cmd="verilator --lint-only -Wall -Irtl --top-module pree_top -GNumPreu=$p -GDatapath=$d $g $srcs"
      if ! $cmd; then echo "FAIL: $cmd"; fail=1; fi
    done
  done
done
exit $fail
