#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The photon-map estimator against PPM (docs/photon_map.md): run time against error on cornell3
# and cornell-teapot, PPM and PM with k = 50, 200, 1000 (clustered search, max radius 4x the PPM
# initial radius), photons quadrupling from BASE, each against a long PPM reference with photons
# of its own (--photon-offset). Also the k-NN searches query against query (the clustered search
# over the single-pass kd-tree search and over the oracle, k = 50 to 2000, 400k to 6.4M photons)
# and the tracing/search/frame speedup for 1 and 2 threads with the dynamic and static task
# schedules, and the photon-path cap's cost and bias (scripts/bench-pm-bounces.sh). CPU seconds
# (user + sys) where one thread runs: the machine is shared. Tables in OUTDIR/pm_*.txt, the plots
# in OUTDIR/pm_bias.png, OUTDIR/pm_knn.png and OUTDIR/pm_threads.png.
# Usage: bench-pm.sh PREE OUTDIR [--quick]   (--quick: small sizes, for testing the script)
# PM_SECTIONS="bias knn threads bounces" (the default) picks the parts to run.
set -euo pipefail
pree=$1; out=$2; quick=${3:-}
mkdir -p "$out"
if [ "$quick" = --quick ]; then W=48; H=36; base=10000; steps=1; refn=160000; ks="50 200"
else W=160; H=120; base=100000; steps=2; refn=12800000; ks="50 200 1000"; fi
cpu_of() { awk '{print $1 + $2}' "$1"; }
js() { python3 -c 'import json,sys; v=json.load(open(sys.argv[1]))
for p in sys.argv[2].split("."): v=v[p]
print(v)' "$1" "$2"; }

sections=${PM_SECTIONS:-bias knn threads bounces}
has() { [[ " $sections " == *" $1 "* ]]; }
bias="$out/pm_bias.txt"
if has bias; then
printf '%-15s %-9s %10s %8s %9s %12s %10s\n' scene estimator photons k cpu_s rmse_linear peak_mib | tee "$bias"
for scene in cornell3 cornell-teapot; do
  ref="$out/pm-ref-$scene-${W}x${H}-$refn"
  if [ ! -f "$ref.exr" ]; then
    echo "bench-pm: reference $scene, $refn PPM photons from index $refn (once; kept in $out)" >&2
    "$pree" render scenes/$scene --width $W --height $H --photons $refn --photon-offset $refn --quiet \
        --out "$ref.exr" --stats "$ref.json"
  fi
  r0=$(js "$ref.json" initial_radius)
  rmax=$(python3 -c "print(4 * $r0)")
  for step in $(seq 0 $steps); do
    n=$((base << (2 * step)))
    for est in ppm $ks; do
      f="$out/pm-$scene-$est-$n"
      if [ "$est" = ppm ]; then args=(); k=-; else args=(--estimator pm --k "$est" --max-radius "$rmax"); k=$est; fi
      /usr/bin/time -f '%U %S' -o "$f.cpu" "$pree" render scenes/$scene --width $W --height $H --photons $n \
          "${args[@]}" --quiet --out "$f.exr" --stats "$f.json"
      rmse=$("$pree" compare "$ref.exr" "$f.exr" | awk '$1=="rmse"{print $2}')
      mib=$(( $(js "$f.json" peak_rss_kib) / 1024 ))
      printf '%-15s %-9s %10d %8s %9.2f %12.6g %10d\n' $scene $([ "$est" = ppm ] && echo ppm || echo pm) $n $k \
          "$(cpu_of "$f.cpu")" "$rmse" $mib | tee -a "$bias"
    done
  done
done

fi

# The k-NN searches query against query (--knn-bench: the three on the same trees in one process,
# repetitions interleaved, medians): the clustered search over the single-pass kd-tree search (the
# fair baseline) and over the oracle, cornell3 at max radius 3. Query time only: the trees,
# clusters and radiance estimates are timed apart. CPU seconds with one thread (a loaded machine
# takes CPU time from a process, not CPU seconds), wall seconds with two. The oracle (nanoflann,
# O(k) per result insertion) runs once, and only where k <= 200 and photons <= 1.6M (elsewhere it
# takes hours). KNN_CONFIGS="WxH:PHOTONS:K:THREADS ..." replaces the matrix; KNN_REPS the repetitions.
knn="$out/pm_knn.txt"
if has knn; then
if [ "$quick" = --quick ]; then configs=${KNN_CONFIGS:-"48x36:20000:50:1 48x36:20000:200:2"}
else
  configs=${KNN_CONFIGS:-}
  if [ -z "$configs" ]; then
    for res in 160x120 320x240; do for n in 400000 1600000 6400000; do for k in 50 200 1000 2000; do
      configs="$configs $res:$n:$k:1"; done; done; done
    configs="$configs 320x240:1600000:200:2 320x240:1600000:1000:2"
  fi
fi
reps=${KNN_REPS:-3}
printf '%-8s %8s %5s %2s %7s %7s %9s %9s %9s %8s %8s %8s %8s %9s\n' frame photons k t tree_s clust_s clustered kdtree naive vs_kdtree vs_naive fallback sparse same_bits | tee "$knn"
for c in $configs; do
  IFS=: read -r res n k t <<<"$c"
  oracle=0; [ "$k" -le 200 ] && [ "$n" -le 1600000 ] && oracle=1
  f="$out/pm-knn-$res-$n-$k-$t"
  "$pree" render scenes/cornell3 --width "${res%x*}" --height "${res#*x}" --photons "$n" --estimator pm --k "$k" \
      --max-radius 3 --threads "$t" --knn-bench "$reps" --knn-bench-oracle "$oracle" --quiet --out "$f.exr" --stats "$f.json"
  python3 - "$f.json" "$res" "$n" "$k" "$t" <<'PY' | tee -a "$knn"
import json, statistics, sys
d = json.load(open(sys.argv[1])); p = d["pm"]; b = p["bench"]; t = int(sys.argv[5])
ms = [m for m in ("clustered", "kdtree", "naive") if m in b]
q = {m: statistics.median(b[m]["cpu_query" if t == 1 else "sec_query"]) for m in ms}
hashes = {b[m]["state_hash"] for m in ms}
ratio = lambda m: "%8.2f" % (q[m] / q["clustered"]) if m in q else "%8s" % "-"
print("%-8s %8s %5s %2s %7.2f %7.2f %9.3f %9.3f %9s %s %s %8d %8d %9s" % (
    sys.argv[2], sys.argv[3], sys.argv[4], t, b["clustered"]["cpu_tree"], p["cpu_cluster"], q["clustered"],
    q["kdtree"], "%9.3f" % q["naive"] if "naive" in q else "-", ratio("kdtree"), ratio("naive"),
    b["clustered"]["fallback"], b["clustered"]["clusters_sparse"], "yes" if len(hashes) == 1 else "NO"))
PY
  rm -f "$f.exr"
done
# Speedup over the fair baseline against k, one line a frame and photon count (one thread).
for res in $(awk 'NR>1 && $4==1 {print $1}' "$knn" | sort -u); do
  for n in $(awk -v r=$res 'NR>1 && $1==r && $4==1 {print $2}' "$knn" | sort -un); do
    awk -v r=$res -v n=$n 'NR>1 && $1==r && $2==n && $4==1 {print $3, $10}' "$knn" | sort -n >"$out/pm-knn-$res-$n.dat"
  done
done
series=""
for d in "$out"/pm-knn-*.dat; do
  [ -s "$d" ] || continue
  name=$(basename "$d" .dat); name=${name#pm-knn-}
  series="$series${series:+, }\"$d\" using 1:2 with linespoints lw 2 title \"${name%-*}, ${name##*-} photons\""
done
gnuplot <<GP
set terminal pngcairo size 900,450 font ",10"
set output "$out/pm_knn.png"
set title "cornell3: query-only speedup of the clustered search over the single-pass kd-tree search (1 thread, medians of $reps)"
set logscale x; set xrange [40:2500]; set xlabel "k"; set ylabel "speedup (kdtree / clustered query CPU seconds)"
set grid; set key top left; set yrange [0:*]
plot $series, 1 with lines dt 2 lc rgb "black" title "1x"
GP
fi

# Threads and task schedules (paper 001): tracing, search and whole frame; wall seconds (the only
# measure of parallel speedup), medians of 3, with the CPU seconds beside them; at a quarter of
# the largest photon count. The repetitions are interleaved (each round runs every configuration
# once), so that a shared machine's changing load falls on all rows alike.
thr="$out/pm_threads.txt"
n=$((base << (2 * steps - 2)))
if has threads; then
configs=()
for sched in dynamic static; do for task in 100 1000 10000; do for t in 1 2; do configs+=("$sched $task $t"); done; done; done
for c in "${configs[@]}"; do read -r sched task t <<<"$c"; rm -f "$out/pm-t-$sched-$task-$t.rows"; done
for rep in 1 2 3; do
  echo "bench-pm: threads round $rep of 3" >&2
  for c in "${configs[@]}"; do
    read -r sched task t <<<"$c"
    f="$out/pm-t-$sched-$task-$t"
    /usr/bin/time -f '%U %S' -o "$f.cpu" "$pree" render scenes/cornell3 --width $W --height $H --photons $n \
        --estimator pm --task-schedule $sched --task-photons $task --threads $t --quiet --out "$f.exr" --stats "$f.json"
    echo "$(js "$f.json" pm.sec_map) $(js "$f.json" pm.sec_search) $(js "$f.json" seconds.total) $(cpu_of "$f.cpu")" >>"$f.rows"
  done
done
printf '%-9s %8s %7s %10s %10s %10s %10s\n' schedule task threads trace_s search_s total_s cpu_s | tee "$thr"
for c in "${configs[@]}"; do
  read -r sched task t <<<"$c"
  f="$out/pm-t-$sched-$task-$t"
  sort -k3 -g "$f.rows" | sed -n 2p | \
    awk -v s=$sched -v k=$task -v t=$t '{printf "%-9s %8d %7d %10.3f %10.3f %10.3f %10.2f\n", s, k, t, $1, $2, $3, $4}' | tee -a "$thr"
  rm -f "$f.rows"
done
# Speedup of 2 threads over 1 per configuration (tracing, search, whole frame), as a bar chart.
awk 'NR>1 {k=$1" "$2; if ($3==1) {a[k]=$4; b[k]=$5; c[k]=$6} else if (k in a) printf "%s/%s %.3f %.3f %.3f\n", $1, $2, a[k]/$4, b[k]/$5, c[k]/$6}' \
    "$thr" >"$out/pm_threads_speedup.dat"
gnuplot <<GP
set terminal pngcairo size 900,400 font ",10"
set output "$out/pm_threads.png"
set title "photon map, cornell3 ${W}x${H}, $n photons: speedup of 2 threads over 1 (medians of 3)"
set style data histograms; set style histogram clustered gap 1; set style fill solid 0.8 border -1
set yrange [0:2.2]; set ylabel "speedup"; set grid ytics; set key top left
set xlabel "schedule / photons per task unit"
plot "$out/pm_threads_speedup.dat" using 2:xtic(1) title "tracing", '' using 3 title "search", '' using 4 title "whole frame"
GP
fi

if has bounces; then "$(dirname "$0")/bench-pm-bounces.sh" "$pree" "$out" $quick; fi

[ -s "$bias" ] || exit 0   # the plot, from this run's or an earlier run's bias table
for scene in cornell3 cornell-teapot; do
  awk -v s=$scene 'NR>1 && $1==s && $2=="ppm"{print $5, $6}' "$bias" > "$out/pm-$scene-ppm.dat"
  for k in $ks; do awk -v s=$scene -v k=$k 'NR>1 && $1==s && $4==k{print $5, $6}' "$bias" > "$out/pm-$scene-k$k.dat"; done
done
plots() {
  local scene=$1 p="plot \"$out/pm-$1-ppm.dat\" using 1:2 with linespoints lw 2 title \"PPM\""
  for k in $ks; do p="$p, \"$out/pm-$scene-k$k.dat\" using 1:2 with linespoints title \"PM k=$k\""; done
  echo "set title \"$scene\"; $p"
}
gnuplot <<GP
set terminal pngcairo size 1000,420 font ",10"
set output "$out/pm_bias.png"
set multiplot layout 1,2 title "${W}x${H}: RMSE against a $refn-photon PPM reference, photons x4 from $base"
set logscale xy
set xlabel "CPU seconds (render, user + sys)"
set ylabel "RMSE, linear radiance"
set grid
$(plots cornell3)
$(plots cornell-teapot)
unset multiplot
GP
echo "bench-pm: $bias, $knn, $thr, $out/pm_bias.png" >&2
