#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# pree_top against the C model (build/cosim/top_bench): random traces, all photons on one hit
# point, pixels with 40 hit points, idle gaps on the input, unordered candidates (bank
# conflicts), a small hit-point set (radiance hazards), index entries misplaced on purpose (stage-A
# bank conflicts in update mode; the bench also requires its abank counter to be non-zero);
# 4 PREUs here, and the misplaced entries with 8 and 16 too; the other scenarios with 8 and 16
# in `make sim`. The stable PREU datapath (13-cycle update hazard window) with 4 PREUs: random,
# one hit point, dense, gaps and misplaced entries, at alpha 0.7 and 0.3. The deep configuration
# (PipeFast 1, paper datapath) with 4 PREUs: every scenario, gaps and stalls. Faults: stalls on every
# input stream, a reset in mid-pass then a clean rerun, rst_ni held low (a bounded wait fails).
set -u
cd "$(dirname "$0")/../.."
bench=${BUILD:-build}/cosim/top_bench
fail=0
run() {
  out=$("$bench" "$@" 2>&1); rc=$?
  echo "$out" | tail -1
  if [ $rc -ne 0 ] || ! echo "$out" | tail -1 | grep -q ': PASS$'; then
    echo "FAIL (rc $rc); reproduce: $bench $*"; echo "$out" | head -20; fail=1
  fi
}
run --preu 4 --scenario random --photons 400
run --preu 4 --scenario one --photons 200
run --preu 4 --scenario dense --photons 300
run --preu 4 --scenario dense --hp 100 --photons 60
run --preu 4 --scenario mixed --photons 300 --gap 0.3
run --preu 4 --scenario mixed --photons 300 --no-reorder
run --preu 4 --scenario abank --photons 300
run --preu 4 --scenario abank --photons 300 --gap 0.3 --seed 2
run --preu 8 --scenario abank --photons 300
run --preu 16 --scenario abank --photons 300 --gap 0.3 --seed 3
run --preu 4 --datapath 1 --scenario random --photons 400
run --preu 4 --datapath 1 --scenario one --photons 200
run --preu 4 --datapath 1 --scenario dense --hp 100 --photons 60
run --preu 4 --datapath 1 --alpha 0.3 --scenario mixed --photons 300 --gap 0.3
run --preu 4 --datapath 1 --scenario abank --photons 300 --seed 2
# Faults. Stalls on every input stream: photon gaps, cycles with fewer index writes than the
# port takes, idle cycles in the hit-point load.
run --preu 4 --scenario mixed --photons 300 --gap 0.3 --stall 0.3 --seed 4
run --preu 4 --datapath 1 --scenario dense --hp 100 --photons 60 --gap 0.2 --stall 0.5 --seed 5
# The deep configuration (PipeFast 1: 49-cycle update window, A's offer register, B's two-slot
# queue with the hazard precomputed a cycle ahead): every scenario, radiance hazards on a small
# hit-point set, misplaced entries, stalls on every input stream.
run --preu 4 --pipe-fast --scenario random --photons 400
run --preu 4 --pipe-fast --scenario one --photons 200
run --preu 4 --pipe-fast --scenario dense --hp 100 --photons 60
run --preu 4 --pipe-fast --scenario mixed --photons 300 --gap 0.3
run --preu 4 --pipe-fast --scenario mixed --photons 300 --no-reorder
run --preu 4 --pipe-fast --scenario abank --photons 300 --gap 0.3 --seed 2
run --preu 4 --pipe-fast --scenario mixed --photons 300 --gap 0.3 --stall 0.3 --seed 4
# A reset in mid-pass, then the hit points reloaded and every photon again: the bits and every
# counter of a run without the reset (the whole summary line equal).
for args in "--preu 4 --scenario random --photons 400" "--preu 4 --datapath 1 --scenario mixed --photons 300 --stall 0.3"; do
  clean=$("$bench" $args 2>&1 | tail -1)
  again=$("$bench" $args --reset-at 150 2>&1 | tail -1)
  echo "$again"
  if [ "$clean" != "$again" ] || ! echo "$again" | grep -q ': PASS$'; then
    echo "FAIL: reset after 150 photons, then a rerun: '$again', without the reset: '$clean'"; fail=1
  fi
done
# rst_ni held low while the photons stream: the driver's bounded wait runs out with a message
# naming the wait and the stream's state (status 3).
out=$("$bench" --preu 4 --scenario random --photons 400 --hold-reset --wait-limit 20000 2>&1); rc=$?
echo "$out" | tail -1
if [ $rc -ne 3 ] || ! echo "$out" | grep -q "made no progress for 20000 cycles waiting for .*(ph_ready_o"; then
  echo "FAIL (rc $rc): no bounded wait failed naming its state with rst_ni held low"; fail=1
fi
exit $fail
