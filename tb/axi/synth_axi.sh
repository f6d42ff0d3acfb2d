#!/usr/bin/env bash
# synth_axi.sh: Yosys synth_xilinx (7-series) of pree_axi with NumPreu PREUs, hierarchy kept (the
# PREU is mapped once). Fails on a latch (after proc) or a combinational loop (before and after
# mapping); writes one resource row to OUTDIR/<tag>_p<NumPreu>.md.
#   whole design (tag "whole"): every file of rtl/pree.f, memories sized down (HpAW = 2 HpBankW,
#     IdxAW 8, PxAW 10): their block RAM count scales with the sizes (docs/integration.md, "Which
#     part"), the logic does not.
#   --own (tag "own"): the wrapper's own logic, pree_top a black box, the co-simulation's memory
#     parameters (HpAW 18, IdxAW 12, PxAW 17). Minutes where the whole design takes far longer.
# Banks as the co-simulation builds: hit points 2^(log2 NumPreu + 4), pixels 2^(log2 NumPreu + 2).
# Usage: synth_axi.sh [--own] NUMPREU OUTDIR
set -euo pipefail
cd "$(dirname "$0")/../.."
tag=whole
if [ "${1:-}" = --own ]; then tag=own; shift; fi
np=${1:?NumPreu}
out=${2:-build/axi/synth}
mkdir -p "$out"
lg=$(awk -v n="$np" 'BEGIN { l = 0; while ((2 ^ l) < n) l++; print l }')
hb=$((lg + 4)); pb=$((lg + 2))
params="-chparam NumPreu $np -chparam HpBankW $hb -chparam PxBankW $pb"
if [ $tag = own ]; then
  read="read_verilog -Irtl rtl/pree_reset_sync.v rtl/pree_axil_slave.v rtl/pree_axi.v; read_verilog -lib rtl/pree_top.v"
  what="wrapper only (pree_top a black box)"
else
  read="read_verilog -Irtl $(grep -v '^//' rtl/pree.f | tr '\n' ' ')"
  params="$params -chparam HpAW $((2 * hb)) -chparam IdxAW 8 -chparam PxAW 10"
  what="whole design"
fi
base="$out/${tag}_p$np"
cmd="$read; hierarchy -check -top pree_axi $params; rename -top pree_axi; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; check -assert; synth_xilinx -family xc7 -top pree_axi; check -assert; tee -q -o $base.stat stat -top pree_axi"
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
