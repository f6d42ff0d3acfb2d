#!/usr/bin/env bash
# Engine speed on cornell3 at 320x240 with 768,000 photons: the update phase of the
# smallppm-compatible path in million candidates per second with 1 and 2 threads, and
# seconds end to end per grid and precision, with peak memory; the photon-major update loop
# (--scan photon) beside the default for comparison. Also checks that the images
# do not change with the thread count. Usage: bench-engine.sh PREE OUTDIR
set -euo pipefail
pree=$1; out=$2; mkdir -p "$out"
scene=scenes/cornell3
j() { python3 -c 'import json,sys; d=json.load(open(sys.argv[1]))
for k in sys.argv[2:]:
    v=d
    for p in k.split("."): v=v[p]
    print(v, end=" ")
print()' "$@"; }
printf '%-9s %-8s %-7s %-6s %11s %9s %9s %9s %9s %9s %10s %9s\n' grid precision threads scan "Mcand/s" update trace grid total wall peak_MiB image
# Each configuration runs three times; the row is the run with the least total time.
for cfg in "smallppm double 1 bucket" "smallppm double 1 photon" "smallppm double 2 bucket" "cells double 1 bucket" \
           "cells double 2 bucket" "cells fp32 2 bucket" "smallppm fp32 2 bucket"; do
  set -- $cfg
  f="$out/engine-$1-$2-t$3"; [ "$4" = bucket ] || f="$f-$4"
  best=""
  for r in 1 2 3; do
    start=$(date +%s.%N)
    "$pree" render $scene --width 320 --height 240 --photons 768000 --grid $1 --precision $2 --threads $3 --scan $4 \
        --out "$f.ppm" --stats "$f.r$r.json" --quiet
    w=$(echo "$(date +%s.%N) - $start" | bc)
    t=$(j "$f.r$r.json" seconds.total)
    if [ -z "$best" ] || [ "$(echo "$t < $bt" | bc)" = 1 ]; then best=$r; bt=$t; wall=$w; fi
  done
  cp "$f.r$best.json" "$f.json"
  read -r mc up tr gr tot rss img <<<"$(j "$f.json" update_mcand_per_s seconds.update seconds.trace seconds.grid seconds.total peak_rss_kib image_hash)"
  printf '%-9s %-8s %-7s %-6s %11.1f %9.3f %9.3f %9.3f %9.3f %9.3f %10.1f %9s\n' $1 $2 $3 $4 $mc $up $tr $gr $tot $wall \
      "$(echo "$rss / 1024" | bc -l)" "${img:0:8}"
done | tee "$out/engine.txt"
# The thread count must not change a bit.
for g in smallppm cells; do
  a=$(j "$out/engine-$g-double-t1.json" image_hash); b=$(j "$out/engine-$g-double-t2.json" image_hash)
  [ "$a" = "$b" ] || { echo "bench-engine: $g image differs between 1 and 2 threads" >&2; exit 1; }
done
for f in "$out/engine-smallppm-double-t1-photon.json"; do
  [ "$(j "$f" image_hash)" = "$(j "$out/engine-smallppm-double-t1.json" image_hash)" ] \
    || { echo "bench-engine: --scan photon and --scan bucket images differ" >&2; exit 1; }
done
cmp -s "$out/engine-smallppm-double-t1.ppm" <(gunzip -c tests/data/smallppm/cornell3_320x240_768k.ppm.gz) \
  && echo "smallppm path: byte-identical to the reference program's output" | tee -a "$out/engine.txt"
