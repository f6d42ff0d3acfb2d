#!/usr/bin/env bash
# make run: render the default scene (cornell3, 320x240, 768,000 photons) in both precisions,
# compare them, and, when the co-simulation is built, render it through the Verilated RTL.
# Usage: make-run.sh PREE OUTDIR
set -euo pipefail
pree=$1; out=$2
mkdir -p "$out"
scene=scenes/cornell3
echo "== software render, double precision (the reference arithmetic)"
"$pree" render $scene --precision double --out "$out/cornell3-double.png" --out "$out/cornell3-double.exr" \
    --out "$out/cornell3-double.ppm" --stats "$out/cornell3-double.json"
echo "== software render, fp32 (the PREE datapath's arithmetic, the RTL's golden model)"
"$pree" render $scene --precision fp32 --out "$out/cornell3-fp32.png" --out "$out/cornell3-fp32.exr" \
    --stats "$out/cornell3-fp32.json"
echo "== fp32 against double"
"$pree" compare "$out/cornell3-double.exr" "$out/cornell3-fp32.exr" --diff "$out/cornell3-fp32-vs-double-diff.png" \
    | tee "$out/cornell3-fp32-vs-double.txt"
if "$pree" cosim --help >/dev/null 2>&1; then
  echo "== RTL co-simulation (Verilated PREE, 4 PREUs)"
  "$pree" cosim $scene --out "$out/cornell3-rtl.png" --out "$out/cornell3-rtl.exr" --stats "$out/cornell3-rtl.json"
  "$pree" compare "$out/cornell3-double.exr" "$out/cornell3-rtl.exr" --diff "$out/cornell3-rtl-vs-double-diff.png" \
      | tee "$out/cornell3-rtl-vs-double.txt"
fi
echo
echo "images and figures in $out/:"
ls -1 "$out" | sed 's/^/  /'
