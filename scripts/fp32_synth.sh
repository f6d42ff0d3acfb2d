#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# fp32_synth.sh: synthesise one binary32 unit with Yosys synth_xilinx (7-series) and check it.
# Usage: scripts/fp32_synth.sh <add|mul|sqr|div|cmp|div8|wacc|u2f>[_fast] <out_dir>
#   (div8: divider, Stages = 8; wacc: pree_wacc; u2f: pree_u64_to_f32; <unit>_fast: the unit
#   with PipeFast = 1, its deep configuration)
# Fails (exit 1) on any latch (a $dlatch cell after proc, "Latch inferred" in the log, or an LD*
# cell after mapping), on a combinational loop or other netlist problem (yosys `check -assert`),
# and on a Yosys error. Writes <out_dir>/<unit>.log, .json (the netlist) and .row (one Markdown
# table row of resources and per-stage depth, from scripts/fp32_netlist_report.py).
set -euo pipefail
id=$1; out=$2
params=""; label=""
unit=${id%_fast}
case $unit in
  div8) top=pree_fp32_div; params="chparam -set Stages 8 pree_fp32_div;"
        label="pree_fp32_div #(.Stages(8))" ;;
  wacc) top=pree_wacc ;;
  u2f)  top=pree_u64_to_f32 ;;
  *)    top=pree_fp32_$unit ;;
esac
if [ "$unit" != "$id" ]; then
  params="chparam -set PipeFast 1 $top;"; label="$top #(.PipeFast(1))"
fi
label=${label:-$top}
mkdir -p "$out"
cd "$(dirname "$0")/.."
rtl="$(ls rtl/pree_fp32_*.v | grep -v "rtl/pree_fp32_\(add\|mul\|sqr\|div\|cmp\)\.v" | tr '\n' ' ')rtl/$top.v"
script="read_verilog -defer $rtl; $params hierarchy -check -top $top; proc;
select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr;
synth_xilinx -family xc7 -flatten -top $top;
check -assert; select -assert-none t:LD*;
stat; write_json $out/$id.json"
repro="yosys -p '$(echo "$script" | tr '\n' ' ')'"
if ! yosys -q -l "$out/$id.log" -p "$script" >/dev/null 2>&1; then
  tail -20 "$out/$id.log"
  echo "fp32_synth $id: FAILED; reproduce with: $repro"
  exit 1
fi
if grep -q "Latch inferred" "$out/$id.log"; then
  grep "Latch inferred" "$out/$id.log" | head
  echo "fp32_synth $id: latch inferred; reproduce with: $repro"
  exit 1
fi
python3 scripts/fp32_netlist_report.py "$out/$id.json" "$top" | sed "s/^| $top |/| $label |/" > "$out/$id.row"
cat "$out/$id.row"
