#!/usr/bin/env bash
# make run: render the default scene (cornell3, 320x240, 768,000 photons) in both precisions and
# with both fp32 datapaths, compare them with the double render, then build the 4-PREU co-simulation (only that Verilated model) with BUILD_COSIM
# and render through the Verilated RTL.
# Usage: make-run.sh PREE OUTDIR [BUILD_COSIM]   (BUILD_COSIM: a command; none: skip the RTL)
set -euo pipefail
pree=$1; out=$2; build_cosim=${3:-}
mkdir -p "$out"
scene=scenes/cornell3
size=(${PREE_RUN_SIZE:-})   # e.g. PREE_RUN_SIZE="--width 64 --height 48 --photons 20000" for a quick look
echo "== software render, double precision (the reference arithmetic)"
"$pree" render $scene "${size[@]}" --precision double --out "$out/cornell3-double.png" --out "$out/cornell3-double.exr" \
    --out "$out/cornell3-double.ppm" --stats "$out/cornell3-double.json"
echo "== software render, fp32 (the PREE datapath's arithmetic, the RTL's golden model)"
"$pree" render $scene "${size[@]}" --precision fp32 --out "$out/cornell3-fp32.png" --out "$out/cornell3-fp32.exr" \
    --stats "$out/cornell3-fp32.json"
echo "== fp32 against double"
"$pree" compare "$out/cornell3-double.exr" "$out/cornell3-fp32.exr" --diff "$out/cornell3-fp32-vs-double-diff.png" \
    | tee "$out/cornell3-fp32-vs-double.txt"
echo "== software render, fp32 with the stable datapath (exact count, wide 1/r2 and tau/r2)"
"$pree" render $scene "${size[@]}" --precision fp32 --datapath stable --out "$out/cornell3-fp32-stable.png" \
    --out "$out/cornell3-fp32-stable.exr" --stats "$out/cornell3-fp32-stable.json"
echo "== fp32 stable against double"
"$pree" compare "$out/cornell3-double.exr" "$out/cornell3-fp32-stable.exr" \
    --diff "$out/cornell3-fp32-stable-vs-double-diff.png" | tee "$out/cornell3-fp32-stable-vs-double.txt"
if [ -n "$build_cosim" ]; then
  echo "== building the 4-PREU co-simulation (one Verilated model; a few minutes the first time)"
  $build_cosim
fi
if "$pree" cosim --help >/dev/null 2>&1; then
  echo "== RTL co-simulation: the Verilated PREE (4 PREUs) does every hit-point update and the radiance pass"
  echo "   (a few minutes: about 10.5 million operations through the RTL)"
  "$pree" cosim $scene "${size[@]}" --out "$out/cornell3-rtl.png" --stats "$out/cornell3-rtl.json"
  python3 - "$out/cornell3-rtl.json" <<'PY' | tee "$out/cornell3-rtl-summary.txt"
import json, sys
d = json.load(open(sys.argv[1]))
def find(o, key):
    if isinstance(o, dict):
        for k, v in o.items():
            if k == key: return v
            r = find(v, key)
            if r is not None: return r
    return None
for k in ["pass", "hp_words_differing", "image_words_differing", "ssim_vs_double", "snr_db_vs_double",
          "cycles", "preu_utilization", "simulated_ops_per_cpu_second"]:
    print(f"rtl {k} {find(d, k)}")
PY
  "$pree" compare "$out/cornell3-double.png" "$out/cornell3-rtl.png" --diff "$out/cornell3-rtl-vs-double-diff.png" \
      | tee "$out/cornell3-rtl-vs-double.txt"
fi
echo
echo "images and figures in $out/:"
ls -1 "$out" | sed 's/^/  /'
