#!/usr/bin/env bash
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
  ls "$TMP" | grep -q '\.tmp\.' && fail "$name: a temporary file was left behind"
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
expect_error "stable datapath in double" "--datapath stable needs --precision fp32" render "$good" --datapath stable "${out[@]}"
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
