#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# bench-scenes.sh: the scene benchmark (called by `make bench`): every scene at 320x240 with
# 10 photons per pixel (768,000, the paper's rule) on 2 threads; prints a Markdown table of
# triangles, scene load and BVH build seconds, hit points, photon hits, HpUO candidates,
# accepted updates, seconds per phase and peak memory, all from `pree render --stats`
# (triangles and load time from build/scene-stats). Per-scene JSON, PNG and log files are kept
# in build/bench-scenes/.
# Usage: scripts/bench-scenes.sh [--images DIR] [SCENE...]   (default: all scenes below)
#   --images DIR   also copy each render to DIR/scene-NAME.png
set -euo pipefail
cd "$(dirname "$0")/.."
images=""
if [ "${1:-}" = "--images" ]; then images=$2; shift 2; fi
scenes=("$@")
[ ${#scenes[@]} -eq 0 ] && scenes=(cornell3 cornell-teapot sibenik conference cornell-sphere cornell-water gold-rings)
source scripts/scene-lib.sh
build_scene_stats
out=build/bench-scenes; mkdir -p "$out"
W=320; H=240; P=$((W * H * 10)); T=2
echo "Scenes at ${W}x${H}, $P photons (10 per pixel), $T threads; $(nproc) cores: $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1)"
echo
echo "| scene | triangles | load s | BVH s | hit points | photon hits | candidates (HpUO) | accepted | eye s | grid s | trace s | update s | radiance s | total s | peak MiB |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for s in "${scenes[@]}"; do
  info=$(build/scene-stats info "scenes/$s" 2>/dev/null)
  tris=$(sed -n 's/.*triangles=\([0-9]*\).*/\1/p' <<<"$info")
  load=$(sed -n 's/.*load_seconds=\([0-9.]*\).*/\1/p' <<<"$info")
  ./build/pree render "scenes/$s" --width $W --height $H --photons $P --threads $T --quiet \
    --out "$out/$s.png" --stats "$out/$s.json" 2>"$out/$s.log"
  [ -n "$images" ] && mkdir -p "$images" && cp "$out/$s.png" "$images/scene-$s.png"
  python3 - "$out/$s.json" "$s" "$tris" "$load" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
s = j["seconds"]
load = float(sys.argv[4])
print("| %s | %s | %.2f | %.3f | %d | %d | %d | %d | %.2f | %.2f | %.2f | %.2f | %.3f | %.2f | %.0f |" % (
    sys.argv[2], format(int(sys.argv[3]), ","), load, s["bvh"], j["hit_points"], j["photon_hits"],
    j["hpuo_candidates"], j["hpuo_accepted"], s["eye"], s["grid"], s["trace"], s["update"],
    s["radiance"], s["total"], j["peak_rss_kib"] / 1024.0))
PY
done
echo
echo "load s: scene_load (read, gunzip, OBJ/MTL checks, Assimp import, conversion), measured by build/scene-stats info."
