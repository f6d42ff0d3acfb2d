#!/usr/bin/env bash
# fp32_synth.sh: synthesise one binary32 unit with Yosys synth_xilinx (7-series) and check it.
# Usage: scripts/fp32_synth.sh <add|mul|sqr|div|cmp> <out_dir>
# Fails (exit 1) on any latch (a $dlatch cell after proc, "Latch inferred" in the log, or an LD*
# cell after mapping), on a combinational loop or other netlist problem (yosys `check -assert`),
# and on a Yosys error. Writes <out_dir>/<unit>.log, .json (the netlist) and .row (one Markdown
# table row of resources and per-stage depth, from scripts/fp32_netlist_report.py).
set -euo pipefail
unit=$1; out=$2
top=pree_fp32_$unit
mkdir -p "$out"
cd "$(dirname "$0")/.."
rtl="rtl/pree_fp32_lzc.v rtl/pree_fp32_unpack.v rtl/pree_fp32_round.v rtl/pree_fp32_div_steps.v rtl/$top.v"
script="read_verilog -defer $rtl; hierarchy -check -top $top; proc;
select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr;
synth_xilinx -family xc7 -flatten -top $top;
check -assert; select -assert-none t:LD*;
stat; write_json $out/$unit.json"
repro="yosys -p '$(echo "$script" | tr '\n' ' ')'"
if ! yosys -q -l "$out/$unit.log" -p "$script" >/dev/null 2>&1; then
  tail -20 "$out/$unit.log"
  echo "fp32_synth $unit: FAILED; reproduce with: $repro"
  exit 1
fi
if grep -q "Latch inferred" "$out/$unit.log"; then
  grep "Latch inferred" "$out/$unit.log" | head
  echo "fp32_synth $unit: latch inferred; reproduce with: $repro"
  exit 1
fi
python3 scripts/fp32_netlist_report.py "$out/$unit.json" "$top" > "$out/$unit.row"
cat "$out/$unit.row"
