#!/usr/bin/env bash
# preu_sim.sh: the PREU RTL (rtl/pree_preu.v) against the C model, both modes and both datapaths
# (paper: model/pree/preu_fp32.c; stable: model/pree/preu_stable.c), in both pipeline configurations:
# PipeFast 0 (the paper's units) with the Verilator bench (200,000 operations each, scoreboard)
# and the Verilog bench over 4,000 vectors each under Icarus and Verilator --binary; PipeFast 1
# (the deep plans: update 45 / 48 stages, radiance 59) at a reduced size, 50,000 and 1,000. All
# must pass, each configuration with one cycle count in both simulators; and a run that
# switches modes with operations in flight, which the RTL's PREE_ASSERT check must stop. Fails
# on any mismatch, latency or protocol error.
set -u
cd "$(dirname "$0")/../.."
fail=0
# $1: configurations, $2: the make command; the tb_preu lines come as Icarus per configuration,
# then Verilator per configuration.
run() {
  local n=$(echo $1 | wc -w) rc
  out=$($2 2>&1); rc=$?
  echo "$out" | grep -E 'PASS|FAIL|fired|rror' | tail -20
  if [ $rc -ne 0 ] || [ "$(echo "$out" | grep -c 'preu_bench: .*PASS')" -ne $n ] || \
     [ "$(echo "$out" | grep -c 'tb_preu: .*PASS')" -ne $((2 * n)) ]; then
    echo "preu_sim: FAIL; reproduce with: $2"; fail=1; return
  fi
  mapfile -t cyc < <(echo "$out" | grep 'tb_preu: .*PASS' | sed 's/.*switches, \([0-9]*\) cycles.*/\1/')
  for ((i = 0; i < n; i++)); do
    if [ "${cyc[$i]}" != "${cyc[$((i + n))]}" ]; then
      echo "preu_sim: Icarus and Verilator disagree on the cycle count (${cyc[*]}); reproduce with: $2"; fail=1
    fi
  done
}
run "0 1" "make -s sim-preu PREU_CFGS=0_1 PREU_N=200000 PREU_IV_N=4000 PREU_SEED=1"
if ! echo "$out" | grep -q 'mode-switch assertion fired'; then
  echo "preu_sim: FAIL: the mode-switch assertion did not fire"; fail=1
fi
run "0f 1f" "make -s sim-preu-vl sim-preu-iv sim-preu-vlbin PREU_CFGS=0f_1f PREU_N=50000 PREU_IV_N=1000 PREU_SEED=1"
if [ $fail -eq 0 ]; then echo "preu_sim: ok"; fi
exit $fail
