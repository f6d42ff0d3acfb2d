#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# verilator --lint-only -Wall on pree_top and everything below it as its own top, NumPreu 1, 2, 4,
# 8 and 16, both datapaths, in the deep configuration (PipeFast 1, PhotonsPerCycle NumPreu / 4 or 1,
# as the co-simulation builds). The paper configuration (PipeFast 0, one photon a cycle) is linted
# inside pree_axi at the same NumPreu and datapaths by axi_lint.sh, which elaborates pree_top with
# exactly those parameters; `make lint-top` runs every combination.
# cost: 90 (its seconds in a serial run; the runner starts costly checks first)
set -u
cd "$(dirname "$0")/../.."
srcs=$(grep -v '^//' rtl/pree.f | tr '\n' ' ')   # the RTL filelist
fail=0
for d in 0 1; do
  for p in 1 2 4 8 16; do
    w=$((p / 4)); [ "$w" -ge 1 ] || w=1
    cmd="verilator --lint-only -Wall -Irtl --top-module pree_top -GNumPreu=$p -GDatapath=$d -GPipeFast=1 -GPhotonsPerCycle=$w $srcs"
    if ! $cmd; then echo "FAIL: $cmd"; fail=1; fi
  done
done
exit $fail
