#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# pree render --light-sampling (model/ppm/photon_pass.c, docs/scene_format.md "Photon emission").
# With one light, power is uniform bit for bit. With two point lights (scenes/examples/caustics.scene
# and a dim second light), uniform sharing (photon i from light i mod 2) correlates the light with
# Halton dimension 0 (base 2: light 0 gets only even i, so only phi in [0, pi)), a bias: the
# uniform image differs from the power one by several times the noise between two power renders
# of disjoint photons. A checkpoint records the choice: resuming with the other is a conflict.
# cost: 6
source "$(dirname "$0")/../lib/check.sh"
cd "$TMP"
S=$ROOT/scenes
R=(--width 48 --height 36 --quiet)
run "$PREE" render "$S/cornell3" "${R[@]}" --photons 40000 --out u.png --stats u.json
run "$PREE" render "$S/cornell3" "${R[@]}" --photons 40000 --light-sampling power --out p.png --stats p.json
expect_eq "one light: power = uniform" "$(json p.json image_hash)/$(json p.json state_hash)" \
  "$(json u.json image_hash)/$(json u.json state_hash)"
{ cat "$S/examples/caustics.scene"; echo "light point -2 2.5 1 intensity 0.06 0.06 0.06"; } > two.scene
run "$PREE" render two.scene "${R[@]}" --photons 200000 --out uni.exr
run "$PREE" render two.scene "${R[@]}" --photons 200000 --light-sampling power --out pow.exr
run "$PREE" render two.scene "${R[@]}" --photons 200000 --light-sampling power --photon-offset 200000 --out pow2.exr
rmse() { "$PREE" compare "$1" "$2" | awk '$1 == "rmse" { print $2 }'; }
bias=$(rmse pow.exr uni.exr) noise=$(rmse pow.exr pow2.exr)
awk -v b="$bias" -v n="$noise" 'BEGIN { exit !(b > 3 * n) }' || fail "uniform against power: RMSE $bias, noise $noise"
echo "ok: two lights: uniform against power RMSE $bias, power against power (other photons) $noise"
run "$PREE" render two.scene "${R[@]}" --photons 64000 --light-sampling power --checkpoint c.ckp --out c.png
"$PREE" render --resume c.ckp --light-sampling uniform 2>err.txt; rc=$?
expect_eq "resume with the other sampling: status" $rc 1
grep -q -- "--light-sampling uniform conflicts with the checkpoint's --light-sampling power" err.txt || fail "$(cat err.txt)"
echo "light_sampling: ok"
