#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# preu_sim.sh: the PREU RTL (rtl/pree_preu.v) against the C model, both modes and both datapaths
# (paper: model/pree/preu_fp32.c; stable: model/pree/preu_stable.c), in both pipeline
# configurations. PipeFast 0 (the paper's units): the Verilator bench (200,000 operations each,
# scoreboard) and the Verilog bench over 4,000 vectors each under Icarus and Verilator --binary
# (each datapath with one cycle count in both simulators), and a run that switches modes with
# operations in flight, which the RTL's PREE_ASSERT check must stop. PipeFast 1 (the deep plans:
# update 48 / 52 stages, radiance 64), at a reduced size: the Verilator bench (50,000 operations
# each). The deep configurations' Verilog bench under Icarus is not run here: its time is in
# elaborating the deep units, not in the vectors (PipeFast 1 paper, 100 vectors, 630 cycles: 449 s
# wall on the shared 2-core machine; 1,000 vectors of both ran over 60 minutes); run it with
# make sim-preu-iv PREU_CFGS=0f_1f PREU_IV_N=100. Fails on any mismatch, latency or protocol error.
# cost: 255 (its seconds in a serial run; the runner starts costly checks first)
set -u
cd "$(dirname "$0")/../.."
fail=0
# $1: configurations, $2: simulators of the Verilog bench (0 none, 1 Icarus, 2 and Verilator), $3: the
# make command. The tb_preu lines come as Icarus per configuration, then Verilator per configuration.
run() {
  local n=$(echo $1 | wc -w) rc
  out=$($3 2>&1); rc=$?
  echo "$out" | grep -E 'PASS|FAIL|fired|rror' | tail -20
  if [ $rc -ne 0 ] || [ "$(echo "$out" | grep -c 'preu_bench: .*PASS')" -ne $n ] || \
     [ "$(echo "$out" | grep -c 'tb_preu: .*PASS')" -ne $(($2 * n)) ]; then
    echo "preu_sim: FAIL; reproduce with: $3"; fail=1; return
  fi
  [ $2 -eq 2 ] || return
  mapfile -t cyc < <(echo "$out" | grep 'tb_preu: .*PASS' | sed 's/.*switches, \([0-9]*\) cycles.*/\1/')
  for ((i = 0; i < n; i++)); do
    if [ "${cyc[$i]}" != "${cyc[$((i + n))]}" ]; then
      echo "preu_sim: Icarus and Verilator disagree on the cycle count (${cyc[*]}); reproduce with: $3"; fail=1
    fi
  done
}
run "0 1" 2 "make -s sim-preu PREU_CFGS=0_1 PREU_N=200000 PREU_IV_N=4000 PREU_SEED=1"
if ! echo "$out" | grep -q 'mode-switch assertion fired'; then
  echo "preu_sim: FAIL: the mode-switch assertion did not fire"; fail=1
fi
run "0f 1f" 0 "make -s sim-preu-vl PREU_CFGS=0f_1f PREU_N=50000 PREU_SEED=1"
if [ $fail -eq 0 ]; then echo "preu_sim: ok"; fi
exit $fail
