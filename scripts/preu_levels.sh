#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# preu_levels.sh: one PREU (paper datapath) through Yosys synth_xilinx (xc7, flattened), checked
# for latches and combinational loops, and its logic depth between registers.
# Usage: scripts/preu_levels.sh <0|1> <out_dir>   (PipeFast 0: the paper's plan; 1: the deep one)
# Writes <out_dir>/preu_pf<P>.{log,json,row}: the row is one Markdown table line of
# scripts/fp32_netlist_report.py --max (LUTs, FFs, DSPs, CARRY4, MUXF7/8, the most LUT levels and
# cells on any register-to-register path, and the register that ends the path with the most
# LUT levels). The PREU's radiance feedback gives its registers no stage number, so the figure is
# the worst path over the whole PREU, not a per-stage list. About 4 CPU minutes for PipeFast 1.
set -euo pipefail
pf=$1; out=$2
case $pf in 0|1) ;; *) echo "preu_levels: PipeFast must be 0 or 1, not $pf" >&2; exit 2 ;; esac
cd "$(dirname "$0")/.."
mkdir -p "$out"
rtl="rtl/pree_preu.v $(ls rtl/pree_fp32_*.v | tr '\n' ' ')rtl/pree_wacc.v rtl/pree_u64_to_f32.v"
script="read_verilog -Irtl -defer $rtl; chparam -set PipeFast $pf pree_preu; hierarchy -check -top pree_preu; proc;
select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr;
synth_xilinx -family xc7 -flatten -top pree_preu;
check -assert; select -assert-none t:LD*;
stat; write_json $out/preu_pf$pf.json"
if ! yosys -q -l "$out/preu_pf$pf.log" -p "$script" >/dev/null 2>&1; then
  tail -20 "$out/preu_pf$pf.log"
  echo "preu_levels $pf: FAILED; reproduce with: yosys -p '$(echo "$script" | tr '\n' ' ')'"
  exit 1
fi
python3 scripts/fp32_netlist_report.py "$out/preu_pf$pf.json" pree_preu --max |
  sed "s/^| pree_preu |/| pree_preu #(.PipeFast($pf)) |/" > "$out/preu_pf$pf.row"
cat "$out/preu_pf$pf.row"
