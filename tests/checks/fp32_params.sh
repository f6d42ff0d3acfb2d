#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Each pipelined binary32 unit refuses its own out-of-range parameters at elaboration, however it
# is instantiated: a Stages value beyond either end of its range, InRegs 2 or PipeFast 2 stops
# verilator --lint-only with a missing module named after the problem, at the unit as the top and
# through pree_preu (MulStages 9). pree_top alone refuses its PREU parameters the same way, under
# verilator --lint-only and Icarus, whatever its datapath (WaccStages and U2fStages too in the
# paper datapath, which builds no such unit): each *Stages one beyond either end of its unit's
# range, Datapath 2, PipeFast 2; and both ends of every range elaborate (lint-clean).
# cost: 10 (its seconds in a serial run; the runner starts costly checks first)
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
top_refused() {   # parameter, expected module name: pree_top under Verilator, then Icarus
  refused pree_top "$1" "$2"
  if iverilog -g2005 -Irtl -y rtl -o "$TMP/bad.vvp" -s pree_top -Ppree_top."$1" rtl/pree_top.v \
       >"$TMP/bad.log" 2>&1; then
    fail "Icarus elaborated pree_top with $1"
  fi
  grep -q "^ *$2 referenced" "$TMP/bad.log" \
    || fail "Icarus, pree_top with $1: no message naming $2: $(head -2 "$TMP/bad.log")"
}
lo=() hi=()   # pree_top's -G / -P settings at the low and high end of every unit's range
for u in "pree_fp32_add 1 7 AddStages" "pree_fp32_mul 1 8 MulStages" "pree_fp32_sqr 1 6 SqrStages" \
         "pree_fp32_div 2 31 DivStages" "pree_wacc 1 5 WaccStages" "pree_u64_to_f32 1 5 U2fStages"; do
  set -- $u
  refused "$1" "Stages=$(($2 - 1))" "${1}_stages_is_$2_to_$3"
  refused "$1" "Stages=$(($3 + 1))" "${1}_stages_is_$2_to_$3"
  refused "$1" "InRegs=2" "pree_fp32_unit_inregs_is_0_or_1"
  refused "$1" "PipeFast=2" "${1}_pipefast_is_0_or_1"
  # pree_top's own check: 0 is the unit's default, so below the range is 1 (div) or -1.
  top="pree_top_$(echo "$4" | tr A-Z a-z)_is_0_or_$2_to_$3"
  top_refused "$4=$(($2 > 1 ? $2 - 1 : -1))" "$top"
  top_refused "$4=$(($3 + 1))" "$top"
  lo+=("$4=$2") hi+=("$4=$3")
done
refused pree_preu "MulStages=9" "pree_fp32_mul_stages_is_1_to_8"
top_refused "Datapath=2" "pree_top_datapath_is_0_paper_or_1_stable"
top_refused "PipeFast=2" "pree_top_pipefast_is_0_or_1"
echo "ok: $n out-of-range parameters stop elaboration with a named module"
# Both ends of every range pass, in the stable datapath (every unit built; one PREU, the smallest
# top): Verilator lint, Icarus.
for set in "${lo[*]} PipeFast=1" "${hi[*]}"; do
  run verilator --lint-only -Wall -Irtl -y rtl --top-module pree_top -GNumPreu=1 -GDatapath=1 \
    $(printf -- '-G%s ' $set) rtl/pree_top.v
  run iverilog -g2005 -Irtl -y rtl -o "$TMP/ok.vvp" -s pree_top -Ppree_top.NumPreu=1 \
    -Ppree_top.Datapath=1 $(printf -- '-Ppree_top.%s ' $set) rtl/pree_top.v
done
echo "ok: pree_top elaborates at both ends of every unit's Stages range"
