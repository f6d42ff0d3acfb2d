#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Capping photon paths (pree render --max-bounces W, paper 001; docs/photon_map.md): the photon-map
# estimator on cornell3 with W = 1, 2, 3, 5 and uncapped, the same photons. Per W and tracing
# schedule (dynamic with 1,000 photons a task unit, the default; static with 10,000): photons
# stored, ray segments, the longest path and the longest task unit (segments; the unit against
# the mean unit), the tracing phase's CPU seconds (both threads) and its busiest and least busy
# thread's, the frame's CPU seconds, on 2 threads, medians of 3 (the run with the median tracing
# CPU time; the repetitions interleaved; CPU seconds, which other load on the machine does not
# inflate); and the bias against the uncapped render: RMSE of linear radiance and the mean
# radiance kept (oiiotool --stats).
# Usage: bench-pm-bounces.sh PREE OUTDIR [--quick]   (--quick: a small frame, for testing)
# Table in OUTDIR/pm_bounces.txt.
set -euo pipefail
pree=$1; out=$2; quick=${3:-}
mkdir -p "$out"
if [ "$quick" = --quick ]; then W=48; H=36; n=20000; else W=160; H=120; n=400000; fi
caps="1 2 3 5 none"
scheds="dynamic:1000 static:10000"
js() { python3 -c 'import json,sys; v=json.load(open(sys.argv[1]))
for p in sys.argv[2].split("."): v=v[p]
print(v)' "$1" "$2"; }
mean() { oiiotool --stats "$1" | awk '/Stats Avg:/ {print ($3 + $4 + $5) / 3}'; }

for c in $caps; do for s in $scheds; do rm -f "$out/pm-b-$c-${s%:*}.rows"; done; done
for rep in 1 2 3; do
  echo "bench-pm-bounces: round $rep of 3" >&2
  for c in $caps; do for s in $scheds; do
    f="$out/pm-b-$c-${s%:*}"
    cap=(); [ "$c" = none ] || cap=(--max-bounces "$c")
    "$pree" render scenes/cornell3 --width $W --height $H --photons $n --estimator pm --threads 2 \
        --task-schedule "${s%:*}" --task-photons "${s#*:}" "${cap[@]}" --quiet --out "$f.exr" --stats "$f.json"
    echo "$(js "$f.json" pm.cpu_map) $(js "$f.json" pm.thread_busy_max) $(js "$f.json" pm.thread_busy_min)" \
         "$(js "$f.json" seconds.cpu)" >>"$f.rows"
  done; done
done

tab="$out/pm_bounces.txt"
printf '%-5s %-8s %9s %10s %5s %9s %6s %9s %7s %7s %9s %9s %7s\n' W schedule stored segments path \
    unit_seg unit_x trace_cpu busy_hi busy_lo frame_cpu rmse kept_% | tee "$tab"
for s in $scheds; do
  ref="$out/pm-b-none-${s%:*}"
  ref_mean=$(mean "$ref.exr")
  for c in $caps; do
    f="$out/pm-b-$c-${s%:*}"
    units=$(( (n + ${s#*:} - 1) / ${s#*:} ))
    seg=$(js "$f.json" photon_segments)
    rmse=0; [ "$c" = none ] || rmse=$("$pree" compare "$ref.exr" "$f.exr" | awk '$1 == "rmse" {print $2}')
    read -r tc bhi blo tot <<<"$(sort -g "$f.rows" | sed -n 2p)"
    printf '%-5s %-8s %9d %10d %5d %9d %6.2f %9.3f %7.3f %7.3f %9.2f %9.5f %7.1f\n' "$c" "${s%:*}" \
        "$(js "$f.json" photon_hits)" "$seg" "$(js "$f.json" pm.path_segments_max)" \
        "$(js "$f.json" pm.unit_segments_max)" "$(python3 -c "print($(js "$f.json" pm.unit_segments_max) * $units / $seg)")" \
        "$tc" "$bhi" "$blo" "$tot" "$rmse" "$(python3 -c "print(100 * $(mean "$f.exr") / $ref_mean)")" | tee -a "$tab"
    rm -f "$f.rows"
  done
done
echo "bench-pm-bounces: $tab" >&2
