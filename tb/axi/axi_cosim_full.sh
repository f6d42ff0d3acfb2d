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
# whole frame; each 16-PREU frame takes minutes of RTL simulation).
# Usage: axi_cosim_full.sh OUTDIR TAG...
source "$(dirname "$0")/../../tests/lib/check.sh"
cd "$ROOT"
out=${1:?OUTDIR}; shift
opts=${AXI_FULL_OPTS:-"--width 320 --height 240 --photons 768000"}
gap=${AXI_FULL_GAP:-0.3}
mkdir -p "$out"
rows=()
for tag in "$@"; do
  n=${tag//[!0-9]/}; d=paper; pf=
  [[ $tag == s* ]] && d=stable
  [[ $tag == *f ]] && pf=--pipe-fast
  for side in axi axigap top; do
    j="$out/full_${side}_$tag.json"
    case $side in
      axi)    prog=build/pree-cosim-axi-$tag; extra="--axi" ;;
      axigap) prog=build/pree-cosim-axi-$tag; extra="--axi --gap $gap" ;;
      top)    prog=build/pree-cosim-$tag; extra= ;;
    esac
    [ -x "$prog" ] || fail "$prog missing (make $prog)"
    run /usr/bin/time -f "   $side $tag: wall %e s" "$PREE" cosim scenes/cornell3 $opts --preu "$n" \
      --datapath $d $pf $extra --quiet --no-reference --stats "$j"
    expect_eq "$side $tag: hit-point words differing" "$(json "$j" hp_words_differing)" 0
    expect_eq "$side $tag: image words differing" "$(json "$j" image_words_differing)" 0
  done
  ja="$out/full_axi_$tag.json"; jg="$out/full_axigap_$tag.json"; jt="$out/full_top_$tag.json"
  rows+=("| $tag | $(json "$jt" update.preu_utilization) | $(json "$ja" update.preu_utilization) | $(json "$jt" update.cycles) | $(json "$ja" update.cycles) | $(json "$jg" update.preu_utilization) |")
done
{
  echo "| model | pree_top utilization | pree_axi utilization | pree_top update cycles | pree_axi update cycles | pree_axi utilization, --gap $gap |"
  echo "|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
} | tee "$out/table.md"
