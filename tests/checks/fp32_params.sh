#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Each pipelined binary32 unit refuses its own out-of-range parameters at elaboration, however it
# is instantiated: a Stages value beyond either end of its range, InRegs 2 or PipeFast 2 stops
# verilator --lint-only with a missing module named after the problem, at the unit as the top and
# through pree_top (MulStages 9).
# cost: 5 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
n=0
refused() {   # top, parameter, expected module name
  if verilator --lint-only -Wall -Irtl -y rtl --top-module "$1" -G"$2" "rtl/$1.v" >"$TMP/bad.log" 2>&1; then
    fail "$1 elaborated with $2"
  fi
  grep -q "Cannot find file containing module: '$3'" "$TMP/bad.log" \
    || fail "$1 with $2: no message naming $3: $(head -2 "$TMP/bad.log")"
  n=$((n + 1))
}
for u in "pree_fp32_add 1 7" "pree_fp32_mul 1 8" "pree_fp32_sqr 1 6" "pree_fp32_div 2 31" \
         "pree_wacc 1 5" "pree_u64_to_f32 1 5"; do
  set -- $u
  refused "$1" "Stages=$(($2 - 1))" "${1}_stages_is_$2_to_$3"
  refused "$1" "Stages=$(($3 + 1))" "${1}_stages_is_$2_to_$3"
  refused "$1" "InRegs=2" "pree_fp32_unit_inregs_is_0_or_1"
  refused "$1" "PipeFast=2" "${1}_pipefast_is_0_or_1"
done
refused pree_top "MulStages=9" "pree_fp32_mul_stages_is_1_to_8"
echo "ok: $n out-of-range parameters stop elaboration with a named module"
