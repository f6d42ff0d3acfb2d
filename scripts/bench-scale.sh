#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The engine at scale (issue 15): cornell3 at 320x240 / 768k, 1600x1200 / 19.2M and
# 3840x2160 / 82.9M photons, 2 threads, three ways: the default (screening batches of up to 4
# blocks as the re-filters give memory back, model/ppm/render_step.c), one block at a time
# (PREE_SCREEN_BLOCKS=1) and without the grid re-filter (PREE_NO_REFILTER=1, so one block at a
# time too): whole-process wall seconds and peak memory (/usr/bin/time), grid entries built and
# left after the last re-filter, candidates examined, the update's seconds and rate, bytes per hit
# point and per grid entry, and the image hash (the same all three ways).
# Usage: bench-scale.sh PREE OUTDIR   (SCALE_SIZES="320x240:768000 ..." picks the frames; RUNS=N
# runs per row, median by wall, default 1: the largest frame takes minutes and ~10 GB)
set -euo pipefail
pree=$1; out=$2; mkdir -p "$out"
runs=${RUNS:-1}
sizes=${SCALE_SIZES:-"320x240:768000 1600x1200:19200000 3840x2160:82900000"}
scene=scenes/cornell3
echo "cornell3, 2 threads; $runs run(s) per row (median by wall); $(nproc) cores: $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1)" | tee "$out/scale.txt"
printf '%-10s %9s %-11s %8s %9s %11s %11s %13s %8s %8s %6s %6s %s\n' frame photons update wall_s peak_MiB \
  entries entries_end candidates update_s Mcand/s B/hp B/entry image | tee -a "$out/scale.txt"
for sz in $sizes; do
  res=${sz%%:*}; photons=${sz#*:}; w=${res%x*}; h=${res#*x}
  for mode in batches one-block no-refilter; do
    f="$out/scale-$res-$photons-$mode"
    case $mode in
      batches) envs=() ;;
      one-block) envs=(PREE_SCREEN_BLOCKS=1) ;;
      no-refilter) envs=(PREE_NO_REFILTER=1) ;;
    esac
    files=()
    for r in $(seq 1 "$runs"); do
      env "${envs[@]}" /usr/bin/time -f '%e %M' -o "$f.r$r.time" "$pree" render $scene --width "$w" --height "$h" \
          --photons "$photons" --threads 2 --out "$f.ppm" --stats "$f.r$r.json" --quiet
      files+=("$f.r$r")
    done
    python3 - "$res" "$photons" "$mode" "${files[@]}" <<'EOF' | tee -a "$out/scale.txt"
import json, sys
res, photons, mode, runs = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4:]
rows = []
for f in runs:
    wall, kib = open(f + ".time").read().split()[:2]
    rows.append((float(wall), int(kib), json.load(open(f + ".json"))))
rows.sort(key=lambda r: r[0])
wall, kib, d = rows[len(rows) // 2]
print("%-10s %9d %-11s %8.2f %9.0f %11d %11d %13d %8.2f %8.1f %6d %6d %s" % (res, photons, mode, wall, kib / 1024,
      d["grid_entries"], d["grid_entries_final"], d["hpuo_candidates"], d["seconds"]["update"],
      d["update_mcand_per_s"], d["hit_point_bytes"], d["grid_entry_bytes"], d["image_hash"]))
EOF
  done
done
# Neither the batches nor the re-filter changes a bit: each frame's rows carry one image hash.
python3 - "$out/scale.txt" <<'EOF'
import sys
hashes = {}
for line in open(sys.argv[1]).read().splitlines()[2:]:
    c = line.split()
    hashes.setdefault((c[0], c[1]), set()).add(c[-1])
bad = [k for k, v in hashes.items() if len(v) != 1]
if bad:
    sys.exit("bench-scale: the batches or the re-filter changed the image at %s" % bad)
EOF
