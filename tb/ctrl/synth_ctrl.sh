#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# synth_ctrl.sh: Yosys synth_xilinx (7-series) of one controller configuration; fails on any
# latch or combinational loop and prints one resource line.
# Usage: synth_ctrl.sh MODULE PARAM=VALUE... (e.g. synth_ctrl.sh pree_aftso_hpuoc NumPreu=8)
# Writes the Yosys log to $LOGDIR (default build/ctrl/synth) and the line to stdout.
set -euo pipefail
mod=$1; shift
logdir=${LOGDIR:-build/ctrl/synth}
mkdir -p "$logdir"
tag=$mod; chp=""
for kv in "$@"; do
  tag="${tag}_${kv%%=*}${kv#*=}"
  chp="$chp chparam -set ${kv%%=*} ${kv#*=} $mod;"
done
log=$logdir/$tag.log
stat=$logdir/$tag.stat
cmd="read_verilog rtl/$mod.v; $chp synth_xilinx -top $mod -flatten; check -assert; tee -q -o $stat stat"
if ! yosys -q -l "$log" -p "$cmd" >/dev/null 2>&1; then
  echo "FAIL: yosys for $tag (log: $log); rerun: yosys -p '$cmd'" >&2
  exit 1
fi
# Latches: proc's message before mapping, or latch primitives after it.
if grep -q "^Latch inferred" "$log" || grep -qE '^\s+(LDCE|LDPE|\$_DLATCH)' "$stat"; then
  echo "FAIL: latch in $tag (log: $log)" >&2
  exit 1
fi
cnt() { awk -v re="$1" '$1 ~ re {s += $2} END {print s + 0}' "$stat"; }
printf '%-22s %-26s LUT=%-6s FF=%-5s CARRY4=%-4s MUXF7=%-4s MUXF8=%-4s DSP48=%s BRAM=%s\n' \
  "$mod" "$*" "$(cnt '^LUT[1-6]$')" "$(cnt '^FD[CPRS]E$')" "$(cnt '^CARRY4$')" "$(cnt '^MUXF7$')" \
  "$(cnt '^MUXF8$')" "$(cnt '^DSP48E1$')" "$(cnt '^RAMB')"
