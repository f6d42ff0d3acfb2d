#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Bad input: each case gives a one-line error naming the problem, a non-zero exit, and no
# output file (image or statistics) left behind.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
good="$ROOT/scenes/cornell3"

# expect_error NAME PATTERN ARGS...: pree must fail, print one line matching PATTERN, write nothing.
expect_error() {
  local name=$1 pattern=$2; shift 2
  rm -f "$TMP/out.png" "$TMP/out.json"
  "$PREE" "$@" >"$TMP/stdout" 2>"$TMP/stderr"; local rc=$?
  [ $rc -ne 0 ] || fail "$name: exit status 0 (command: pree $*)"
  [ "$(wc -l < "$TMP/stderr")" -eq 1 ] || { cat "$TMP/stderr"; fail "$name: expected one error line (command: pree $*)"; }
  grep -qE -e "$pattern" "$TMP/stderr" || fail "$name: error '$(cat "$TMP/stderr")' does not match /$pattern/"
  [ ! -e "$TMP/out.png" ] && [ ! -e "$TMP/out.json" ] || fail "$name: an output file was written"
  ls -a "$TMP" | grep -q '\.tmp[-.]' && fail "$name: a temporary file was left behind"
  echo "ok: $name (exit $rc): $(cat "$TMP/stderr")"
}

scene() { printf '%s\n' "$@" > "$TMP/bad.scene"; }
out=(--out "$TMP/out.png" --stats "$TMP/out.json" --quiet)

expect_error "missing scene file" "nonexistent: No such file" render "$TMP/nonexistent" "${out[@]}"
expect_error "no scene given" "no scene given" render "${out[@]}"
expect_error "unknown option" "unknown option '--bogus'" render "$good" --bogus "${out[@]}"
expect_error "unknown command" "unknown command" frobnicate
expect_error "zero width" "--width: 0 is out of range" render "$good" --width 0 "${out[@]}"
expect_error "absurd height" "--height: 99999999 is out of range" render "$good" --height 99999999 "${out[@]}"
expect_error "non-numeric width" "--width: 'abc' is not an integer" render "$good" --width abc "${out[@]}"
expect_error "zero photons" "--photons: 0 is out of range" render "$good" --photons 0 "${out[@]}"
expect_error "absurd photons" "--photons: .* is out of range" render "$good" --photons 99999999999999 "${out[@]}"
expect_error "negative threads" "--threads: -1 is out of range" render "$good" --threads -1 "${out[@]}"
expect_error "bad precision" "--precision: 'half'" render "$good" --precision half "${out[@]}"
expect_error "bad grid" "--grid: 'kd'" render "$good" --grid kd "${out[@]}"
expect_error "missing option value" "--width needs a value" render "$good" --width
expect_error "flag given a value" "option '--no-skip' takes no value" render "$good" --no-skip=1 "${out[@]}"
expect_error "2^63 photons" "--photons: 9223372036854775808 is out of range" render "$good" --photons 9223372036854775808 "${out[@]}"
expect_error "ambiguous prefix" "unknown option '--photon'" render "$good" --photon 1000 "${out[@]}"
# getopt_long's forms: --name=value, and operands after the options.
run "$PREE" render --width=8 --height=6 --photons=1000 --quiet --out "$TMP/eq.ppm" "$good"
[ -s "$TMP/eq.ppm" ] || fail "--name=value form: no image"
expect_error "bad image extension" "must end in .png, .ppm or .exr" render "$good" --out "$TMP/out.jpg"
expect_error "unwritable output" "out.png" render "$good" --width 8 --height 8 --photons 1000 --out "$TMP/nodir/out.png" --quiet

scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 .5" "sphere 1 0 0 -5 m" "light point 0 5 0 intensity 1 1 1" "sphere 1 0 0 nan m"
expect_error "NaN in a sphere" "bad.scene:5: number 'nan' is not finite" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 .5" "sphere 1 0 0 -5 m" "light point 0 5 0 intensity 1 1 1" "sphere 1 0 0 -5 nosuch"
expect_error "unknown material" "bad.scene:5: unknown material 'nosuch'" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 .5" "bogus 1 2 3"
expect_error "unknown directive" "bad.scene:3: unknown directive 'bogus'" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 .5" "sphere 1 0 0 m"
expect_error "too few values" "bad.scene:3: (too few values|expected a number)" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 1.5" 
expect_error "colour out of range" "bad.scene:2: material 'm': colour components" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 .5" "sphere -1 0 0 -5 m"
expect_error "negative radius" "bad.scene:3: sphere radius must be positive" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 .5" "sphere 1 0 0 -5 m"
expect_error "no light" "bad.scene:4: the scene has no light" render "$TMP/bad.scene" "${out[@]}"
scene "material m diffuse .5 .5 .5" "sphere 1 0 0 -5 m" "light point 0 5 0 intensity 1 1 1"
expect_error "no camera" "the scene has no camera" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 0 scale 0.5 near 0"
expect_error "zero view direction" "bad.scene:1: camera: the view direction is zero" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 .5" "triangle 0 0 0 1 1 1 2 2 2 m"
expect_error "degenerate triangle" "bad.scene:3: triangle is degenerate" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "material m diffuse .5 .5 .5" "material m mirror 1 1 1"
expect_error "duplicate material" "bad.scene:3: material 'm' is defined twice" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0" "depth 40"
expect_error "absurd depth" "bad.scene:2: depth 40" render "$TMP/bad.scene" "${out[@]}"
# The update rule's options, and values beyond binary32's range at the PREE boundary (fp32).
expect_error "alpha zero" "--alpha: 0 is out of range" render "$good" --alpha 0 "${out[@]}"
expect_error "alpha above one" "--alpha: 1.5 is out of range" render "$good" --alpha 1.5 "${out[@]}"
expect_error "alpha not a number" "--alpha: 'nan' is not a number" render "$good" --alpha nan "${out[@]}"
expect_error "bad datapath" "--datapath: 'fast' is not paper or stable" render "$good" --datapath fast "${out[@]}"
expect_error "stable datapath in double" "--datapath stable is fp32.s .*drop --precision double" render "$good" --precision double --datapath stable "${out[@]}"
expect_error "bad layout" "--layout: 'hilbert' is not spatial or pixel" render "$good" --layout hilbert "${out[@]}"
sed 's/intensity 2500 2500 2500/intensity 1e38 1e38 1e38/' "$good" > "$TMP/hot.scene"
for dp in paper stable; do
  expect_error "light flux beyond binary32 ($dp)" "photon 0's flux .* beyond binary32's range" render "$TMP/hot.scene" \
    --width 16 --height 12 --photons 1000 --precision fp32 --datapath $dp "${out[@]}"
done
printf 'camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0\n\0sphere 1 0 0 -5 m\n' > "$TMP/bad.scene"
expect_error "NUL byte in a line" "bad.scene:2: binary data \\(a NUL byte\\)" render "$TMP/bad.scene" "${out[@]}"
{ printf '#'; head -c 5000 /dev/zero | tr '\0' x; printf ' sphere\n'; } > "$TMP/bad.scene"
expect_error "long comment stays a comment" "bad.scene:2: the scene has no camera" render "$TMP/bad.scene" "${out[@]}"
head -c 3000 /dev/urandom > "$TMP/bad.scene"
"$PREE" render "$TMP/bad.scene" "${out[@]}" 2>"$TMP/stderr" && fail "binary garbage accepted"
[ "$(wc -l < "$TMP/stderr")" -eq 1 ] && grep -q "bad.scene:" "$TMP/stderr" || fail "binary garbage: $(cat "$TMP/stderr")"
echo "ok: binary garbage: $(cat "$TMP/stderr")"

