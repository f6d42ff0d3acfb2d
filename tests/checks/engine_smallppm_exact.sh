#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The paper's software baseline reproduced byte for byte: pree's smallppm-compatible path
# against the original program's own output (tests/data/smallppm/ORIGIN.md), with its counts.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
run "$PREE" render "$ROOT/scenes/cornell3" --width 320 --height 240 --photons 768000 --precision double \
    --grid smallppm --out "$TMP/x.ppm" --stats "$TMP/x.json" --quiet
gunzip -c "$ROOT/tests/data/smallppm/cornell3_320x240_768k.ppm.gz" > "$TMP/ref.ppm"
cmp "$TMP/x.ppm" "$TMP/ref.ppm" || fail "output differs from the reference smallppm image (cmp above)"
echo "ok: byte-identical to the reference"
expect_eq hit_points "$(json "$TMP/x.json" hit_points)" 152046
expect_eq photons_emitted "$(json "$TMP/x.json" photons_emitted)" 768000
expect_eq photon_hits "$(json "$TMP/x.json" photon_hits)" 2454756
expect_eq hpuo_candidates "$(json "$TMP/x.json" hpuo_candidates)" 78118412
expect_eq hpuo_normal_passed "$(json "$TMP/x.json" hpuo_normal_passed)" 61427542
expect_eq hpuo_accepted "$(json "$TMP/x.json" hpuo_accepted)" 3536147
expect_eq hit_points_zero_weight "$(json "$TMP/x.json" hit_points_zero_weight)" 12527
