#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# AFTSO-HpUOC utilization on geometric N^P (mean 32, 300 k photons back to back) stays at its
# measured level (docs/controllers.md), and the RTL takes exactly as many cycles as the model
# on the same 20 k photons for NumPreu 4/8/16.
set -u
cd "$(dirname "$0")/../.."
need=(build/ctrl/aftso_util build/ctrl/aftso_p4_e0/aftso_bench build/ctrl/aftso_p4_e1/aftso_bench
      build/ctrl/aftso_p8_e1/aftso_bench build/ctrl/aftso_p16_e1/aftso_bench)
if ! make -s "${need[@]}"; then echo "FAIL: build; rerun: make ${need[*]}"; exit 1; fi
fail=0
field() { sed -n "s/.* $1=\([0-9.]*\).*/\1/p"; }

# preu early-ready minimum-utilization-percent
while read -r p e min; do
  cmd="build/ctrl/aftso_util --preu $p --early-ready $e --geo 32 --photons 300000 --seed 3"
  out=$($cmd) || { echo "FAIL; rerun: $cmd"; fail=1; continue; }
  echo "$out"
  u=$(echo "$out" | field utilization)
  if ! awk -v u="$u" -v m="$min" 'BEGIN { exit !(u >= m) }'; then
    echo "FAIL: utilization $u% below $min%; rerun: $cmd"; fail=1
  fi
done <<'LIST'
4 1 99.99
8 1 99.95
16 1 99.0
4 0 99.99
LIST

np=build/ctrl/np_check.txt
build/ctrl/aftso_util --geo 32 --photons 20000 --seed 9 --write-np "$np" >/dev/null || { echo "FAIL: writing $np"; exit 1; }
for p in 4 8 16; do
  mcmd="build/ctrl/aftso_util --preu $p --np-file $np"
  rcmd="build/ctrl/aftso_p${p}_e1/aftso_bench --np-file $np"
  m=$($mcmd) || { echo "FAIL; rerun: $mcmd"; fail=1; continue; }
  r=$($rcmd) || { echo "$r"; echo "FAIL; rerun: $rcmd"; fail=1; continue; }
  echo "$r"
  mc=$(echo "$m" | field cycles); rc=$(echo "$r" | field cycles)
  if [ -z "$mc" ] || [ "$mc" != "$rc" ]; then
    echo "FAIL: NumPreu=$p model cycles '$mc' != RTL cycles '$rc'; rerun: $mcmd; $rcmd"; fail=1
  fi
done
exit $fail
