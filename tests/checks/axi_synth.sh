#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The AXI4 wrapper's own logic through Yosys synth_xilinx (tb/axi/synth_axi.sh --own: pree_top a
# black box, 4 PREUs, the co-simulation's memory parameters): no latch after proc, no
# combinational loop before or after mapping, and a resource row with LUTs and flip-flops.
# (pree_top itself: tests/checks/top_yosys.sh.)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
run bash tb/axi/synth_axi.sh --own 4 "$TMP"
row=$(cat "$TMP/own_p4.md")
luts=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $3); print $3}')
ffs=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $4); print $4}')
[ "${luts:-0}" -gt 0 ] && [ "${ffs:-0}" -gt 0 ] || fail "no resource row: $row"
echo "ok: pree_axi's own logic, 4 PREUs: $luts LUTs, $ffs flip-flops, no latch"
