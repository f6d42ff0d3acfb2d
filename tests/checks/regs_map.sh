#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# pree_axi's register map has one source, rtl/regs/pree_axi.rdl:
#   - the generated files are current: scripts/regs_gen.sh (PeakRDL, in the hardware tools' venv)
#     regenerates them into a scratch copy, which must equal the committed drv/pree_axi_regs.h,
#     rtl/pree_axi_regs.vh, tb/regs/pree_axi_regs_table.h and docs/integration.md;
#   - the RTL decodes exactly that map: build/regs/regs_check (tb/regs/regs_check.c) reads and
#     writes every register and field of the Verilated pree_axi through AXI4-Lite against the
#     generated table (reset values, RO/RW/WO/RW1C, field positions, STATUS in its states, the
#     counters' region, unmapped addresses).
# cost: 4 (about 3 s of PeakRDL, 1 s of simulation)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
venv=${FPGA_VENV:-$ROOT/build/fpga-venv}
[ -x "$venv/bin/peakrdl" ] || fail "no PeakRDL in $venv (make fpga-deps, or FPGA_VENV=<venv>)"
[ -x build/regs/regs_check ] || fail "build/regs/regs_check missing (make build/regs/regs_check)"
mkdir -p "$TMP/gen/docs"
cp docs/integration.md "$TMP/gen/docs/"
run scripts/regs_gen.sh "$venv" "$TMP/gen"
for f in drv/pree_axi_regs.h rtl/pree_axi_regs.vh tb/regs/pree_axi_regs_table.h docs/integration.md; do
  cmp -s "$f" "$TMP/gen/$f" || fail "$f is stale against rtl/regs/pree_axi.rdl (make regs): $(diff "$f" "$TMP/gen/$f" | head -5 | tr '\n' ' ')"
done
echo "ok: the four generated files equal a fresh generation from rtl/regs/pree_axi.rdl"
run build/regs/regs_check
