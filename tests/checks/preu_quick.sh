#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# preu_quick.sh: PREU lint (verilator -Wall, four configurations a datapath), Yosys structural checks (no
# latch, no combinational loop) and a short Verilator run against the C model (20,000 operations),
# both datapaths (paper, stable), and one hit point fed 100,000 accepted photons through each
# datapath's PREU with its state written back every time (make sim-preu-chain; 10 million there).
# level: quick
# cost: 305 (its seconds in a serial run; the runner starts costly checks first)
set -u
cd "$(dirname "$0")/../.."
for cmd in "make -s lint-preu" "make -s yosys-check-preu" "make -s sim-preu-vl PREU_N=20000 PREU_SEED=7" \
           "make -s sim-preu-chain PREU_CHAIN_N=100000"; do
  if ! out=$($cmd 2>&1); then
    echo "$out" | tail -20
    echo "preu_quick: FAIL; reproduce with: $cmd"
    exit 1
  fi
  echo "$out" | tail -3
done
echo "preu_quick: ok"
