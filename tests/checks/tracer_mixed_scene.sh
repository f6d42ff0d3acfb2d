#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The tracer's mixed case (analytic spheres, intersected in double in Embree user geometry, with
# triangles in one scene: scenes/cornell3-teapot): image and state hashes equal to those recorded
# with the per-sphere scalar tracer of commit 1b71716 (before the AVX2 sphere group and the
# one-pass choice of the nearest sphere), with and without AVX2, for 1 and 2 threads; a scene
# of 17 spheres (one primitive per sphere); and scenes of spheres only (9 and 16: no Embree, the
# group tested directly) against the same scenes through Embree (PREE_TRACER_EMBREE).
# level: quick
. "$(dirname "$0")/../lib/check.sh"
expect="23b58c52a53865b9/fc6638536e4aad73"
# (An empty PREE_NO_AVX2 would still turn AVX2 off: the variable is set only for the scalar runs.)
for avx in "" 1; do
  for t in 1 2; do
    run env ${avx:+PREE_NO_AVX2=1} "$PREE" render "$ROOT/scenes/cornell3-teapot" --width 96 --height 72 --photons 60000 \
        --threads $t --out "$TMP/m.ppm" --stats "$TMP/m.json" --quiet
    expect_eq "cornell3-teapot threads=$t no_avx2=${avx:-0} hashes" \
        "$(json "$TMP/m.json" image_hash)/$(json "$TMP/m.json" state_hash)" "$expect"
  done
done
# More than 16 spheres: one Embree primitive per sphere (the per-sphere path), against the hashes
# of the session-1 tracer on the same scene (cornell3 with 8 more balls).
{ cat "$ROOT/scenes/cornell3"; for i in 1 2 3 4 5 6 7 8; do echo "sphere 3 $((10 * i)) 5 $((40 + 5 * i)) ball"; done; } > "$TMP/many"
run "$PREE" render "$TMP/many" --width 80 --height 60 --photons 40000 --threads 2 --out "$TMP/many.ppm" --stats "$TMP/many.json" --quiet
expect_eq "17 spheres hashes" "$(json "$TMP/many.json" image_hash)/$(json "$TMP/many.json" state_hash)" "b3edde8fc34ebef3/fc150b1411cb223c"
# Spheres only, at most 16: the group is tested without Embree; through Embree's callback
# (PREE_TRACER_EMBREE) the image and state are the same, with and without AVX2.
{ cat "$ROOT/scenes/cornell3"; for i in 1 2 3 4 5 6 7; do echo "sphere 3 $((10 * i)) 5 $((40 + 5 * i)) ball"; done; } > "$TMP/sixteen"
for scene in "$ROOT/scenes/cornell3" "$TMP/sixteen"; do
  for avx in "" 1; do
    run env ${avx:+PREE_NO_AVX2=1} "$PREE" render "$scene" --width 80 --height 60 --photons 40000 --threads 2 \
        --out "$TMP/d.ppm" --stats "$TMP/d.json" --quiet
    run env ${avx:+PREE_NO_AVX2=1} PREE_TRACER_EMBREE=1 "$PREE" render "$scene" --width 80 --height 60 --photons 40000 \
        --threads 2 --out "$TMP/e.ppm" --stats "$TMP/e.json" --quiet
    expect_eq "$(basename "$scene") no_avx2=${avx:-0}: direct = Embree (image/state)" \
        "$(json "$TMP/d.json" image_hash)/$(json "$TMP/d.json" state_hash)" \
        "$(json "$TMP/e.json" image_hash)/$(json "$TMP/e.json" state_hash)"
  done
done
