#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# --photon-offset K traces photon k with sequence index K + k: the photon paths of [0, 2N) are
# those of [0, N) and of [N, 2N) together (photon segments and hits add up exactly), offset 0
# is the default, and the result with an offset still does not depend on the thread count.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
size="--width 64 --height 48 --photons"
r() { run "$PREE" render "$ROOT/scenes/cornell3" $size "$@" --quiet; }
r 20000 --out "$TMP/a.ppm" --stats "$TMP/a.json"
r 20000 --photon-offset 0 --out "$TMP/z.ppm" --stats "$TMP/z.json"
expect_eq "offset 0 = default" "$(json "$TMP/z.json" image_hash)" "$(json "$TMP/a.json" image_hash)"
r 20000 --photon-offset 20000 --threads 1 --out "$TMP/b1.ppm" --stats "$TMP/b1.json"
r 20000 --photon-offset 20000 --threads 2 --out "$TMP/b2.ppm" --stats "$TMP/b2.json"
expect_eq "offset 20000, threads 1 = 2" "$(json "$TMP/b2.json" image_hash)/$(json "$TMP/b2.json" state_hash)" \
    "$(json "$TMP/b1.json" image_hash)/$(json "$TMP/b1.json" state_hash)"
[ "$(json "$TMP/b1.json" image_hash)" != "$(json "$TMP/a.json" image_hash)" ] || fail "offset 20000 gave the offset-0 image"
r 40000 --out "$TMP/c.ppm" --stats "$TMP/c.json"
for k in photon_segments photon_hits; do
  expect_eq "$k of [0, 40000) = [0, 20000) + [20000, 40000)" "$(json "$TMP/c.json" $k)" \
      "$(( $(json "$TMP/a.json" $k) + $(json "$TMP/b1.json" $k) ))"
done
