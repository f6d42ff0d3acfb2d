#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `pree check SCENE`: parses, loads meshes and validates without rendering; the report's counts
# and memory estimate for known scenes; the same one-line errors as render; no file written.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
cd "$TMP"
"$PREE" check "$ROOT/scenes/cornell3" --width 320 --height 240 > c3.txt || fail "check cornell3 (pree check $ROOT/scenes/cornell3)"
expect_eq "cornell3 spheres" "$(awk '$1=="spheres"{print $2}' c3.txt)" 9
expect_eq "cornell3 materials" "$(awk '$1=="materials"{print $2}' c3.txt)" 7
expect_eq "cornell3 lights" "$(awk '$1=="lights"{print $2}' c3.txt)" 1
expect_eq "cornell3 triangles" "$(awk '$1=="triangles"{print $2}' c3.txt)" 0
# The hit points from the eye rays of 1 pixel in 4 across and down (80x60 pixels; glass splits
# them): the render at this size has 152,046.
expect_eq "cornell3 hit points estimate" "$(awk '$1=="hit_points_estimate"{print $2}' c3.txt)" 151984
# 64 MiB + 76800 pixels * (48 + 200) bytes
expect_eq "cornell3 memory estimate" "$(awk '$1=="memory_estimate_bytes"{print $2}' c3.txt)" $((67108864 + 76800 * 248))
"$PREE" check "$ROOT/scenes/cornell-teapot" > tp.txt 2>/dev/null || fail "check cornell-teapot"
[ "$(awk '$1=="triangles"{print $2}' tp.txt)" -gt 1000 ] || fail "cornell-teapot: no mesh triangles: $(cat tp.txt)"
echo "ok: cornell-teapot: $(awk '$1=="triangles"' tp.txt)"
expect_eq "cornell3 glass as the engine takes it" "$(grep '^material glass ' c3.txt)" "material glass glass 0.999 0.999 0.999 ior 1.5"
expect_eq "cornell3 light" "$(grep '^light 0 ' c3.txt)" \
  "light 0 point at 50 60 85 flux 31415.9 31415.9 31415.9 photons 1/1 flux_share 1"
"$PREE" check "$ROOT/scenes/examples/room.scene" > room.txt || fail "check room.scene"
expect_eq "room: one light facing down" "$(grep '^light ' room.txt)" \
  "light 0 area 1 triangle area 0.18 facing 0 -1 0 flux 8.4823 8.4823 8.4823 photons 1/1 flux_share 1"
"$PREE" check "$ROOT/scenes/examples/caustics.scene" --width 200 --height 150 --eye-rays 2 > ca.txt || fail "check caustics.scene"
"$PREE" render "$ROOT/scenes/examples/caustics.scene" --width 200 --height 150 --eye-rays 2 --photons 1000 --quiet \
  --out ca.txt.png --stats ca.txt.json || fail "render caustics.scene"
python3 - "$(awk '$1=="hit_points_estimate"{print $2}' ca.txt)" "$(json ca.txt.json hit_points)" <<'PY' ||
import sys
e, n = float(sys.argv[1]), int(sys.argv[2])
print("caustics 200x150, 2 eye rays a pixel: hit points estimated %d, rendered %d (%+.2f%%)" % (e, n, 100 * (e / n - 1)))
sys.exit(0 if abs(e / n - 1) < 0.02 else 1)
PY
  fail "the caustics estimate is not within 2% of the render's hit points"
rm -f ca.txt.png ca.txt.json
"$PREE" check "$ROOT/scenes/examples/mesh.scene" > mesh.txt || fail "check mesh.scene"
expect_eq "mesh: the MTL rule's classes" "$(grep -c '^material alcove.obj:\(wall diffuse\|blue diffuse\|polished mirror\|panel_light diffuse\) ' mesh.txt)" 4
[ -z "$(ls -A | grep -v '\.txt$')" ] || fail "pree check wrote a file: $(ls -A)"
# An MTL texture is ignored, never silently: one warning naming the file, line and key.
printf 'newmtl m\nKd 0.5 0.5 0.5\nmap_Kd missing.png\nmap_Ks missing.png\n' > t.mtl
printf 'mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n' > t.obj
printf 'camera position 0 0 5 lookat 0 0 0 up 0 1 0 fov 40\nmesh t.obj\nlight point 0 0 3 intensity 1 1 1\n' > t.scene.txt
"$PREE" check t.scene.txt > /dev/null 2> tex.txt || fail "check t.scene.txt: $(cat tex.txt)"
expect_eq "texture warning" "$(cat tex.txt)" \
  "pree: warning: t.mtl:3: 'map_Kd': 2 texture lines ignored (PREE uses the constant colours Kd, Ks, Ke and Tf)"

expect_fail() {   # expect_fail NAME PATTERN ARGS...: exit 1, one stderr line matching PATTERN
  local name=$1 pat=$2; shift 2
  "$PREE" check "$@" >out.txt 2>err.txt; local rc=$?
  [ $rc -eq 1 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -qE -e "$pat" err.txt && [ ! -s out.txt ] ||
    fail "$name: exit $rc, stderr '$(cat err.txt)', want /$pat/ (pree check $*)"
  echo "ok: $name: $(cat err.txt)"
}
expect_fail "/dev/zero" "/dev/zero: not a regular file" /dev/zero
printf '%s\n' "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "depth 5 6" > bad.scene
expect_fail "extra value" "bad.scene:2: depth: unexpected '6'" bad.scene
expect_fail "memory" "would need about 15.5[6-9] GiB .* but --max-memory is 2.00 GiB" "$ROOT/scenes/cornell3" --width 8192 --height 8192 --max-memory 2G
printf '%s\n' "camera origin 0 0 0 dir 1 0 0 scale 0.5 near 0" "material m diffuse .5 .5 .5" "sphere 1 5 0 0 m" "light point 0 5 0 flux 1 1 1" > x.scene
expect_fail "camera rays" "camera: the eye rays .* have no direction" x.scene
"$PREE" check "$ROOT/scenes/cornell3" --bogus 2>err.txt; [ $? -eq 2 ] && grep -q "unknown option '--bogus'" err.txt || fail "unknown option: $(cat err.txt)"
echo "ok: unknown option: $(cat err.txt)"
