#!/usr/bin/env bash
# preu_sim.sh: the PREU RTL (rtl/pree_preu.v) against the C model (model/preu_fp32.c), both modes:
# the Verilator bench (200,000 operations, scoreboard) and the Verilog bench over 4,000 vectors
# under Icarus and Verilator --binary (both must pass, with the same cycle count), and a run that
# switches modes with operations in flight, which the RTL's PREE_ASSERT check must stop.
# Fails on any mismatch, latency or protocol error.
set -u
cd "$(dirname "$0")/../.."
cmd="make -s sim-preu PREU_N=200000 PREU_IV_N=4000 PREU_SEED=1"
out=$($cmd 2>&1); rc=$?
echo "$out" | tail -20
if [ $rc -ne 0 ] || ! echo "$out" | grep -q 'preu_bench: .*PASS' || [ "$(echo "$out" | grep -c 'tb_preu: .*PASS')" -ne 2 ] || \
   ! echo "$out" | grep -q 'mode-switch assertion fired'; then
  echo "preu_sim: FAIL; reproduce with: $cmd"
  exit 1
fi
n=$(echo "$out" | grep 'tb_preu: .*PASS' | sed 's/.*switches, \([0-9]*\) cycles.*/\1/' | sort -u | wc -l)
if [ "$n" -ne 1 ]; then echo "preu_sim: Icarus and Verilator disagree on the cycle count; reproduce with: $cmd"; exit 1; fi
echo "preu_sim: ok"
