#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Controllers in simulation: the Verilator benches compare pree_aftso_hpuoc and pree_adiso_rec
# cycle by cycle with their C models (plus an operation scoreboard and exactly-once address
# coverage for N = 0..2000), the Icarus benches replay the C models' vectors; NumPreu 4/8/16
# (Icarus also 1 and 2, EarlyReady 1), and the wide intakes of pree_top's 8- and 16-PREU builds (PhotonsPerCycle 2 into 8 entries,
# 4 into 16) against the same model (model/aftso_rule.c).
# level: quick
set -u
cd "$(dirname "$0")/../.."
aftso=(build/ctrl/aftso_p4_e0/aftso_bench build/ctrl/aftso_p4_e1/aftso_bench
       build/ctrl/aftso_p8_e1/aftso_bench build/ctrl/aftso_p16_e1/aftso_bench
       build/ctrl/aftso_p8_e1_b8_w2/aftso_bench build/ctrl/aftso_p16_e1_b16_w4/aftso_bench)
adiso=(build/ctrl/adiso_p4/adiso_bench build/ctrl/adiso_p8/adiso_bench build/ctrl/adiso_p16/adiso_bench)
vvps=()
for c in p1_e1 p2_e1 p4_e0 p4_e1 p8_e0 p8_e1 p16_e0 p16_e1; do vvps+=(build/ctrl/icarus/aftso_$c); done
for p in 1 2 4 8 16; do vvps+=(build/ctrl/icarus/adiso_p$p); done
targets=("${aftso[@]}" "${adiso[@]}")
for v in "${vvps[@]}"; do targets+=("$v.vvp" "$v.ncyc"); done
if ! make -s "${targets[@]}"; then echo "FAIL: build; rerun: make ${targets[*]}"; exit 1; fi

fail=0
run() {
  local out
  if out=$("$@" 2>&1); then echo "$out" | tail -1
  else echo "$out" | tail -25; echo "FAIL; rerun: $*"; fail=1; fi
}
for b in "${aftso[@]}" "${adiso[@]}"; do run "$b"; done
for v in "${vvps[@]}"; do run vvp -N "$v.vvp" "+stim=$v.stim" "+exp=$v.exp" "+ncyc=$(cat "$v.ncyc")"; done
exit $fail
