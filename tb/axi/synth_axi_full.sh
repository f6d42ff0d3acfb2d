#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# synth_axi_full.sh: Yosys synth_xilinx (7-series) of the whole pree_axi with the full ABC script
# (not abc -fast) at the memory sizes of the fit table (docs/integration_resources.md): 2^14 hit
# points in 2 NumPreu banks, 2^14 pixels in NumPreu banks (at least 2), IdxAW 12. Fails on a latch
# (after proc) or a combinational loop (before and after mapping). Writes OUTDIR/<tag>_pf<P>_p<N>.*:
# .log, .stat (stat -top), .json (the mapped netlist), .depth.md (tb/cosim/synth_top_depth.py),
# .time (wall, user + system CPU seconds) and .md, one row of the table of
# docs/integration_resources.md.
#   hierarchical (tag "hier", the default): the PREU (pree_preu), the RAM banks (pree_ram_sdp) and
#     the controllers (pree_aftso_hpuoc, pree_adiso_rec) stay modules, each flattened inside;
#     everything else (the wrapper, pree_top and its parts) is flattened into pree_axi. Instances
#     with the same parameters share one module, so ABC maps one PREU once whatever NumPreu is;
#     the totals are stat -top's, each module's cells times its instances. No optimisation
#     crosses a kept module's ports (constants, unused outputs, logic merged across them).
#   --fine (tag "fine"): hierarchical, and pree_top's parts (the index and RAM bank groups, the
#     offer, read, queue and issue stages, the two memory crossbars, the counters) and the AXI4-Lite
#     slave stay modules as well, so that ABC maps each on its own: the reduced run for 16 PREUs,
#     where ABC over the flattened rest of pree_axi is 587,931 gates (153,590 at 8 PREUs; the
#     hierarchical 16-PREU run was never carried to its end). No optimisation crosses these parts'
#     ports either.
#   --flat (tag "flat"): the whole design flattened (synth_xilinx -flatten), ABC over all of it.
# LUT levels (tb/cosim/synth_top_depth.py on pree_axi, the kept modules' netlists joined at their
# ports): the most LUTs on any path between registers, RAM ports, DSP48E1 ports and the top's
# ports, split by where the path runs: within a PREU (it starts and ends in u_preu.*), or not.
# Usage: synth_axi_full.sh [--flat|--fine] PIPEFAST NUMPREU OUTDIR   (PIPEFAST 0: the paper's PREUs,
# 1: the deep ones). Yosys: the `yosys` on PATH (make synth-axi-full: Debian's 0.23).
set -euo pipefail
cd "$(dirname "$0")/../.."
tag=hier
case ${1:-} in --flat) tag=flat; shift ;; --fine) tag=fine; shift ;; esac
[ $# -eq 3 ] || { echo "usage: synth_axi_full.sh [--flat|--fine] PIPEFAST NUMPREU OUTDIR" >&2; exit 2; }
pf=$1; np=$2; out=$3
case $pf in 0|1) ;; *) echo "synth_axi_full: PIPEFAST must be 0 or 1, not $pf" >&2; exit 2 ;; esac
case $np in 1|2|4|8|16) ;; *) echo "synth_axi_full: NUMPREU must be 1, 2, 4, 8 or 16, not $np" >&2; exit 2 ;; esac
mkdir -p "$out"
lg=$(awk -v n="$np" 'BEGIN { l = 0; while ((2 ^ l) < n) l++; print l }')
pb=$((lg > 0 ? lg : 1))
params="NumPreu $np PipeFast $pf HpAW 14 HpBankW $((lg + 1)) PxAW 14 PxBankW $pb IdxAW 12"
kept="pree_preu pree_ram_sdp pree_aftso_hpuoc pree_adiso_rec"
[ $tag = fine ] && kept="$kept pree_ram_banks pree_top_offer pree_top_read pree_top_queue pree_top_issue pree_top_hpmem pree_top_pxmem pree_counters pree_axil_slave"
base="$out/${tag}_pf${pf}_p$np"
if [ $tag != flat ]; then
  prep="setattr -mod -set keep_hierarchy 1 $(printf '*%s ' $kept); flatten; setattr -mod -unset keep_hierarchy *"
  synth="synth_xilinx -family xc7 -top pree_axi"
else
  prep="flatten"
  synth="synth_xilinx -family xc7 -flatten -top pree_axi"
fi
cmd="read_verilog -Irtl $(grep -v '^//' rtl/pree.f | tr '\n' ' '); chparam $(printf -- '-set %s %s ' $params)pree_axi
hierarchy -check -top pree_axi; $prep; rename -top pree_axi; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; check -assert
$synth; check -assert; select -assert-none t:LD*; tee -q -o $base.stat stat -top pree_axi; write_json $base.json"
echo "yosys -p '$(echo "$cmd" | tr '\n' ' ')'"
if ! /usr/bin/time -f "%e %U %S" -o "$base.time" yosys -q -l "$base.log" -p "$cmd" >/dev/null 2>&1; then
  echo "synth_axi_full: yosys failed (log: $base.log)" >&2
  tail -20 "$base.log" >&2
  exit 1
fi
python3 tb/cosim/synth_top_depth.py --inline "$(echo $kept | tr ' ' ',')" "$base.json" pree_axi > "$base.depth.md"
# in_preu 1: the endpoints in a PREU whose deepest path starts in it; 0: every other endpoint.
levels() { awk -F'|' -v in_preu="$1" 'NR > 2 && (($2 ~ /u_preu\./ && $5 ~ /u_preu\./) == in_preu) && $3 + 0 > m {m = $3 + 0} END {print m + 0}' "$base.depth.md"; }
# The totals: stat -top's "design hierarchy" block, or the one module's block when flattened.
if grep -q '=== design hierarchy ===' "$base.stat"; then
  awk '/=== design hierarchy ===/{h=1} h' "$base.stat" > "$base.total"
else
  cp "$base.stat" "$base.total"
fi
cnt() { awk -v re="$1" '$1 ~ re {s += $2} END {print s + 0}' "$base.total"; }
cpu=$(awk '{printf "%.0f", $2 + $3}' "$base.time")
printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' \
  "$np" "$([ "$pf" = 1 ] && echo deep || echo paper)" "$tag" \
  "$(cnt '^LUT[1-6]$')" "$(cnt '^FD[CPRS]E$')" "$(cnt '^CARRY4$')" "$(cnt '^MUXF[78]$')" "$(cnt '^DSP48E1$')" \
  "$(cnt '^RAMB36E1$')" "$(cnt '^RAMB18E1$')" "$(cnt '^RAM(64M|32M|64X1D|32X1D|128X1D|256X1S)$')" \
  "$(levels 1)" "$(levels 0)" "$cpu" > "$base.md"
cat "$base.md"
