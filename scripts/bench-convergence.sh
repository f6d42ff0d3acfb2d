#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Run time against error: cornell3 at 768,000 x 2^k photons (k = 0..6) in both precisions, each
# precision one render writing a convergence series (--write-at: each point has the bits of a
# render of that count; its seconds, wall and CPU, are the render's so far, from its statistics),
# each point compared with a long double-precision reference render (512x the photons, 8x the
# longest). Prints a table (photons, precision, wall seconds, CPU seconds, RMSE on linear radiance,
# SSIM of the 8-bit images) and draws out/bench/convergence.png with gnuplot. The reference's
# photons are disjoint from the renders' (--photon-offset).
# Usage: bench-convergence.sh PREE OUTDIR [--quick|--plot-only]   (--quick: 96x72, for testing the
# script; --plot-only: redraw the plot from OUTDIR/convergence.txt)
set -euo pipefail
pree=$1; out=$2; quick=${3:-}
mkdir -p "$out"
scene=scenes/cornell3
if [ "$quick" = --quick ]; then W=96; H=72; base=69000; steps=3; refmul=16
else W=320; H=240; base=768000; steps=6; refmul=512; fi
# The reference traces photons of its own: sequence indices [R, 2R) for R reference photons,
# disjoint from the [0, N) of every render it judges (with shared photons, the error of the
# longest renders would be understated).
ref="$out/conv-ref-${W}x${H}-$((base * refmul))-from-$((base * refmul))"
if [ ! -f "$ref.exr" ]; then
  echo "bench-convergence: reference render, $((base * refmul)) photons from index $((base * refmul)) (once; kept in $out)" >&2
  "$pree" render $scene --width $W --height $H --photons $((base * refmul)) --photon-offset $((base * refmul)) \
      --precision double --out "$ref.exr" --out "$ref.png" --stats "$ref.json"
fi
tab="$out/convergence.txt"
if [ "$quick" = --plot-only ]; then W=320; H=240; base=768000; refmul=512; fi
[ "$quick" = --plot-only ] || {
printf '%-12s %-9s %9s %9s %12s %10s %10s\n' photons precision seconds cpu_s rmse_linear ssim_8bit psnr_8bit | tee "$tab"
points=$(for k in $(seq 0 $steps); do echo $((base << k)); done | paste -sd,)
for prec in double fp32; do
  "$pree" render $scene --width $W --height $H --photons $((base << steps)) --precision $prec --write-at "$points" \
      --out "$out/conv-$prec.exr" --out "$out/conv-$prec.png" --stats "$out/conv-$prec.json" --quiet
  for k in $(seq 0 $steps); do
    n=$((base << k)); f="$out/conv-$prec-$n"
    read -r sec cpu <<<"$(python3 -c 'import json,sys; s=json.load(open(sys.argv[1]))["seconds"]; print(s["total"], s["cpu"])' "$f.json")"
    rmse=$("$pree" compare "$ref.exr" "$f.exr" | awk '$1=="rmse"{print $2}')
    read -r ssim psnr <<<"$("$pree" compare "$ref.png" "$f.png" | awk '$1=="ssim"{s=$2} $1=="psnr_db"{p=$2} END{print s, p}')"
    printf '%-12s %-9s %9.3f %9.2f %12.6g %10.6f %10.3f\n' $n $prec $sec $cpu $rmse $ssim $psnr | tee -a "$tab"
  done
done
}
# Plotted against CPU seconds (all threads of the render so far): on a shared machine wall time
# measures the other load as much as the engine.
awk 'NR>1 && $2=="double"{print $4, $5, $6}' "$tab" > "$out/conv-double.dat"
awk 'NR>1 && $2=="fp32"{print $4, $5, $6}' "$tab" > "$out/conv-fp32.dat"
gnuplot <<GP
set terminal pngcairo size 1000,420 font ",10"
set output "$out/convergence.png"
set multiplot layout 1,2 title "cornell3 ${W}x${H}: error against a $((base * refmul))-photon reference, photons doubling from $base"
set logscale xy
set xlabel "CPU seconds (render, user + sys)"
set ylabel "RMSE, linear radiance"
set grid
plot "$out/conv-double.dat" using 1:2 with linespoints title "double", \
     "$out/conv-fp32.dat" using 1:2 with linespoints title "fp32"
unset logscale y
set logscale x
set ylabel "SSIM, 8-bit images"
plot "$out/conv-double.dat" using 1:3 with linespoints title "double", \
     "$out/conv-fp32.dat" using 1:3 with linespoints title "fp32"
unset multiplot
GP
echo "plot: $out/convergence.png"
