#!/usr/bin/env bash
# make run: render the default scene (cornell3, 320x240, 768,000 photons) in double precision
# first (the first picture, within a minute of the build on this machine), then fp32 with both
# datapaths and their comparison with the double render (figures as JSON, difference maps), then
# build the 4-PREU co-simulation (only that Verilated model) with BUILD_COSIM and render through
# the Verilated RTL. Ends with a summary: where the images are, and the figures.
# Usage: make-run.sh PREE OUTDIR [BUILD_COSIM]   (BUILD_COSIM: a command; none: skip the RTL)
# PREE_RUN_START: the `date +%s.%N` the run began (make run sets it before building), for the
# time to the first image; PREE_RUN_SIZE, e.g. "--width 64 --height 48 --photons 20000", for a
# quick look.
set -euo pipefail
pree=$1; out=$2; build_cosim=${3:-}
start=${PREE_RUN_START:-$(date +%s.%N)}
mkdir -p "$out"
scene=scenes/cornell3
size=(${PREE_RUN_SIZE:-})
since() { awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }'; }

# compare_to_double NAME: B = out/cornell3-NAME.EXT against the double render; figures in
# out/cornell3-NAME-vs-double.json, maps out/cornell3-NAME-vs-double-diff{,-abs,-ssim,-flip}.png.
compare_to_double() {
  local name=$1 ext=$2 base="$out/cornell3-$1-vs-double"
  "$pree" compare "$out/cornell3-double.$ext" "$out/cornell3-$name.$ext" --flip --diff "$base-diff.png" --json >"$base.json"
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1]))
print("   ssim %.7f  psnr %.2f dB  flip %.3g  max |diff| %.3g  max relative %.3g" % (d["ssim"], float(d["psnr_db"]), d["flip"], d["max_abs"], d["rel_max"]))' "$base.json"
}

echo "== software render, double precision (the reference arithmetic)"
"$pree" render $scene "${size[@]}" --precision double --out "$out/cornell3-double.png" --out "$out/cornell3-double.exr" \
    --out "$out/cornell3-double.ppm" --stats "$out/cornell3-double.json"
first=$(since)
echo "== first image: $out/cornell3-double.png, $first s after make run began"
echo "$first" >"$out/first-image-seconds.txt"
echo "== software render, fp32 (the PREE datapath's arithmetic, the RTL's golden model)"
"$pree" render $scene "${size[@]}" --precision fp32 --out "$out/cornell3-fp32.png" --out "$out/cornell3-fp32.exr" \
    --stats "$out/cornell3-fp32.json"
echo "== fp32 against double (linear EXR)"
compare_to_double fp32 exr
echo "== software render, fp32 with the stable datapath (exact count, wide 1/r2 and tau/r2)"
"$pree" render $scene "${size[@]}" --precision fp32 --datapath stable --out "$out/cornell3-fp32-stable.png" \
    --out "$out/cornell3-fp32-stable.exr" --stats "$out/cornell3-fp32-stable.json"
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
  "$pree" cosim $scene "${size[@]}" --out "$out/cornell3-rtl.png" --stats "$out/cornell3-rtl.json"
  echo "== RTL against double (8-bit PNG)"
  compare_to_double rtl png
  rtl=1
fi
echo
python3 scripts/run-summary.py "$out" "$rtl"
