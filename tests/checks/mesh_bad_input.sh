#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Bad mesh input through the command line: each case must exit non-zero with exactly one line
# on stderr that names the file (and line where there is one), and write no image; degenerate
# triangles among good ones and a camera inside a closed mesh are documented non-errors (a
# warning line / a correct, here black, image).
# level: quick
set -u
cd "$(dirname "$0")/../.."
[ -x build/pree ] || make -s build/pree >/dev/null || { echo "FAIL: cannot build build/pree (make build/pree)"; exit 1; }
pree=${PREE:-$PWD/build/pree}
d=build/checks/mesh_bad_input; rm -rf "$d"; mkdir -p "$d"; cd "$d"
fail=0
scene() {   # scene NAME MESH-LINE: a scene file with one mesh line
  printf 'camera position 0 0 5 lookat 0 0 0 up 0 1 0 fov 60\nmaterial w diffuse .5 .5 .5\n%s\nlight point 0 0 3 intensity 1 1 1\n' "$2" > "$1"
}
# expect_error NAME MESH-LINE EXPECTED-SUBSTRING
expect_error() {
  scene "s_$1" "$2"
  local cmd="$pree render s_$1 --width 16 --height 12 --photons 1000 --quiet --out s_$1.png"
  $cmd 2>"$1.err"; local rc=$?
  local lines; lines=$(wc -l <"$1.err")
  if [ $rc -eq 0 ] || [ "$lines" -ne 1 ] || ! grep -qF -- "$3" "$1.err" || [ -e "s_$1.png" ]; then
    echo "FAIL $1: rc=$rc, $lines stderr line(s), image $( [ -e "s_$1.png" ] && echo written || echo absent ):"
    sed 's/^/    /' "$1.err"
    echo "  expected one line containing: $3"
    echo "  reproduce: (cd $d && $cmd)"
    fail=1
  else
    echo "ok $1: $(cat "$1.err")"
  fi
}
printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' > nan.obj
printf 'v 0 0 0\nv 1 0 0\nv 1 inf 0\nf 1 2 3\n' > inf.obj
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n' > index.obj
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nv 1 x 0\n' > number.obj
printf 'mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n' > nomtl.obj
printf 'mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl a\nf 1 2 3\n' > badmtl.obj
printf 'newmtl a\nKd 0.5 0.5 0.5\nillum seven\n' > bad.mtl
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n' > degenerate.obj
printf 'v 0 0 0\nv 1 0 0\n' > empty.obj
head -c 2000 /dev/zero > binary.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' | gzip -c | head -c 30 > truncated.obj.gz
printf 'solid nothing\n' > broken.ply
# Found by the mesh fuzzer (make fuzz, 30 min): Assimp leaks its partial mesh when it rejects
# this file (tests/fuzz/lsan.supp); pree gives one line and no image.
cp ../../../tests/fuzz/corpus/mesh/found-assimp-leak-bad-index.obj fuzzleak.obj
expect_error fuzzleak  "mesh fuzzleak.obj material w"     "s_fuzzleak:3: fuzzleak.obj: OBJ: bad vertex index"
expect_error missing   "mesh missing.obj"                 "s_missing:3: missing.obj: No such file or directory"
expect_error nan       "mesh nan.obj"                     "s_nan:3: nan.obj:3: coordinate 'nan' is not finite"
expect_error inf       "mesh inf.obj"                     "s_inf:3: inf.obj:3: coordinate 'inf' is not finite"
expect_error index     "mesh index.obj"                   "s_index:3: index.obj:4: face refers to vertex 9, but 3 are defined"
expect_error number    "mesh number.obj"                  "s_number:3: number.obj:5: malformed number 'x'"
expect_error nomtl     "mesh nomtl.obj"                   "s_nomtl:3: nomtl.obj:1: material library: none.mtl: No such file"
expect_error badmtl    "mesh badmtl.obj"                  "s_badmtl:3: bad.mtl:3: 'illum' needs an integer 0..10"
expect_error degenerate "mesh degenerate.obj material w"  "s_degenerate:3: degenerate.obj: no triangles (1 degenerate dropped"
expect_error empty     "mesh empty.obj material w"        "s_empty:3: empty.obj: no faces"
expect_error binary    "mesh binary.obj material w"       "s_binary:3: binary.obj:1: binary data"
expect_error truncated "mesh truncated.obj.gz material w" "s_truncated:3: truncated.obj.gz: unexpected end of file"
expect_error ply       "mesh broken.ply material w"       "s_ply:3: broken.ply: "
expect_error option    "mesh nan.obj rotate q 3"          "s_option:3: mesh: rotate: axis must be x, y or z"
printf 'camera position 0 0 5 lookat 0 0 0 up 0 1 0 fov 60\nlight point 0 0 3 intensity 1 1 1\n' > s_nogeometry
cmd="$pree render s_nogeometry --width 16 --height 12 --photons 1000 --quiet --out s_nogeometry.png"
if $cmd 2>ng.err || ! grep -q "s_nogeometry:3: the scene has no geometry" ng.err || [ -e s_nogeometry.png ]; then
  echo "FAIL empty scene: $(cat ng.err)"; echo "  reproduce: (cd $d && $cmd)"; fail=1
else echo "ok empty scene: $(cat ng.err)"; fi

# Degenerate triangles among good ones: one warning line, exit 0, an image.
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n' > somedegenerate.obj
scene s_some "mesh somedegenerate.obj material w"
cmd="$pree render s_some --width 16 --height 12 --photons 1000 --quiet --out s_some.png"
if ! $cmd 2>some.err || [ "$(cat some.err)" != "pree: warning: somedegenerate.obj: dropped 1 degenerate (zero-area) triangle" ] || [ ! -s s_some.png ]; then
  echo "FAIL degenerate warning: $(cat some.err)"; echo "  reproduce: (cd $d && $cmd)"; fail=1
else echo "ok degenerate warning: $(cat some.err)"; fi

# Camera inside a closed mesh (a cube, light outside): exit 0 and an all-black image.
printf 'v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nf 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n' > cube.obj
printf 'camera position 0 0 0 lookat 0 0 -1 up 0 1 0 fov 60\nmaterial w diffuse .5 .5 .5\nmesh cube.obj material w\nlight point 0 0 3 intensity 1 1 1\n' > s_inside
cmd="$pree render s_inside --width 16 --height 12 --photons 1000 --quiet --out s_inside.ppm"
if ! $cmd 2>inside.err || [ -s inside.err ] || [ "$(tail -n +4 s_inside.ppm | tr -s ' \n' '\n' | sort -u | tr -d '\n')" != "0" ]; then
  echo "FAIL camera inside: $(cat inside.err)"; echo "  reproduce: (cd $d && $cmd)"; fail=1
else echo "ok camera inside a closed mesh: black image, exit 0"; fi
exit $fail
