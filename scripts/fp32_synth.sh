#!/usr/bin/env bash
# fp32_synth.sh: synthesise one binary32 unit with Yosys synth_xilinx (7-series) and check it.
# Usage: scripts/fp32_synth.sh <add|mul|sqr|div|cmp|div8|wacc|u2f> <out_dir>
#   (div8: divider, Stages = 8; wacc: pree_wacc; u2f: pree_u64_to_f32)
# Fails (exit 1) on any latch (a $dlatch cell after proc, "Latch inferred" in the log, or an LD*
# cell after mapping), on a combinational loop or other netlist problem (yosys `check -assert`),
# and on a Yosys error. Writes <out_dir>/<unit>.log, .json (the netlist) and .row (one Markdown
# table row of resources and per-stage depth, from scripts/fp32_netlist_report.py).
set -euo pipefail
id=$1; out=$2
params=""; label=""
case $id in
  div8) top=pree_fp32_div; params="chparam -set Stages 8 pree_fp32_div;"
        label="pree_fp32_div #(.Stages(8))" ;;
  wacc) top=pree_wacc ;;
  u2f)  top=pree_u64_to_f32 ;;
  *)    top=pree_fp32_$id ;;
esac
label=${label:-$top}
mkdir -p "$out"
cd "$(dirname "$0")/.."
rtl="rtl/pree_fp32_lzc.v rtl/pree_fp32_unpack.v rtl/pree_fp32_round.v rtl/pree_fp32_div_steps.v rtl/$top.v"
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
