#!/usr/bin/env bash
# synth_axi_own.sh: the wrapper's own logic: Yosys synth_xilinx (7-series) of pree_axi with
# pree_top as a black box (its ports only), NumPreu PREUs, the co-simulation's memory parameters
# (HpAW 18, IdxAW 12, PxAW 17; banks log2 NumPreu + 4 and + 2). Fails on a latch or a loop;
# writes one row to OUTDIR/own_p<NumPreu>.md. Minutes where the whole design takes an hour.
# Usage: synth_axi_own.sh NUMPREU OUTDIR
set -euo pipefail
cd "$(dirname "$0")/../.."
np=${1:?NumPreu}
out=${2:-build/axi/synth}
mkdir -p "$out"
lg=$(awk -v n="$np" 'BEGIN { l = 0; while ((2 ^ l) < n) l++; print l }')
params="-chparam NumPreu $np -chparam HpBankW $((lg + 4)) -chparam PxBankW $((lg + 2))"
cmd="read_verilog -Irtl rtl/pree_reset_sync.v rtl/pree_axil_slave.v rtl/pree_axi.v; read_verilog -lib rtl/pree_top.v; hierarchy -check -top pree_axi $params; rename -top pree_axi; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; check -assert; synth_xilinx -family xc7 -top pree_axi; check -assert; tee -q -o $out/own_stat_p$np.txt stat -top pree_axi"
echo "yosys -p '$cmd'"
if ! yosys -q -l "$out/own_yosys_p$np.log" -p "$cmd" >/dev/null 2>&1; then
  echo "synth_axi_own: yosys failed (log: $out/own_yosys_p$np.log)" >&2
  tail -20 "$out/own_yosys_p$np.log" >&2
  exit 1
fi
if grep -q "^Latch inferred" "$out/own_yosys_p$np.log" || grep -qE '^\s+[0-9]+\s+(LDCE|LDPE)' "$out/own_stat_p$np.txt"; then
  echo "synth_axi_own: latch found (log: $out/own_yosys_p$np.log)" >&2
  exit 1
fi
awk '/=== design hierarchy ===/{h=1} h' "$out/own_stat_p$np.txt" > "$out/own_total_p$np.txt"
cnt() { awk -v re="$2" '$1 ~ re {s += $2} END {print s + 0}' "$1"; }
printf '| pree_axi NumPreu=%s, wrapper only (pree_top a black box) | %s | %s | %s | %s | %s | %s | %s |\n' "$np" \
  "$(cnt "$out/own_total_p$np.txt" '^LUT[1-6]$')" "$(cnt "$out/own_total_p$np.txt" '^FD[CPRS]E$')" \
  "$(cnt "$out/own_total_p$np.txt" '^CARRY4$')" "$(cnt "$out/own_total_p$np.txt" '^DSP48E1$')" \
  "$(cnt "$out/own_total_p$np.txt" '^RAMB36E1$')" "$(cnt "$out/own_total_p$np.txt" '^RAMB18E1$')" \
  "$(cnt "$out/own_total_p$np.txt" '^RAM(64M|32M|64X1D|32X1D|128X1D|256X1S)$')" > "$out/own_p$np.md"
cat "$out/own_p$np.md"
