#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# synth_axi.sh: Yosys synth_xilinx (7-series) of pree_axi with NumPreu PREUs, hierarchy kept (the
# PREU is mapped once). Fails on a latch (after proc) or a combinational loop (before and after
# mapping); writes one resource row to OUTDIR/<tag>_p<NumPreu>.md.
#   whole design (tag "whole"): every file of rtl/pree.f, memories sized down (HpAW = 2 HpBankW,
#     IdxAW 8, PxAW 10): their block RAM count scales with the sizes (docs/integration_resources.md, "Memories
#     and fit"), the logic does not.
#   --own (tag "own"): the wrapper's own logic, pree_top a black box, the co-simulation's memory
#     parameters (HpAW 18, IdxAW 12, PxAW 17). Minutes where the whole design takes far longer.
#   --fast (tag "fast", whole design): synth_xilinx up to its LUT mapping, which then runs as
#     `abc -fast` (the rest of map_luts and finalize as synth_xilinx's). The full flow's ABC did
#     not finish in an hour on the 4-PREU design (some 220k multiplexer cells before LUT mapping,
#     most of them the LUT-RAM hit-point banks' read trees); FF, CARRY4, DSP, block and LUT RAM
#     are mapped before that step and are the full flow's, the LUT count is abc -fast's.
# Banks as the co-simulation builds: hit points 2^(log2 NumPreu + 4), pixels 2^(log2 NumPreu + 2).
# The whole design takes its parameters through `chparam` on pree_axi (Yosys 0.23's `hierarchy
# -chparam` fails an assertion there); --own keeps `hierarchy -chparam` (its rows above were measured
# so; `chparam` gives it 1305 LUTs instead of 1344, ABC working on differently named modules).
# Usage: synth_axi.sh [--own | --fast] NUMPREU OUTDIR
set -euo pipefail
cd "$(dirname "$0")/../.."
tag=whole
case "${1:-}" in --own) tag=own; shift ;; --fast) tag=fast; shift ;; esac
np=${1:?NumPreu}
out=${2:-build/axi/synth}
mkdir -p "$out"
lg=$(awk -v n="$np" 'BEGIN { l = 0; while ((2 ^ l) < n) l++; print l }')
hb=$((lg + 4)); pb=$((lg + 2))
params="NumPreu $np HpBankW $hb PxBankW $pb"
if [ $tag = own ]; then
  read="read_verilog -Irtl rtl/pree_reset_sync.v rtl/pree_axil_slave.v rtl/pree_axi.v; read_verilog -lib rtl/pree_top.v"
  what="wrapper only (pree_top a black box)"
else
  read="read_verilog -Irtl $(grep -v '^//' rtl/pree.f | tr '\n' ' ')"
  params="$params HpAW $((2 * hb)) IdxAW 8 PxAW 10"
  what="whole design"
  [ $tag = fast ] && what="whole design, LUTs by abc -fast"
fi
base="$out/${tag}_p$np"
synth="synth_xilinx -family xc7 -top pree_axi"
if [ $tag = fast ]; then
  synth="synth_xilinx -family xc7 -top pree_axi -run :map_luts; opt_expr -mux_undef -noclkinv; abc -fast -luts 2:2,3,6:5,10,20; clean; techmap -map +/xilinx/ff_map.v; xilinx_srl -fixed -minlen 3; techmap -map +/xilinx/lut_map.v -map +/xilinx/cells_map.v -D LUT_WIDTH=6; xilinx_dffopt; opt_lut_ins -tech xilinx; synth_xilinx -family xc7 -top pree_axi -run finalize:"
fi
if [ $tag = own ]; then
  setp="hierarchy -check -top pree_axi $(printf -- '-chparam %s %s ' $params)"
else
  setp="chparam $(printf -- '-set %s %s ' $params)pree_axi; hierarchy -check -top pree_axi"
fi
cmd="$read; $setp; rename -top pree_axi; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; check -assert; $synth; check -assert; tee -q -o $base.stat stat -top pree_axi"
echo "yosys -p '$cmd'"
if ! yosys -q -l "$base.log" -p "$cmd" >/dev/null 2>&1; then
  echo "synth_axi: yosys failed (log: $base.log)" >&2
  tail -20 "$base.log" >&2
  exit 1
fi
if grep -q "^Latch inferred" "$base.log" || grep -qE '^\s+[0-9]+\s+(LDCE|LDPE)' "$base.stat"; then
  echo "synth_axi: latch found (log: $base.log)" >&2
  exit 1
fi
awk '/=== design hierarchy ===/{h=1} h' "$base.stat" > "$base.total"
cnt() { awk -v re="$1" '$1 ~ re {s += $2} END {print s + 0}' "$base.total"; }
printf '| pree_axi NumPreu=%s, %s | %s | %s | %s | %s | %s | %s | %s |\n' "$np" "$what" \
  "$(cnt '^LUT[1-6]$')" "$(cnt '^FD[CPRS]E$')" "$(cnt '^CARRY4$')" "$(cnt '^DSP48E1$')" \
  "$(cnt '^RAMB36E1$')" "$(cnt '^RAMB18E1$')" "$(cnt '^RAM(64M|32M|64X1D|32X1D|128X1D|256X1S)$')" > "$base.md"
cat "$base.md"
