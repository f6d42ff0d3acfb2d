#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# pbrt-v4 scene files (model/scene/scene_pbrt.c, docs/pbrt.md). scenes/pbrt/cornell3.pbrt renders
# the image of its native twin (scenes/cornell3 as a pbrt file can state it: a look-at camera with
# no near offset, no front wall, clear glass; the file's sppm radius given as --radius): the same
# fp32 image hash, and in double the same
# binary32 EXR. scenes/pbrt/room.pbrt (a PLY mesh, a rotated triangle mesh, a conductor sphere, a
# ReverseOrientation'd area light, sppm's photons and depth, Film's size) renders bit for bit as
# its native twin, in double and fp32. Against scenes/cornell3 itself at the same initial radius
# (front wall and near offset differ) the SSIM stays above 0.8 at this size. Unsupported directives and parameters are one
# line "FILE:LINE: ..." with nothing written; harmless ones a note each. pree cosim (4 PREUs)
# takes cornell3.pbrt's radius as the render does (the same image, 32x24 / 4,000 photons).
# cost: 10
source "$(dirname "$0")/../lib/check.sh"
cd "$TMP"
S=$ROOT/scenes
{ echo "camera position 50 48 295.6 lookat 50 47.957388 294.6 up 0 1 0 fov 28.799316231093776"
  echo "material glass glass 1 1 1 ior 1.5"
  grep -v 'front wall\|^camera\|^material glass' "$S/cornell3"; } > twin.scene
R=(--width 80 --height 60 --photons 60000 --quiet)
for p in double fp32; do
  run "$PREE" render twin.scene "${R[@]}" --radius 0.8323809424774448 --precision $p --out t-$p.exr --stats t-$p.json
  "$PREE" render "$S/pbrt/cornell3.pbrt" "${R[@]}" --precision $p --out q-$p.exr --stats q-$p.json 2>notes.txt \
    || fail "cornell3.pbrt ($p): $(cat notes.txt)"
  expect_eq "cornell3.pbrt = its native twin ($p): max |diff| in the EXR" \
    "$("$PREE" compare t-$p.exr q-$p.exr | awk '$1 == "max_abs" { print $2 }')" 0
done
expect_eq "cornell3.pbrt = its native twin: fp32 image hash" "$(json q-fp32.json image_hash)" "$(json t-fp32.json image_hash)"
expect_eq "cornell3.pbrt: the initial radius is sppm's radius" "$(json q-fp32.json initial_radius)" 0.8323809424774448
# pree cosim takes the file's radius too: its RTL image is the fp32 render's.
run "$PREE" cosim "$S/pbrt/cornell3.pbrt" --width 32 --height 24 --photons 4000 --quiet --no-reference --out rtl.exr
run "$PREE" render "$S/pbrt/cornell3.pbrt" --width 32 --height 24 --photons 4000 --quiet --precision fp32 --out fp32.exr
expect_eq "cornell3.pbrt: RTL image = fp32 render (pixel SHA-1)" "$(iinfo --hash rtl.exr | sed -n 's/.*SHA-1: //p')" \
  "$(iinfo --hash fp32.exr | sed -n 's/.*SHA-1: //p')"
expect_eq "notes (Film, Sampler, PixelFilter), once each" "$(grep -c '^pree: note: .*cornell3.pbrt:1[678]: ' notes.txt)" 3
run "$PREE" render "$S/cornell3" "${R[@]}" --radius 0.8323809424774448 --out c.exr
ssim=$("$PREE" compare c.exr q-double.exr | awk '$1 == "ssim" { print $2 }')
awk -v s="$ssim" 'BEGIN { exit !(s > 0.8) }' || fail "cornell3.pbrt against scenes/cornell3: SSIM $ssim"
echo "ok: cornell3.pbrt against scenes/cornell3 (no front wall, no near offset): SSIM $ssim"

cat > room.scene <<'SCENE'
camera position 1 1 4.6 lookat 1 1 0 up 0 1 0 fov 40
material white diffuse .75 .75 .75
material red diffuse .7 .15 .12
material mirror mirror .95 .95 .95
material lamp diffuse .8 .8 .8
triangle 0 0 0  2 0 0  2 0 2  white
triangle 0 0 0  2 0 2  0 0 2  white
triangle 0 0 0  0 2 0  2 2 0  white
triangle 0 0 0  2 2 0  2 0 0  white
triangle 0 0 0  0 2 0  0 2 2  red
triangle 0 0 0  0 2 2  0 0 2  red
sphere 0.35  0.6 0.35 0.9  mirror
triangle 0.75 1.99 0.75  1.25 1.99 1.25  1.25 1.99 0.75  lamp
light triangle 0.75 1.99 0.75  1.25 1.99 0.75  1.25 1.99 1.25  radiance 12 12 12
SCENE
for p in double fp32; do
  run "$PREE" render room.scene --width 64 --height 48 --photons 20000 --precision $p --out n.png --stats n.json --quiet
  "$PREE" render "$S/pbrt/room.pbrt" --precision $p --out r.png --stats r.json --quiet 2>/dev/null || fail "room.pbrt ($p)"
  expect_eq "room.pbrt = its native twin ($p): image/state hashes" "$(json r.json image_hash)/$(json r.json state_hash)" \
    "$(json n.json image_hash)/$(json n.json state_hash)"
done

bad() {  # bad NAME FILE-TEXT EXPECTED: one line naming file and line, status 1, nothing written
  printf '%b' "$2" > bad.pbrt
  rm -f o.png
  "$PREE" render bad.pbrt --out o.png 2>err.txt; local rc=$?
  expect_eq "$1: status" $rc 1
  grep -v '^pree: note: ' err.txt > e1.txt
  [ "$(wc -l < e1.txt)" -eq 1 ] || fail "$1: not one error line: $(cat err.txt)"
  grep -qF -- "$3" e1.txt || fail "$1: '$(cat e1.txt)' does not say '$3'"
  [ ! -e o.png ] || fail "$1: an image was written"
  echo "ok: $1: $(cat e1.txt)"
}
W='LookAt 0 1 4  0 1 0  0 1 0\nCamera "perspective"\nWorldBegin\n'
bad "unsupported directive" "${W}Texture \"t\" \"spectrum\" \"imagemap\"\n" "bad.pbrt:4: Texture is not supported"
bad "rough conductor" "${W}Material \"conductor\" \"float roughness\" 0.1\n" "bad.pbrt:4: Material: a rough conductor"
bad "partial sphere" "${W}Shape \"sphere\" \"float zmax\" 0.5\n" "bad.pbrt:4: Shape: a partial sphere"
bad "unknown parameter" "${W}Shape \"sphere\" \"float foo\" 3\n" "bad.pbrt:4: Shape: parameter \"float foo\" is not supported"
bad "gaussian filter" "PixelFilter \"gaussian\"\n${W}" "bad.pbrt:1: PixelFilter: \"gaussian\" is not supported"
bad "missing Include" "${W}Include \"none.pbrt\"\n" "bad.pbrt:4: Include: none.pbrt: No such file"
bad "sppm radius" "Integrator \"sppm\" \"float radius\" -1\n${W}" "bad.pbrt:1: Integrator: sppm's radius -1 is not in (0, 1e30]"
bad "area light on a sphere" "${W}AreaLightSource \"diffuse\"\nShape \"sphere\"\n" "bad.pbrt:5: Shape: an area light on a sphere"
bad "no light" "${W}Shape \"sphere\"\n" "bad.pbrt: the scene has no light"
echo "pbrt_scene: ok"
