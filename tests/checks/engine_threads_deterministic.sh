#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Determinism: 1, 2 and 3 threads give the same image bits and the same final hit-point
# state, in both precisions and with every grid.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
for prec in double fp32; do
  for grid in cells smallppm; do
    ref=""
    for t in 1 2 3; do
      run "$PREE" render "$ROOT/scenes/cornell3" --width 96 --height 72 --photons 60000 --precision $prec \
          --grid $grid --threads $t --out "$TMP/i$t.ppm" --stats "$TMP/s$t.json" --quiet
      got="$(json "$TMP/s$t.json" image_hash)/$(json "$TMP/s$t.json" state_hash)/$(json "$TMP/s$t.json" hpuo_accepted)"
      if [ -z "$ref" ]; then ref=$got; else expect_eq "$prec $grid threads=$t hashes" "$got" "$ref"; fi
    done
  done
done
