#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The whole-frame rows through the AXI4 wrapper beside pree_top alone: for each model tag
# (p4, p8, p16: paper datapath; s4 ...: stable; a trailing f: PipeFast 1), `pree cosim --axi`
# (build/pree-cosim-axi-<tag>) without gaps and with random back-pressure on every stream
# (--gap AXI_FULL_GAP) and `pree cosim` (build/pree-cosim-<tag>, pree_top alone, its own photon
# intake) on the same scene, each with 0 differing words in the hit-point memory and the image;
# then one table row per tag with the update-mode utilizations (the --stats JSON's
# update.preu_utilization) and cycle counts of pree_top and of the wrapper without gaps, and the
# wrapper's utilization under back-pressure.
# `make sim-axi-full` (AXI_FULL_TAGS, AXI_FULL_OPTS: default cornell3 320x240 / 768k photons, the
# whole frame; each 16-PREU frame takes minutes of RTL simulation). AXI_FULL_QUICK=1: the quick
# builds (g++ -O0: build/axi/quick/pree-cosim-axi-<tag>, build/cosim/quick/pree-cosim-<tag>; the
# same cycles, a slower simulation, builds many times cheaper), or the -O3 build where only that
# one is there. AXI_FULL_GAP_TAGS: the tags that
# also run with --gap (default all; the others show - in those columns).
# Usage: axi_cosim_full.sh OUTDIR TAG...
source "$(dirname "$0")/../../tests/lib/check.sh"
cd "$ROOT"
out=${1:?OUTDIR}; shift
opts=${AXI_FULL_OPTS:-"--width 320 --height 240 --photons 768000"}
gap=${AXI_FULL_GAP:-0.3}
# prog NAME QUICK_DIR: the program that runs NAME.
prog_of() {
  if [ -n "${AXI_FULL_QUICK:-}" ] && [ -x "$2/$1" ]; then echo "$2/$1"; else echo "build/$1"; fi
}
mkdir -p "$out"
rm -f "$out"/full_*.json
rows=()
pct() { awk -v u="$1" 'BEGIN { printf "%.2f%%", 100 * u }'; }   # a utilization in percent
util() { pct "$(json "$1" update.preu_utilization)"; }
gap_fig() { if [ -f "$1" ]; then "$2" "$1"; else echo -; fi; }
cycles() { json "$1" update.cycles; }
for tag in "$@"; do
  n=${tag//[!0-9]/}; d=paper; pf=
  [[ $tag == s* ]] && d=stable
  fast=0
  [[ $tag == *f ]] && { pf=--pipe-fast; fast=1; }
  sides="axi top"
  [[ " ${AXI_FULL_GAP_TAGS-$*} " == *" $tag "* ]] && sides="axi axigap top"
  for side in $sides; do
    j="$out/full_${side}_$tag.json"
    case $side in
      axi)    prog=$(prog_of pree-cosim-axi-$tag build/axi/quick); extra="--axi" ;;
      axigap) prog=$(prog_of pree-cosim-axi-$tag build/axi/quick); extra="--axi --gap $gap" ;;
      top)    prog=$(prog_of pree-cosim-$tag build/cosim/quick); extra= ;;
    esac
    [ -x "$prog" ] || fail "$prog missing (make $prog)"
    run /usr/bin/time -f "   $side $tag: wall %e s" "$prog" scenes/cornell3 $opts --preu "$n" \
      --datapath $d $pf $extra --quiet --no-reference --stats "$j"
    expect_eq "$side $tag: hit-point words differing" "$(json "$j" hp_words_differing)" 0
    expect_eq "$side $tag: image words differing" "$(json "$j" image_words_differing)" 0
    expect_eq "$side $tag: pass (the operations counted are those sent)" "$(json "$j" pass)" True
  done
  ja="$out/full_axi_$tag.json"; jg="$out/full_axigap_$tag.json"; jt="$out/full_top_$tag.json"
  rows+=("| $n | $d | $fast | $(json "$ja" photons_per_cycle) | $(cycles "$jt") | $(util "$jt") | $(cycles "$ja") | $(util "$ja") | $(gap_fig "$jg" cycles) | $(gap_fig "$jg" util) |")
done
{
  echo "| PREUs | datapath | PipeFast | photons a beat | pree_top update cycles | pree_top utilization | pree_axi update cycles | pree_axi utilization | pree_axi --gap $gap: update cycles | utilization |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
} | tee "$out/table.md"
