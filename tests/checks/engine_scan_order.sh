#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bucket-major update (--scan bucket, the default: model/ppm/update_batch.c) against the
# photon-major oracle (--scan photon): the same image bits, final hit-point state and counts,
# for every grid, both precisions, 1 and 2 threads, with and without the AVX2 screening
# (PREE_NO_AVX2=1: the screening and the sphere group), and a triangle-mesh scene with glass;
# and the cells grid through its hash table (PREE_GRID_HASHED=1) against its dense cell map.
# level: quick
# cost: 66 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
hashes() { echo "$(json "$1" image_hash)/$(json "$1" state_hash)/$(json "$1" hpuo_candidates)/$(json "$1" hpuo_normal_passed)/$(json "$1" hpuo_accepted)"; }
for scene in cornell3 cornell-water; do
  for prec in double fp32; do
    for grid in cells smallppm brute; do
      size="--width 80 --height 60 --photons 40000"
      [ $grid = brute ] && size="--width 40 --height 30 --photons 8000"
      run "$PREE" render "$ROOT/scenes/$scene" $size --precision $prec --grid $grid --threads 1 \
          --scan photon --out "$TMP/p.ppm" --stats "$TMP/p.json" --quiet
      ref=$(hashes "$TMP/p.json")
      for t in 1 2; do
        run "$PREE" render "$ROOT/scenes/$scene" $size --precision $prec --grid $grid --threads $t \
            --scan bucket --out "$TMP/b.ppm" --stats "$TMP/b.json" --quiet
        expect_eq "$scene $prec $grid threads=$t bucket = photon" "$(hashes "$TMP/b.json")" "$ref"
      done
      # The scalar screening (what runs without AVX2) against the same oracle.
      run env PREE_NO_AVX2=1 "$PREE" render "$ROOT/scenes/$scene" $size --precision $prec --grid $grid \
          --threads 2 --scan bucket --out "$TMP/s.ppm" --stats "$TMP/s.json" --quiet
      expect_eq "$scene $prec $grid scalar bucket = photon" "$(hashes "$TMP/s.json")" "$ref"
    done
  done
done
# The cells grid numbered by its hash table (what scenes with very many cells use) instead of the
# dense cell map: the same bits.
for prec in double fp32; do
  size="--width 80 --height 60 --photons 40000"
  run "$PREE" render "$ROOT/scenes/cornell3" $size --precision $prec --threads 2 --out "$TMP/d.ppm" --stats "$TMP/d.json" --quiet
  run env PREE_GRID_HASHED=1 "$PREE" render "$ROOT/scenes/cornell3" $size --precision $prec --threads 2 \
      --out "$TMP/h.ppm" --stats "$TMP/h.json" --quiet
  expect_eq "cornell3 $prec cells hashed = dense" "$(hashes "$TMP/h.json")" "$(hashes "$TMP/d.json")"
done
