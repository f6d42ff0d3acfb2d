#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Instruction counts of the engine's phases under callgrind: a figure that, unlike seconds on a
# virtual machine, repeats to the last digit for the same binary and inputs, so two commits can be
# compared without the machine's wander. One thread (the count of a parallel run depends on the
# schedule). Per configuration: total instructions, each phase's inclusive count, and the update's
# instructions per candidate and the trace's per photon segment.
# Usage: bench-count.sh PREE OUTDIR [--quick]   (--quick: 80x60 / 40k photons, for testing the script)
set -euo pipefail
pree=$1; out=$2; quick=${3:-}
mkdir -p "$out"
size="--width 320 --height 240 --photons 768000"
[ "$quick" = --quick ] && size="--width 80 --height 60 --photons 40000"
echo "cornell3 $size, 1 thread, valgrind --tool=callgrind (instructions executed)" | tee "$out/count.txt"
printf '%-16s %12s %10s %10s %10s %10s %10s %10s %12s %12s\n' configuration "total (M)" "eye" "grid" "trace" \
  "prepare" "screen" "apply" "upd/cand" "trace/seg" | tee -a "$out/count.txt"
for cfg in "smallppm double" "cells double" "cells fp32"; do
  set -- $cfg
  f="$out/count-$1-$2"
  valgrind --tool=callgrind --callgrind-out-file="$f.callgrind" "$pree" render scenes/cornell3 $size --grid $1 \
      --precision $2 --threads 1 --out "$f.ppm" --stats "$f.json" --quiet 2>"$f.log"
  callgrind_annotate --inclusive=yes "$f.callgrind" >"$f.annotate" 2>/dev/null
  python3 - "$cfg" "$f.annotate" "$f.json" "$f.log" <<'EOF' | tee -a "$out/count.txt"
import json, re, sys
label, ann, stats, log = sys.argv[1:]
inc = {}
for line in open(ann):
    m = re.match(r"\s*([\d,]+) \([\s\d.]+%\)\s+\S+:([\w.]+) \[", line)
    if m and m.group(2) not in inc:
        inc[m.group(2)] = int(m.group(1).replace(",", ""))
total = int(re.search(r"Collected : (\d+)", open(log).read()).group(1))
st = json.load(open(stats))
def g(name): return inc.get(name, 0)
upd = g("update_batch_prepare") + g("update_batch_screen") + g("update_batch_apply")
print("%-16s %12.1f %10.1f %10.1f %10.1f %10.1f %10.1f %10.1f %12.2f %12.1f" % (
    label, total / 1e6, g("eye_pass") / 1e6, g("grid_build") / 1e6, g("render_trace_block._omp_fn.0") / 1e6,
    g("update_batch_prepare") / 1e6, g("update_batch_screen") / 1e6, g("update_batch_apply") / 1e6,
    upd / st["hpuo_candidates"], g("render_trace_block._omp_fn.0") / st["photon_segments"]))
EOF
done
echo "(phases in millions of instructions, inclusive; files in $out/count-*)" | tee -a "$out/count.txt"
