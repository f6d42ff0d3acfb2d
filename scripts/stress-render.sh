#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# stress-render.sh: the whole-render part of the stress suite (make stress-render; issue 10,
# docs/numerics_renders.md).
#  1. Drift: scenes/cornell3 and the caustic scene scenes/cornell-sphere at 16x12 with 1e6, 1e7
#     and 1e8 photons, rendered in double, fp32 with the paper's datapath and fp32 with the stable
#     one; each fp32 image against the double image of the same photons (the photon paths are
#     the same, so the difference is the datapath's arithmetic alone): relative L2 over the image
#     (10^(-SNR/20) from `pree compare --json`: sqrt(sum (b - a)^2 / sum a^2)) and max |b - a| / peak.
#  2. Scale invariance: copies of both scenes with every length multiplied by s = 1e-4 .. 1e6
#     (cornell3: sphere centres and radii, camera origin and near distance, light position, and
#     the point light's intensity by s^2 so that radiance stays the same; cornell-sphere: the
#     mesh's `scale s` and the camera's position and look-at point; its area light's flux grows as
#     s^2 by itself), each rendered like the s = 1 copy and compared with it. Scales written 2^K
#     are powers of two: every coordinate, distance and radius then scales exactly in binary
#     (double and binary32 alike), so any difference from the s = 1 image comes from an absolute
#     constant of the host (a ray epsilon, a padding), not from rounding.
# Tables: OUTDIR/render-drift.md, OUTDIR/render-scale.md; images and stats in OUTDIR/render/.
# Usage: scripts/stress-render.sh PREE OUTDIR [--quick]   (--quick: 1e5 photons, scales 1e-4, 1, 1e6, 2^10)
set -euo pipefail
pree=$(realpath "$1"); out=$2; quick=${3:-}
cd "$(dirname "$0")/.."
root=$(pwd)
W=16; H=12
if [ "$quick" = --quick ]; then PHOTONS=(100000); SCALE_PHOTONS=100000; SCALES=(1e-4 1 1e6 2^10)
else PHOTONS=(1000000 10000000 100000000); SCALE_PHOTONS=1000000
  SCALES=(1e-4 1e-3 1e-2 1e-1 1 1e1 1e2 1e3 1e4 1e5 1e6 2^-13 2^-10 2^-7 2^-3 2^3 2^7 2^10 2^13 2^17 2^20); fi
SCENES=(cornell3 cornell-sphere)
MODES=("double" "fp32-paper" "fp32-stable")
r="$out/render"; mkdir -p "$r"
t0=$(date +%s)

mode_args() {
  case $1 in
    double) echo "--precision double" ;;
    fp32-paper) echo "--precision fp32 --datapath paper" ;;
    fp32-stable) echo "--precision fp32 --datapath stable" ;;
  esac
}
render() {  # render SCENEFILE PHOTONS MODE NAME: NAME.exr, NAME.json, NAME.time (wall seconds)
  local s=$1 n=$2 m=$3 f=$r/$4
  echo "stress-render: $pree render $s --width $W --height $H --photons $n $(mode_args "$m") --out $f.exr --stats $f.json" >&2
  local a; a=$(date +%s.%N)
  # shellcheck disable=SC2046
  "$pree" render "$s" --width $W --height $H --photons "$n" $(mode_args "$m") --quiet --out "$f.exr" --stats "$f.json"
  echo "$(date +%s.%N) - $a" | bc > "$f.time"
}
cmp_row() {  # cmp_row REF TEST: "relL2 max/peak"
  "$pree" compare "$r/$1.exr" "$r/$2.exr" --json | python3 -c '
import json, sys
d = json.load(sys.stdin)
snr = d["snr_db"]
rel = 0.0 if snr == "inf" else 10 ** (-float(snr) / 20)
print("%.3e %.3e" % (rel, d["max_abs"] / d["peak"] if d["peak"] else 0))'
}
js() { python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); v=d
for p in sys.argv[2].split("."): v=v[p]
print(v)' "$1" "$2"; }

# 1. Drift.
{
echo "| scene | photons | datapath | render s (wall) | accepted | accepts per weighted hit point | rel. L2 vs double | max abs / peak |"
echo "|---|---:|---|---:|---:|---:|---:|---:|"
for sc in "${SCENES[@]}"; do
  for n in "${PHOTONS[@]}"; do
    for m in "${MODES[@]}"; do render "scenes/$sc" "$n" "$m" "drift-$sc-$n-$m"; done
    for m in "${MODES[@]}"; do
      f="$r/drift-$sc-$n-$m"
      acc=$(js "$f.json" hpuo_accepted); hp=$(( $(js "$f.json" hit_points) - $(js "$f.json" hit_points_zero_weight) ))
      if [ "$m" = double ]; then c="- -"; else c=$(cmp_row "drift-$sc-$n-double" "drift-$sc-$n-$m"); fi
      read -r rel mx <<<"$c"
      printf '| %s | %s | %s | %.1f | %s | %s | %s | %s |\n' "$sc" "$n" "$m" "$(cat "$f.time")" "$acc" \
        "$(awk -v a="$acc" -v h="$hp" 'BEGIN { printf "%.0f", a / h }')" "$rel" "$mx"
    done
  done
done
} | tee "$out/render-drift.md"

# 2. Scale invariance: scaled scene files in a temporary folder.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/pree-stress-scale.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
scale_scene() {  # scale_scene SCENE S -> prints the path of the scaled copy (scripts/scale-scene.py)
  "$root/scripts/scale-scene.py" "$root/scenes/$1" "$2" "$tmp/$1-$2" && echo "$tmp/$1-$2"
}
{
echo "| scene | scale | datapath | render s (wall) | accepted | initial radius / scale | rel. L2 vs scale 1 | max abs / peak |"
echo "|---|---:|---|---:|---:|---:|---:|---:|"
for sc in "${SCENES[@]}"; do
  for s in "${SCALES[@]}"; do
    f=$(scale_scene "$sc" "$s")
    for m in "${MODES[@]}"; do render "$f" $SCALE_PHOTONS "$m" "scale-$sc-$s-$m"; done
  done
  for s in "${SCALES[@]}"; do
    for m in "${MODES[@]}"; do
      g="$r/scale-$sc-$s-$m"
      read -r rel mx <<<"$(cmp_row "scale-$sc-1-$m" "scale-$sc-$s-$m")"
      r0=$(python3 -c 'import sys; s = sys.argv[2]; s = 2.0 ** int(s[2:]) if s.startswith("2^") else float(s)
print("%.6g" % (float(sys.argv[1]) / s))' "$(js "$g.json" initial_radius)" "$s")
      printf '| %s | %s | %s | %.1f | %s | %s | %s | %s |\n' "$sc" "$s" "$m" "$(cat "$g.time")" \
        "$(js "$g.json" hpuo_accepted)" "$r0" "$rel" "$mx"
    done
  done
done
} | tee "$out/render-scale.md"
echo "stress-render: $(( $(date +%s) - t0 )) s; tables $out/render-drift.md, $out/render-scale.md" >&2
