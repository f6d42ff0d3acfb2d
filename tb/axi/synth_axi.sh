#!/usr/bin/env bash
# synth_axi.sh: Yosys synth_xilinx (7-series) of pree_axi through rtl/pree.f with NumPreu PREUs,
# hierarchy kept (the PREU is mapped once). Fails on a latch or a combinational loop; appends one
# resource row (the whole design, and pree_axi's own logic: AXI-Lite, FIFOs, command engine) to
# OUTDIR/resources_p<NumPreu>.md.
# Memories are sized down for the run (HpAW = 2 HpBankW, IdxAW = 8, PxAW = 10; banks as the
# co-simulation builds: hit points 2^(log2 NumPreu + 4), pixels 2^(log2 NumPreu + 2)): their block
# RAM count scales with the sizes (docs/integration.md, "Which part"), the logic does not.
# Usage: synth_axi.sh NUMPREU OUTDIR
set -euo pipefail
cd "$(dirname "$0")/../.."
np=${1:?NumPreu}
out=${2:-build/axi/synth}
mkdir -p "$out"
lg=$(awk -v n="$np" 'BEGIN { l = 0; while ((2 ^ l) < n) l++; print l }')
hb=$((lg + 4)); pb=$((lg + 2)); ha=$((2 * hb))
srcs=$(grep -v '^//' rtl/pree.f | tr '\n' ' ')
params="chparam -set NumPreu $np -set HpAW $ha -set HpBankW $hb -set IdxAW 8 -set PxAW 10 -set PxBankW $pb pree_axi"
cmd="read_verilog -Irtl $srcs; $params; hierarchy -check -top pree_axi; rename -top pree_axi; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; check -assert; synth_xilinx -family xc7 -top pree_axi; check -assert; tee -q -o $out/stat_p$np.txt stat -top pree_axi"
echo "yosys -p '$cmd'"
if ! yosys -q -l "$out/yosys_p$np.log" -p "$cmd" >/dev/null 2>&1; then
  echo "synth_axi: yosys failed (log: $out/yosys_p$np.log)" >&2
  tail -20 "$out/yosys_p$np.log" >&2
  exit 1
fi
if grep -q "^Latch inferred" "$out/yosys_p$np.log" || grep -qE '^\s+[0-9]+\s+(LDCE|LDPE)' "$out/stat_p$np.txt"; then
  echo "synth_axi: latch found (log: $out/yosys_p$np.log)" >&2
  exit 1
fi
awk '/=== design hierarchy ===/{h=1} h' "$out/stat_p$np.txt" > "$out/total_p$np.txt"
awk '/^=== /{h = ($0 ~ /^=== pree_axi ===$/)} h' "$out/stat_p$np.txt" > "$out/own_p$np.txt"
cnt() { awk -v re="$2" '$1 ~ re {s += $2} END {print s + 0}' "$1"; }
row() {
  printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "$1" \
    "$(cnt "$2" '^LUT[1-6]$')" "$(cnt "$2" '^FD[CPRS]E$')" "$(cnt "$2" '^CARRY4$')" \
    "$(cnt "$2" '^DSP48E1$')" "$(cnt "$2" '^RAMB36E1$')" "$(cnt "$2" '^RAMB18E1$')" \
    "$(cnt "$2" '^RAM(64M|32M|64X1D|32X1D|128X1D|256X1S)$')"
}
{
  row "pree_axi NumPreu=$np, whole design" "$out/total_p$np.txt"
  row "pree_axi NumPreu=$np, wrapper's own logic" "$out/own_p$np.txt"
} > "$out/resources_p$np.md"
cat "$out/resources_p$np.md"
