#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A photon with more candidates than the PREE's index table takes for one photon (2048) goes to
# the RTL as several photons of the same record, each with a part of its candidates
# (cosim_sched_offer): the hit-point memory and the image are still the fp32 model's, bit for
# bit. The scene: a 6 x 1.6 floor tile seen close up (about 2,600 of the 96x72 hit points on it)
# and a far wall that makes the initial radius (from the hit points' box) 23 units, so that a
# photon on the tile has every tile hit point as a candidate: 115 photon hits with candidates
# stream as 265 photons. pree cosim (4 PREUs) with the scheduler and without it
# (--no-schedule): 0 differing words, more photons streamed than photon hits (the split), and
# the RTL image equals pree render --precision fp32.
# cost: 12 (its seconds in a serial run; 9 CPU s)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
[ -x "$PREE" ] || fail "$PREE not built (make build)"
cat >"$TMP/split.scene" <<'EOF'
camera position 0 0.6 0.9 lookat 0 0 -0.2 up 0 1 0 fov 60
material white diffuse .8 .8 .8
triangle -3 0 -0.8  -3 0 0.8  3 0 0.8  white
triangle -3 0 -0.8  3 0 0.8  3 0 -0.8  white
triangle -3000 -3000 -1000  3000 -3000 -1000  0 3000 -1000  white
light point 0 2.5 0 intensity 1 1 1
EOF
frame=("$TMP/split.scene" --width 96 --height 72 --photons 1000 --quiet)
pixels_sha() { iinfo --hash "$1" | sed -n 's/.*SHA-1: //p'; }
run "$PREE" render "${frame[@]}" --precision fp32 --threads 2 --out "$TMP/model.exr"
for o in "" --no-schedule; do
  run "$PREE" cosim "${frame[@]}" $o --no-reference --out "$TMP/rtl$o.exr" --stats "$TMP/c$o.json"
  expect_eq "${o:-scheduled}: differing hit-point/image words" \
    "$(json "$TMP/c$o.json" hp_words_differing)/$(json "$TMP/c$o.json" image_words_differing)" 0/0
  expect_eq "${o:-scheduled}: RTL image = fp32 render (pixel SHA-1)" "$(pixels_sha "$TMP/rtl$o.exr")" \
    "$(pixels_sha "$TMP/model.exr")"
done
hits=$(json "$TMP/c.json" photon_hits_streamed) sent=$(json "$TMP/c.json" schedule.photons)
echo "photon hits streamed $hits, photons the scheduler sent $sent"
[ "$sent" -gt "$hits" ] 2>/dev/null || fail "no photon was split ($sent photons for $hits photon hits)"
echo "cosim_photon_split: ok"
