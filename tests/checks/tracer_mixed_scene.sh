#!/usr/bin/env bash
# The tracer's mixed case (analytic spheres, intersected in double in Embree user geometry, with
# triangles in one scene: scenes/cornell3-teapot): image and state hashes equal to those recorded
# with the per-sphere scalar tracer of commit 1b71716 (before the AVX2 sphere group and the
# one-pass choice of the nearest sphere), with and without AVX2, for 1 and 2 threads.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
expect="23b58c52a53865b9/fc6638536e4aad73"
for avx in "" 1; do
  for t in 1 2; do
    run env PREE_NO_AVX2=$avx "$PREE" render "$ROOT/scenes/cornell3-teapot" --width 96 --height 72 --photons 60000 \
        --threads $t --out "$TMP/m.ppm" --stats "$TMP/m.json" --quiet
    expect_eq "cornell3-teapot threads=$t no_avx2=${avx:-0} hashes" \
        "$(json "$TMP/m.json" image_hash)/$(json "$TMP/m.json" state_hash)" "$expect"
  done
done
