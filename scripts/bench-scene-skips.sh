#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# bench-scene-skips.sh: what the engine saves when a scene lacks a feature, measured on
# variants of cornell-sphere at 320x240, 768,000 photons, 2 threads (docs/scenes.md, "Skips"):
#   triangles  the scene as shipped: both balls are triangle meshes (Embree native triangles)
#   analytic   the balls as analytic spheres (Embree user geometry, double-precision callbacks)
#   noglass    the glass ball made diffuse: no glass, so no eye-path branching
# Prints a Markdown table from each render's --stats JSON; files in build/bench-scenes/skips/.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/scene-lib.sh
build_scene_stats
d=build/bench-scenes/skips; mkdir -p "$d"
data=../../../scenes/data/cornell-box/CornellBox-Sphere.obj.gz   # relative to the variant files
cam=$(grep '^camera' scenes/cornell-sphere)
printf '%s\nmesh %s\n' "$cam" "$data" > "$d/triangles"
# Ball centres and radii from the OBJ's vertex bounds (546 vertices each).
printf '%s\nmaterial ball_mirror mirror .95 .95 .95\nmaterial ball_glass glass 1 1 1 ior 2.5\n' "$cam" > "$d/analytic"
printf 'mesh %s exclude leftSphere exclude rightSphere\n' "$data" >> "$d/analytic"
printf 'sphere 0.3263 -0.42140 0.3321 -0.28000 ball_mirror\nsphere 0.3263 0.44585 0.3321 0.37675 ball_glass\n' >> "$d/analytic"
printf '%s\nmaterial ball_white diffuse .75 .75 .75\nmesh %s map rightSphere ball_white\n' "$cam" "$data" > "$d/noglass"
echo "| variant | triangles | spheres | hit points | eye rays | glass splits | photon segments | eye s | trace s | update s | total s |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for v in triangles analytic noglass; do
  ./build/pree render "$d/$v" --width 320 --height 240 --photons 768000 --threads 2 --quiet \
    --out "$d/$v.png" --stats "$d/$v.json" 2>"$d/$v.log"
  info=$(build/scene-stats info "$d/$v" 2>/dev/null)
  python3 - "$d/$v.json" "$v" "$info" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); s = j["seconds"]; v = sys.argv[2]
info = dict(kv.split("=") for kv in sys.argv[3].split())
tris, sph = format(int(info["triangles"]), ","), int(info["spheres"])
print("| %s | %s | %d | %d | %d | %d | %d | %.2f | %.2f | %.2f | %.2f |" % (v, tris, sph, j["hit_points"], j["eye_rays"],
      j["glass_splits"], j["photon_segments"], s["eye"], s["trace"], s["update"], s["total"]))
PY
done
