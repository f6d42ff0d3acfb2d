#!/usr/bin/env bash
# preu_sim.sh: the PREU RTL (rtl/pree_preu.v) against the C model, both modes and both datapaths
# (paper: model/pree/preu_fp32.c; stable: model/pree/preu_stable.c): the Verilator bench (200,000
# operations each, scoreboard) and the Verilog bench over 4,000 vectors each under Icarus and
# Verilator --binary (all must pass, each datapath with one cycle count in both simulators),
# and a run that switches modes with operations in flight, which the RTL's PREE_ASSERT check
# must stop. Fails on any mismatch, latency or protocol error.
set -u
cd "$(dirname "$0")/../.."
cmd="make -s sim-preu PREU_N=200000 PREU_IV_N=4000 PREU_SEED=1"
out=$($cmd 2>&1); rc=$?
echo "$out" | tail -20
if [ $rc -ne 0 ] || [ "$(echo "$out" | grep -c 'preu_bench: .*PASS')" -ne 2 ] || \
   [ "$(echo "$out" | grep -c 'tb_preu: .*PASS')" -ne 4 ] || \
   ! echo "$out" | grep -q 'mode-switch assertion fired'; then
  echo "preu_sim: FAIL; reproduce with: $cmd"
  exit 1
fi
# The tb_preu lines come as Icarus dp0, Icarus dp1, Verilator dp0, Verilator dp1.
mapfile -t cyc < <(echo "$out" | grep 'tb_preu: .*PASS' | sed 's/.*switches, \([0-9]*\) cycles.*/\1/')
if [ "${cyc[0]}" != "${cyc[2]}" ] || [ "${cyc[1]}" != "${cyc[3]}" ]; then
  echo "preu_sim: Icarus and Verilator disagree on the cycle count (${cyc[*]}); reproduce with: $cmd"; exit 1
fi
echo "preu_sim: ok"
