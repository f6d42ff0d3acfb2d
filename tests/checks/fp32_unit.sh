#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The fp32 bench configurations of the configuration table (config/pree_config.json,
# "fp32_benches"), one check each, named fp32_<sim>_<configuration>: sim vl, the Verilator bench
# (the directed list plus FP32_QUICK, 1 million, random operations with random valid gaps), or
# iv, the Icarus testbench over a vector file from tb/fp32/fp32_vecgen (the directed list plus
# 20000 random); bit for bit against the C model (model/pree/fp32_ops.h, wide_acc.h), at the
# latency the table gives. Fails on any mismatch. The table sets each one's level (the Verilator
# models of the deep configurations are built on demand, so those are full level).
# Usage: bash tests/checks/fp32_unit.sh [fp32_vl_add ...]   (none: every case in turn)
# cases: python3 scripts/pree_config.py cases
set -u
cd "$(dirname "$0")/../.."
cases=$(python3 scripts/pree_config.py cases) || exit 2
[ $# -gt 0 ] || set -- $(cut -d' ' -f1 <<<"$cases")
fail=0
for name in "$@"; do
  line=$(grep "^$name " <<<"$cases") || {
    echo "fp32_unit.sh: no case $name in config/pree_config.json (python3 scripts/pree_config.py cases)"
    exit 2
  }
  echo "== $line"
  sim=${name#fp32_}; cfg=${sim#*_}; sim=${sim%%_*}
  scripts/fp32_check.sh "sim-fp32-$sim-$cfg" || fail=1
done
exit $fail
