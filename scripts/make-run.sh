#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# make run: render a scene (default cornell3; 320x240, 768,000 photons) in double precision
# first (the first picture, within a minute of the build on this machine), then fp32 with both
# datapaths and their comparison with the double render (figures as JSON, difference maps), then
# build the 4-PREU co-simulation (only that Verilated model) with BUILD_COSIM and render through
# the Verilated RTL. Ends with a summary: where the images are, and the figures.
# Usage: make-run.sh PREE OUTDIR [BUILD_COSIM]   (BUILD_COSIM: a command; none: skip the RTL)
# PREE_RUN_START: the `date +%s.%N` the run began (make run sets it before building), for the
# time to the first image; PREE_RUN_SCENE (make run SCENE=path): the scene, whose file name less
# its extension names the outputs (OUTDIR/NAME-double.png, ...; OUTDIR/run-scene.txt records it
# for the summary and make report); PREE_RUN_SIZE (make run SIZE=...), e.g. "--width 64 --height
# 48 --photons 20000", options given to every render.
set -euo pipefail
pree=$1; out=$2; build_cosim=${3:-}
start=${PREE_RUN_START:-$(date +%s.%N)}
mkdir -p "$out"
scene=${PREE_RUN_SCENE:-scenes/cornell3}
[ -f "$scene" ] || { echo "make run: SCENE=$scene: no such file" >&2; exit 2; }
name=$(basename "$scene"); name=${name%.*}
size=(${PREE_RUN_SIZE:-})
# Every path is checked before the first render (a bad SIZE fails here, not after the double render).
"$pree" check "$scene" "${size[@]}" >/dev/null
echo "$name" >"$out/run-scene.txt"
since() { awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }'; }

# compare_to_double KIND EXT: out/NAME-KIND.EXT against the double render; figures in
# out/NAME-KIND-vs-double.json, maps out/NAME-KIND-vs-double-diff{,-abs,-ssim,-flip}.png.
compare_to_double() {
  local base="$out/$name-$1-vs-double"
  "$pree" compare "$out/$name-double.$2" "$out/$name-$1.$2" --flip --diff "$base-diff.png" --json >"$base.json"
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1]))
print("   ssim %.7f  psnr %.2f dB  flip %.3g  max |diff| %.3g  max relative %.3g" % (d["ssim"], float(d["psnr_db"]), d["flip"], d["max_abs"], d["rel_max"]))' "$base.json"
}

echo "== software render, double precision (the reference arithmetic)"
"$pree" render "$scene" "${size[@]}" --precision double --out "$out/$name-double.png" --out "$out/$name-double.exr" \
    --out "$out/$name-double.ppm" --stats "$out/$name-double.json"
first=$(since)
echo "== first image: $out/$name-double.png, $first s after make run began"
echo "$first" >"$out/first-image-seconds.txt"
echo "== software render, fp32 (the PREE datapath's arithmetic, the RTL's golden model)"
"$pree" render "$scene" "${size[@]}" --precision fp32 --out "$out/$name-fp32.png" --out "$out/$name-fp32.exr" \
    --stats "$out/$name-fp32.json"
echo "== fp32 against double (linear EXR)"
compare_to_double fp32 exr
echo "== software render, fp32 with the stable datapath (exact count, wide 1/r2 and tau/r2)"
"$pree" render "$scene" "${size[@]}" --precision fp32 --datapath stable --out "$out/$name-fp32-stable.png" \
    --out "$out/$name-fp32-stable.exr" --stats "$out/$name-fp32-stable.json"
echo "== fp32 stable against double (linear EXR)"
compare_to_double fp32-stable exr
if [ -n "$build_cosim" ]; then
  echo "== building the 4-PREU co-simulation (one Verilated model; several minutes the first time)"
  $build_cosim
fi
rtl=0
if "$pree" cosim --help >/dev/null 2>&1; then
  echo "== RTL co-simulation: the Verilated PREE (4 PREUs) does every hit-point update and the radiance pass"
  echo "   (a few minutes: about 10.5 million operations through the RTL)"
  # The double render's own size and photons (a pbrt file's Film and sppm settings included).
  read -r w h n <<<"$(python3 -c 'import json, sys; d = json.load(open(sys.argv[1]))
print(d["width"], d["height"], d["photons_emitted"])' "$out/$name-double.json")"
  "$pree" cosim "$scene" "${size[@]}" --width "$w" --height "$h" --photons "$n" --out "$out/$name-rtl.png" \
      --stats "$out/$name-rtl.json"
  echo "== RTL against double (8-bit PNG)"
  compare_to_double rtl png
  rtl=1
fi
echo
python3 scripts/run-summary.py "$out" "$rtl"