# Issue 14: values beyond what the tracer (Embree's ray.valid()) and binary32 hold, inputs that
# are not regular files, extra fields, duplicate singletons, and bytes the terminal must not see.
cam="camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 0"; mat="material m diffuse .5 .5 .5"
sph="sphere 1 0 0 -5 m"; lgt="light point 0 5 0 intensity 1 1 1"
small=(--width 8 --height 8 --photons 1000)
scene "camera origin 2e18 0 0 dir 0 0 -1 scale 0.5 near 0" "$mat" "$sph" "$lgt"
expect_error "camera origin 2e18" "bad.scene:1: value '2e18' lies beyond \\+-1e\\+15" render "$TMP/bad.scene" "${out[@]}"
scene "$cam" "$mat" "$sph" "light point 2e18 5 0 intensity 1 1 1"
expect_error "light at 2e18" "bad.scene:4: value '2e18' lies beyond" render "$TMP/bad.scene" "${out[@]}"
scene "camera position 0 0 0 lookat 0 0 -1 up 0 1 0 fov 1e-300" "$mat" "$sph" "$lgt"
expect_error "fov 1e-300" "bad.scene:1: camera: scale .* is not in \\[1e-06, 1e\\+06\\]" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 1e308 near 0" "$mat" "$sph" "$lgt"
expect_error "scale 1e308" "bad.scene:1: camera: scale 1e\\+308 is not" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 0.5 near 1e308" "$mat" "$sph" "$lgt"
expect_error "near 1e308" "bad.scene:1: value '1e308' lies beyond" render "$TMP/bad.scene" "${out[@]}"
scene "camera origin 0 0 0 dir 0 0 -1 scale 1e6 near 1e15" "$mat" "$sph" "$lgt"
expect_error "eye rays beyond the tracer" "bad.scene: camera: the eye rays .* start beyond \\+-1e17" render "$TMP/bad.scene" "${small[@]}" "${out[@]}"
scene "camera origin 0 0 0 dir 1 0 0 scale 0.5 near 0" "$mat" "$sph" "$lgt"
expect_error "view along x without up" "bad.scene: camera: the eye rays .* have no direction" render "$TMP/bad.scene" "${small[@]}" "${out[@]}"
scene "$cam" "$mat" "sphere 1e300 0 0 -5 m" "$lgt"
expect_error "sphere radius 1e300" "bad.scene:3: value '1e300' lies beyond" render "$TMP/bad.scene" "${out[@]}"
scene "$cam" "$mat" "$sph" "light point 0 5 0 intensity 1e308 1 1"
expect_error "intensity 1e308" "bad.scene:4: light power 1e308 1 1 overflows double" render "$TMP/bad.scene" "${out[@]}"
scene "$cam" "$mat" "$sph" "$lgt" "depth 5 6 7"
expect_error "depth with extra values" "bad.scene:5: depth: unexpected '6'" render "$TMP/bad.scene" "${out[@]}"
scene "$cam" "$mat" "$sph" "$lgt" "epsilon 1e-4 2"
expect_error "epsilon with extra values" "bad.scene:5: epsilon: unexpected '2'" render "$TMP/bad.scene" "${out[@]}"
scene "$cam" "material m diffuse .5 .5 .5 ior 1.5" "$sph" "$lgt"
expect_error "ior on a diffuse material" "bad.scene:2: material 'm': 'ior' applies to glass only" render "$TMP/bad.scene" "${out[@]}"
scene "$cam" "$mat" "$sph" "$lgt" "$cam"
expect_error "second camera" "bad.scene:5: camera is given twice \\(first on line 1\\)" render "$TMP/bad.scene" "${out[@]}"
scene "$cam" "$mat" "$sph" "$lgt" "depth 5" "depth 6"
expect_error "second depth" "bad.scene:6: depth is given twice \\(first on line 5\\)" render "$TMP/bad.scene" "${out[@]}"
scene "$cam" "$mat" "$sph" "$lgt" $'bogus\e[31m\x01red'
expect_error "escape bytes are escaped" "bad.scene:5: unknown directive 'bogus\\\\x1B\\[31m\\\\x01red'" render "$TMP/bad.scene" "${out[@]}"
grep -q $'\e' "$TMP/stderr" && fail "a raw escape byte reached stderr"
expect_error "/dev/zero as the scene" "/dev/zero: not a regular file" render /dev/zero "${out[@]}"
mkfifo "$TMP/fifo"
expect_error "a FIFO as the scene" "fifo: not a regular file" render "$TMP/fifo" "${out[@]}"
mkdir "$TMP/dir.scene"
expect_error "a directory as the scene" "dir.scene: is a directory, not a file" render "$TMP/dir.scene" "${out[@]}"
expect_error "2^63 photons" "--photons: 9223372036854775808 is out of range" render "$good" --photons 9223372036854775808 "${out[@]}"
expect_error "1x1 image" "the 1 hit point\\(s\\) lie at one place, so the initial radius .* is 0" render "$good" --width 1 --height 1 --photons 1000 "${out[@]}"
expect_error "1x1 image (smallppm grid)" "initial radius .* is 0" render "$good" --width 1 --height 1 --photons 1000 --grid smallppm "${out[@]}"
# A line of exactly the limit (1 MiB with its newline) is read; one byte more is an error.
{ printf '%s\n' "$cam" "$mat" "$sph" "$lgt"; printf '#'; head -c $((1048576 - 2)) /dev/zero | tr '\0' x; printf '\n'; } > "$TMP/long.scene"
run "$PREE" render "$TMP/long.scene" "${small[@]}" --out "$TMP/long.png" --quiet
{ printf '%s\n' "$cam" "$mat" "$sph" "$lgt"; printf '#'; head -c $((1048576 - 1)) /dev/zero | tr '\0' x; printf '\n'; } > "$TMP/bad.scene"
expect_error "line one byte over the limit" "bad.scene:5: line longer than 1048576 bytes" render "$TMP/bad.scene" "${out[@]}"
# A UTF-8 byte-order mark before the first line is skipped; one later is an unknown directive.
{ printf '\xef\xbb\xbf'; printf '%s\n' "$cam" "$mat" "$sph" "$lgt"; } > "$TMP/bom.scene"
run "$PREE" render "$TMP/bom.scene" "${small[@]}" --out "$TMP/bom.png" --quiet
{ printf '%s\n' "$cam"; printf '\xef\xbb\xbf'; printf '%s\n' "$mat" "$sph" "$lgt"; } > "$TMP/bad.scene"
expect_error "a BOM after line 1" "bad.scene:2: unknown directive '\\\\xEF\\\\xBB\\\\xBFmaterial'" render "$TMP/bad.scene" "${out[@]}"
# Finite light power whose image overflows: an error, never inf or NaN pixels with status 0.
scene "$cam" "$mat" "$sph" "light point 0 0 -3 flux 1.7e308 1 1" "light point 0 0 -3 flux 1.7e308 1 1"
expect_error "image beyond double's range" "bad.scene: [0-9]+ pixel values are not finite .*nothing written" render "$TMP/bad.scene" "${small[@]}" "${out[@]}"

