#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# postroute_cells.sh: the post-route simulation's cell models (tb/postroute/, docs/fpga_board.md,
# "Post-route simulation") against Yosys's own ECP5 models (the hardware tools' venv: LUT4, LUT2,
# PFUMX, L6MUX21, CCU2C, TRELLIS_DPR16X4) on random vectors under Icarus
# (tb/postroute/ecp5_pnr_cells_tb.v); a mutant of TRELLIS_RAMW's wiring must fail. The venv:
# FPGA_VENV, default build/fpga-venv (make test installs it).
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=${FPGA_VENV:-build/fpga-venv}
out=build/postroute/cells
mkdir -p "$out"
# Yosys's models that the bench compares against.
if ! scripts/ecp5_yosys_cells.sh "$venv" "$out/yosys_ref.v" 2>/dev/null; then
  echo "FAIL postroute_cells: no Yosys ECP5 library in $venv (make fpga-deps; make test installs it)"
  exit 1
fi
cells="tb/postroute/ecp5_pnr_comb.v tb/fpga/MULT18X18D.v"
run() {   # <vvp> <cells...>: the bench's verdict line
  iverilog -g2005 -o "$1" tb/postroute/ecp5_pnr_cells_tb.v "$out/yosys_ref.v" "${@:2}" 2>&1 | grep -v "^$" >&2 || true
  vvp -n "$1" | grep -E '^(PASS|FAIL)' | tail -1
}
res=$(run "$out/cells.vvp" $cells)
echo "$res"
case $res in PASS*) ;; *) echo "FAIL postroute_cells: the models differ from Yosys's"; exit 1 ;; esac
# The mutant: TRELLIS_RAMW's address outputs in the other order must make the DPRAM differ.
sed 's/assign {WADO3, WADO2, WADO1, WADO0} = {D0, C0, B0, A0};/assign {WADO3, WADO2, WADO1, WADO0} = {A0, B0, C0, D0};/' \
  tb/postroute/ecp5_pnr_comb.v > "$out/comb_mutant.v"
cmp -s tb/postroute/ecp5_pnr_comb.v "$out/comb_mutant.v" && { echo "FAIL postroute_cells: the mutant edit no longer applies"; exit 1; }
res=$(run "$out/mutant.vvp" "$out/comb_mutant.v" tb/fpga/MULT18X18D.v)
case $res in FAIL*) echo "mutant (RAMW address order): $res" ;; *) echo "FAIL postroute_cells: the RAMW mutant passed"; exit 1 ;; esac
echo "PASS postroute_cells"
