#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Each skip of the default grid changes nothing: the image bits with skips equal those of
# the same grid without skips and of the brute-force grid (every hit point a candidate for
# every photon), in double and fp32. The skips must also really skip something.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
common=(--width 64 --height 48 --photons 40000 --quiet)
for prec in double fp32; do
  run "$PREE" render "$ROOT/scenes/cornell3" "${common[@]}" --precision $prec --out "$TMP/a.ppm" --stats "$TMP/skip.json"
  run "$PREE" render "$ROOT/scenes/cornell3" "${common[@]}" --precision $prec --no-skip --out "$TMP/b.ppm" --stats "$TMP/noskip.json"
  run "$PREE" render "$ROOT/scenes/cornell3" "${common[@]}" --precision $prec --grid brute --out "$TMP/c.ppm" --stats "$TMP/brute.json"
  img=$(json "$TMP/skip.json" image_hash)
  expect_eq "$prec image, skips vs no skips" "$(json "$TMP/noskip.json" image_hash)" "$img"
  expect_eq "$prec image, skips vs brute force" "$(json "$TMP/brute.json" image_hash)" "$img"
  for k in skip_photon_hits_no_cell skip_candidates_outside_radius skip_radiance_zero_weight; do
    v=$(json "$TMP/skip.json" $k)
    [ "$v" -gt 0 ] || fail "$prec: $k is $v: the skip did nothing on cornell3"
    echo "ok: $prec $k = $v"
    expect_eq "$prec $k without skips" "$(json "$TMP/noskip.json" $k)" 0
  done
  [ "$(json "$TMP/skip.json" grid_entries)" -lt "$(json "$TMP/noskip.json" grid_entries)" ] \
    || fail "$prec: zero-weight hit points were not left out of the grid"
  # Accepted updates of hit points with weight zero are work the skips avoid.
  echo "ok: $prec accepted with skips $(json "$TMP/skip.json" hpuo_accepted), without $(json "$TMP/noskip.json" hpuo_accepted)"
done