# Outputs are checked before any work, are never an input or another output (by inode), and
# never replace anything but a regular file; the inputs stay as they were.
cp "$good" "$TMP/scene.png"; cp "$good" "$TMP/keep.scene"; ln "$TMP/keep.scene" "$TMP/hard.json"
expect_error "--stats over the scene" "--stats .*keep.scene: the same file as the scene" render "$TMP/keep.scene" --out "$TMP/out.png" --stats "$TMP/keep.scene" --quiet
expect_error "--out over a scene named .png" "--out .*scene.png: the same file as the scene" render "$TMP/scene.png" --out "$TMP/scene.png" --quiet
expect_error "--stats a hard link to the scene" "--stats .*hard.json: the same file as the scene" render "$TMP/keep.scene" --out "$TMP/out.png" --stats "$TMP/hard.json" --quiet
cmp -s "$good" "$TMP/keep.scene" && cmp -s "$good" "$TMP/scene.png" || fail "an input was changed"
expect_error "--stats and --out the same file" "--stats .*/x.png: the same file as --out" render "$good" --out "$TMP/x.png" --stats "$TMP/./x.png" --quiet
[ ! -e "$TMP/x.png" ] || fail "x.png written"
expect_error "two --out spellings of one file" "--out .*: the same file as --out" render "$good" --out "$TMP/out.png" --out "$TMP/../$(basename "$TMP")/out.png" --quiet
expect_error "--stats /dev/null" "--stats /dev/null: not a regular file" render "$good" "${out[@]:0:2}" --stats /dev/null --quiet
[ -c /dev/null ] || fail "/dev/null is no longer a device"
ln -s "$TMP/keep.scene" "$TMP/link.png"
expect_error "--out a symbolic link" "--out .*link.png: is a symbolic link" render "$good" --out "$TMP/link.png" --quiet
expect_error "--stats into a missing directory" "--stats .*nodir/s.json: the directory .* does not exist" render "$good" --out "$TMP/out.png" --stats "$TMP/nodir/s.json" --quiet
long=$(printf 'n%.0s' $(seq 252))
expect_error "a name over 255 bytes" "the name is longer than the file system's 255 bytes" render "$good" --out "$TMP/$long.png" --quiet
run "$PREE" render "$good" "${small[@]}" --out "$TMP/${long:0:251}.png" --stats "$TMP/${long:0:250}.json" --quiet
[ -s "$TMP/${long:0:251}.png" ] && [ -s "$TMP/${long:0:250}.json" ] || fail "255-byte names not written"
ls -a "$TMP" | grep -q '\.tmp[-.]' && fail "a temporary file was left behind"
echo "ok: 255-byte output names are written"
# Memory: the estimate is checked before anything large is allocated, against --max-memory here
# (the machine's own limits, RLIMIT_AS and MemAvailable, otherwise).
expect_error "8192x8192 beyond --max-memory" "needs? about 1[0-9].[0-9]+ GiB .* but --max-memory is 1.00 GiB" render "$good" --width 8192 --height 8192 --max-memory 1G "${out[@]}"
expect_error "2.4 M hit points beyond --max-memory" "the hit points' state and grid.* but --max-memory is 0.44 GiB" render "$good" --width 1280 --height 960 --photons 1000 --max-memory 450M "${out[@]}"
expect_error "bad --max-memory" "--max-memory: '2x' is not a size" render "$good" --max-memory 2x "${out[@]}"
expect_error "tiny --max-memory" "--max-memory: 1K is out of range" render "$good" --max-memory 1K "${out[@]}"
