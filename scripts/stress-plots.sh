#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# stress-plots.sh: the stress suite's log-log plots of |relative error| against accepted photons,
# from OUTDIR/hitpoint.csv (scripts/stress-hitpoint.sh): OUTDIR/numerics-r2.png (r2 against the
# closed form, both datapaths and the double reference, constant and random flux),
# OUTDIR/numerics-radiance.png (the radiance word against double; tau against long double) and
# OUTDIR/numerics-alpha.png (r2 error per alpha, each datapath). Points with an error of exactly
# 0 have no place on a log axis and are left out.
# Usage: scripts/stress-plots.sh OUTDIR
set -euo pipefail
out=$1
csv="$out/hitpoint.csv"
[ -f "$csv" ] || { echo "stress-plots: no $csv (run make stress-hitpoint)" >&2; exit 1; }
d="$out/plotdata"; mkdir -p "$d"
# series LABEL MODEL COLUMN -> accepts |error| (CSV columns: 8 accepts, 10 r2/closed, 13 tau/ld, 15 L/double)
series() { awk -F, -v l="$1" -v m="$2" -v c="$3" 'NR > 1 && $1 == l && $2 == m { v = $c + 0; if (v < 0) v = -v; print $8, v }' "$csv"; }
for l in main main-random; do
  for m in paper stable double; do
    series $l $m 10 > "$d/$l-$m-r2.dat"; series $l $m 13 > "$d/$l-$m-tau.dat"; series $l $m 15 > "$d/$l-$m-L.dat"
  done
done
alphas=$(awk -F, 'NR > 1 && $1 ~ /^alpha-/ { print substr($1, 7) }' "$csv" | sort -u -g)
for a in $alphas; do for m in paper stable; do series alpha-$a $m 10 > "$d/alpha-$a-$m-r2.dat"; done; done
gnuplot <<GP
set terminal pngcairo size 1000,460 font ",10"
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set grid
set xlabel "accepted photons"
set key top left
set output "$out/numerics-r2.png"
set title "one hit point, alpha 0.7, r2_0 = 1: |relative error of r2| against the closed form"
set ylabel "|relative error of r2|"
plot "$d/main-paper-r2.dat" w lp pt 7 ps 0.5 lc rgb "#c0392b" t "paper datapath, flux 1", \
     "$d/main-random-paper-r2.dat" w l dt 2 lc rgb "#e67e22" t "paper, random flux", \
     "$d/main-stable-r2.dat" w lp pt 5 ps 0.5 lc rgb "#2471a3" t "stable datapath, flux 1", \
     "$d/main-random-stable-r2.dat" w l dt 2 lc rgb "#5dade2" t "stable, random flux", \
     "$d/main-double-r2.dat" w lp pt 1 ps 0.6 lc rgb "#555555" t "double (smallppm's recurrence)"
set output "$out/numerics-radiance.png"
set multiplot layout 1,2 title "one hit point, alpha 0.7, r2_0 = 1, flux 1 (dashed: random flux)"
set title "radiance word L against double, N_{emitted} = 1000 x accepts"
set ylabel "|relative error of L|"
plot "$d/main-paper-L.dat" w lp pt 7 ps 0.5 lc rgb "#c0392b" t "paper", \
     "$d/main-random-paper-L.dat" w l dt 2 lc rgb "#e67e22" notitle, \
     "$d/main-stable-L.dat" w lp pt 5 ps 0.5 lc rgb "#2471a3" t "stable", \
     "$d/main-random-stable-L.dat" w l dt 2 lc rgb "#5dade2" notitle, \
     "$d/main-double-L.dat" w lp pt 1 ps 0.6 lc rgb "#555555" t "double vs long double"
set title "tau against the long-double recurrence"
set ylabel "|relative error of tau|"
plot "$d/main-paper-tau.dat" w lp pt 7 ps 0.5 lc rgb "#c0392b" t "paper", \
     "$d/main-random-paper-tau.dat" w l dt 2 lc rgb "#e67e22" notitle, \
     "$d/main-stable-tau.dat" w lp pt 5 ps 0.5 lc rgb "#2471a3" t "stable", \
     "$d/main-random-stable-tau.dat" w l dt 2 lc rgb "#5dade2" notitle, \
     "$d/main-double-tau.dat" w lp pt 1 ps 0.6 lc rgb "#555555" t "double"
unset multiplot
set output "$out/numerics-alpha.png"
set multiplot layout 1,2 title "|relative error of r2| against the closed form, r2_0 = 1, flux 1, per alpha (alpha 0.1 leaves the top: r2 below binary32's range)"
set yrange [1e-18:1e3]
set title "paper datapath"
set ylabel "|relative error of r2|"
plot $(first=1; for a in $alphas; do [ $first = 1 ] || printf ', '; first=0; printf '"%s" w lp pt 7 ps 0.4 t "alpha %s"' "$d/alpha-$a-paper-r2.dat" "$a"; done)
set title "stable datapath"
plot $(first=1; for a in $alphas; do [ $first = 1 ] || printf ', '; first=0; printf '"%s" w lp pt 5 ps 0.4 t "alpha %s"' "$d/alpha-$a-stable-r2.dat" "$a"; done)
unset multiplot
GP
echo "stress-plots: $out/numerics-r2.png $out/numerics-radiance.png $out/numerics-alpha.png" >&2
