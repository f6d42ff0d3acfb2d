#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The example scenes (scenes/examples/, docs/scene_format.md "Example scenes") render: each at
# 64x48 with 20,000 photons to the image and state hashes recorded (room and mesh show their area
# light: tests/checks/visible_lights.sh), with photons reaching its diffuse surfaces; and scripts/make-run.sh (make run SCENE=...) runs the
# whole software comparison on one of them, naming every output after the scene.
# cost: 8
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
[ -x "$PREE" ] || fail "$PREE not built (make build)"
while read -r name hashes; do
  run "$PREE" render "scenes/examples/$name.scene" --width 64 --height 48 --photons 20000 --out "$TMP/$name.png" \
      --stats "$TMP/$name.json" --quiet
  [ "$(json "$TMP/$name.json" photon_hits)" -gt 1000 ] || fail "$name: almost no photon reaches a diffuse surface"
  expect_eq "$name image/state hashes" "$(json "$TMP/$name.json" image_hash)/$(json "$TMP/$name.json" state_hash)" "$hashes"
done <<'LIST'
room c159ae7088d7116a/a75dabb2c8d4338c
mesh d959035a075d58c7/70a0fb00dfc453b4
caustics 92bd103be5cddae2/354758e09d683cea
LIST
mkdir -p "$TMP/bin" && cp "$PREE" "$TMP/bin/pree"   # alone: no co-simulation program beside it
PREE_RUN_SCENE=scenes/examples/room.scene PREE_RUN_SIZE="--width 48 --height 36 --photons 5000" \
  scripts/make-run.sh "$TMP/bin/pree" "$TMP/out" >"$TMP/log" 2>&1 || { tail -20 "$TMP/log"; fail "make-run.sh on room exited non-zero"; }
for f in room-double.png room-fp32.exr room-fp32-stable.exr room-fp32-vs-double.json room-fp32-stable-vs-double.json \
         room-fp32-vs-double-diff-flip.png run-scene.txt; do
  [ -s "$TMP/out/$f" ] || fail "make-run.sh on room: no $f"
done
grep -q "^== summary (room)" "$TMP/log" || fail "the summary does not name the scene"
grep -q "^fp32 stable vs double: SSIM" "$TMP/log" || fail "the summary does not give the stable datapath's figures"
expect_eq "make-run.sh on a missing scene" "$(PREE_RUN_SCENE=scenes/examples/none.scene scripts/make-run.sh "$TMP/bin/pree" "$TMP/o2" 2>&1 >/dev/null; echo "rc $?")" \
  "make run: SCENE=scenes/examples/none.scene: no such file
rc 2"
echo "scene_examples: ok"
