#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# synth_top.sh: Yosys synthesis of pree_top with 4 PREUs for a Xilinx 7-series part
# (synth_xilinx), hierarchy kept (the PREU is mapped once, instantiated four times). Fails on a
# latch or a combinational loop; writes the resource table to OUTDIR/resources.md (the whole
# design, pree_top's own logic, the controllers, the rest: 4 PREUs with their fp32 units and the
# block RAMs), the mapped netlist to OUTDIR/netlist.json and the logic depth of pree_top's own
# paths (tb/cosim/synth_top_depth.py) to OUTDIR/depth.md, the controllers' paths included (their
# netlists joined to the top's at their ports, --inline).
# pree_ram_banks (the banks' request logic), pree_counters and pree_top's parts (pree_top_offer,
# _read, _queue, _issue, _hpmem and _pxmem) are flattened into pree_top, so that their logic
# counts as pree_top's own and its paths are measured whole; the RAMs, PREUs and controllers stay
# modules.
# Memories are sized down for the run (HpAW=12 in 16 banks, IdxAW=8, PxAW=10 in 4 banks): their
# block-RAM count scales with the sizes, the logic does not.
# Usage: synth_top.sh OUTDIR [PIPEFAST]   (PIPEFAST 0, the default: the paper's PREUs; 1: the deep ones)
set -euo pipefail
out=${1:-build/cosim/synth}
pipefast=${2:-0}
mkdir -p "$out"
srcs=$(grep -v '^//' rtl/pree.f | tr '\n' ' ')   # the RTL filelist
params="chparam -set PipeFast $pipefast -set NumPreu 4 -set HpAW 12 -set HpBankW 4 -set IdxAW 8 -set PxAW 10 -set PxBankW 2 pree_top"
cmd="read_verilog -Irtl $srcs; $params; hierarchy -check -top pree_top; setattr -mod -set keep_hierarchy 1 *; setattr -mod -unset keep_hierarchy *pree_ram_banks *pree_counters *pree_top_offer *pree_top_read *pree_top_issue *pree_top_queue *pree_top_hpmem *pree_top_pxmem; flatten; setattr -mod -unset keep_hierarchy *; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; check -assert; synth_xilinx -family xc7 -top pree_top; check -assert; tee -q -o $out/stat.txt stat -top pree_top; write_json $out/netlist.json"
echo "yosys -p '$cmd'"
if ! yosys -q -l "$out/yosys.log" -p "$cmd" >/dev/null 2>&1; then
  echo "synth_top: yosys failed (log: $out/yosys.log); rerun: yosys -p '$cmd'" >&2
  tail -20 "$out/yosys.log" >&2
  exit 1
fi
if grep -q "^Latch inferred" "$out/yosys.log" || grep -qE '^\s+[0-9]+\s+(LDCE|LDPE)' "$out/stat.txt"; then
  echo "synth_top: latch found (log: $out/yosys.log)" >&2
  exit 1
fi
# The hierarchy total is the last "design hierarchy" block of stat -top; a module's own cells
# are its "=== name ===" block (pree_top's own block is the one named exactly pree_top).
awk '/=== design hierarchy ===/{h=1} h' "$out/stat.txt" > "$out/total.txt"
section() { awk -v re="$1" '/^=== /{h = ($0 ~ re)} h' "$out/stat.txt"; }
section '^=== pree_top ===$' > "$out/own.txt"
section 'pree_aftso_hpuoc ===$' > "$out/aftso.txt"
section 'pree_adiso_rec ===$' > "$out/adiso.txt"
cnt() { awk -v re="$2" '$1 ~ re {s += $2} END {print s + 0}' "$out/$1.txt"; }
row() {
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$1" \
    "$(cnt "$2" '^LUT[1-6]$')" "$(cnt "$2" '^FD[CPRS]E$')" "$(cnt "$2" '^CARRY4$')" "$(cnt "$2" '^MUXF7$')" \
    "$(cnt "$2" '^MUXF8$')" "$(cnt "$2" '^DSP48E1$')" "$(cnt "$2" '^RAMB36E1$')" "$(cnt "$2" '^RAMB18E1$')" \
    "$(cnt "$2" '^RAM(64M|32M|64X1D|32X1D|128X1D|256X1S)$')"
}
{
  echo "| design | LUT | FF | CARRY4 | MUXF7 | MUXF8 | DSP48E1 | RAMB36E1 | RAMB18E1 | RAM64M/RAM32M |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  row "pree_top NumPreu=4, PipeFast=$pipefast, whole design" total
  row "pree_top's own logic (lanes, crossbars, hazards, counters)" own
  row "pree_aftso_hpuoc" aftso
  row "pree_adiso_rec" adiso
} > "$out/resources.md"
cat "$out/resources.md"
if command -v python3 >/dev/null; then
  python3 tb/cosim/synth_top_depth.py --inline pree_aftso_hpuoc,pree_adiso_rec "$out/netlist.json" > "$out/depth.md"
  cat "$out/depth.md"
fi
