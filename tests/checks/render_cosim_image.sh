#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The fp32 render's image is the RTL's, bit for bit: `pree render --precision fp32` and `pree
# cosim` (the Verilated pree_top) with the same scene, size, photons and PREE options write EXR
# files whose pixel words are the same (iinfo --hash: a SHA-1 of the binary32 pixel data, not of
# the header). The two files are compared with each other, not through the co-simulation's own
# reference. cornell3 32x24 / 4k photons (2,304 values) in every configuration the regression
# builds a model of: 4 PREUs in both hit-point layouts, PipeFast 1, the stable datapath, 8 and 16
# PREUs, and a board of two 4-PREU PREEs (mpirun -np 2 pree cosim against render --prees 2). The
# render runs on 2 threads (its photon pass then holds the hit points in another order than the
# co-simulation's one-thread pass). At this size each option changes the image (a pixel's hit
# points added in another order), so the images must also differ pairwise: a render that ignored
# an option would fail.
# cost: 25 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
command -v iinfo >/dev/null || fail "iinfo missing (Debian openimageio-tools: scripts/install-deps.sh)"
command -v mpirun >/dev/null || fail "mpirun missing (Debian openmpi-bin: scripts/install-deps.sh)"
MPIRUN=(mpirun --oversubscribe --allow-run-as-root --bind-to none -np 2)
frame=(scenes/cornell3 --width 32 --height 24 --photons 4000 --quiet)
pixels_sha() { iinfo --hash "$1" | sed -n 's/.*SHA-1: //p'; }
declare -A seen
k=0
# same_image WHAT: the RTL's image $TMP/rtl$k.exr and the render's $TMP/model$k.exr, the same
# pixel words, and not the image of an earlier configuration.
same_image() {
  local rtl model
  rtl=$(pixels_sha "$TMP/rtl$k.exr")
  model=$(pixels_sha "$TMP/model$k.exr")
  [ -n "$rtl" ] || fail "$1: no pixel hash from iinfo --hash $TMP/rtl$k.exr"
  if [ "$rtl" != "$model" ]; then
    idiff -fail 0 -warn 0 "$TMP/rtl$k.exr" "$TMP/model$k.exr" | tail -4
    fail "$1: the render's image is not the RTL's (pixel SHA-1 $model, RTL $rtl)"
  fi
  echo "ok: $1: render = RTL (pixel SHA-1 $rtl)"
  [ -z "${seen[$rtl]:-}" ] || fail "$1 gives the image of ${seen[$rtl]}: the frame is too small to tell them apart"
  seen[$rtl]=$1
}
for cfg in "--preu 4" "--preu 4 --layout pixel" "--preu 4 --pipe-fast" "--preu 4 --datapath stable" "--preu 8" \
           "--preu 16"; do
  k=$((k + 1))
  run "$PREE" cosim "${frame[@]}" $cfg --no-reference --out "$TMP/rtl$k.exr"
  run "$PREE" render "${frame[@]}" $cfg --precision fp32 --threads 2 --out "$TMP/model$k.exr"
  same_image "$cfg"
done
k=$((k + 1))
echo "+ ${MPIRUN[*]} $PREE cosim ${frame[*]} --preu 4 --no-reference --out $TMP/rtl$k.exr"
"${MPIRUN[@]}" "$PREE" cosim "${frame[@]}" --preu 4 --no-reference --out "$TMP/rtl$k.exr" ||
  fail "two ranks: exit $?"
run "$PREE" render "${frame[@]}" --preu 4 --prees 2 --precision fp32 --threads 2 --out "$TMP/model$k.exr"
same_image "a board of two PREEs (--prees 2)"
