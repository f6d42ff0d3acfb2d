#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What `pree render` tells a user: the last line names every file written (and --quiet prints
# nothing on success); an output that cannot be created (/proc) is refused before any work with
# one line and nothing written; --datapath stable alone renders fp32 (the bits of --precision
# fp32 --datapath stable); a photon count off the thousands says what it renders, once; the
# default image is NAME.png, NAME the scene file's name less .scene.
# cost: 3
source "$(dirname "$0")/../lib/check.sh"
cd "$TMP"
SCENE=$ROOT/scenes/examples/room.scene
R=(--width 24 --height 18 --threads 2)
run "$PREE" render "$SCENE" "${R[@]}" --photons 2500 --out a.png --out a.exr --stats a.json 2>err.txt
expect_eq "last line" "$(tail -1 err.txt)" "pree render: wrote a.png, a.exr, a.json"
expect_eq "rounding notes" "$(grep -c 'renders 2000 photons' err.txt)" 1
grep -q -- '--photons 2500 renders 2000 photons (whole batches of 1000)' err.txt || fail "rounding note: $(head -1 err.txt)"
expect_eq "photons rendered" "$(json a.json photons_emitted)" 2000
run "$PREE" render "$SCENE" "${R[@]}" --photons 2000 --quiet 2>q.txt
[ ! -s q.txt ] || fail "--quiet printed: $(cat q.txt)"
[ -s room.png ] || fail "no default image room.png: $(ls)"
run "$PREE" render "$SCENE" "${R[@]}" --photons 3000 --datapath stable --stats s.json --out s.png --quiet
run "$PREE" render "$SCENE" "${R[@]}" --photons 3000 --precision fp32 --datapath stable --stats f.json --out f.png --quiet
expect_eq "--datapath stable alone: precision" "$(json s.json precision)" fp32
expect_eq "--datapath stable alone = with --precision fp32" "$(json s.json image_hash)" "$(json f.json image_hash)"
start=$(date +%s.%N)
"$PREE" render "$SCENE" --width 320 --height 240 --photons 5000000 --out /proc/x.png --out b.png 2>p.txt; rc=$?
took=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
expect_eq "/proc output: status" $rc 1
expect_eq "/proc output: lines" "$(wc -l < p.txt)" 1
grep -q -- '--out /proc/x.png: cannot create a temporary file' p.txt || fail "/proc output: $(cat p.txt)"
[ ! -e b.png ] || fail "/proc output: the other image was written"
awk -v t="$took" 'BEGIN { exit !(t < 2) }' || fail "/proc output refused after $took s (after rendering?)"
echo "ok: /proc output refused in $took s"
# fp32 far from the origin: one warning naming the binary32 step against the initial radius.
far() {  # far X: a floor of two triangles about x = X, seen from above
  printf 'camera position %s 1 3 lookat %s 0 0 up 0 1 0 fov 40\nmaterial w diffuse .7 .7 .7\n' "$1" "$1"
  printf 'triangle %s 0 -2 %s 0 -2 %s 0 2 w\n' "$(($1 - 2))" "$(($1 + 2))" "$(($1 + 2))"
  printf 'triangle %s 0 -2 %s 0 2 %s 0 2 w\nlight point %s 2 0 intensity 1 1 1\n' "$(($1 - 2))" "$(($1 + 2))" "$(($1 - 2))" "$1"
}
far 0 > near.scene; far 20000 > far.scene
run "$PREE" render near.scene --width 32 --height 24 --photons 2000 --precision fp32 --out n.png --quiet 2>w0.txt
[ ! -s w0.txt ] || fail "a warning at the origin: $(cat w0.txt)"
run "$PREE" render far.scene --width 32 --height 24 --photons 2000 --precision fp32 --out f.png --quiet 2>w1.txt
grep -q "far.scene: hit points lie up to 200[0-9.]* from the origin, where one binary32 step (0.00195312) is .*% of the initial radius" w1.txt \
  || fail "no translation warning: $(cat w1.txt)"
echo "ok: $(cat w1.txt)"
echo "render_cli_workflow: ok"
