#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Each mesh scene renders from one command at 64x48 with 20k photons; its linear image has no
# NaN or infinity, no negative value, and a mean radiance (over pixels and channels) within
# +-15% of a reference measured at 400k photons (docs/scenes.md, "Checks"). At 20k photons
# the image mean was within 3.5% of that reference for every scene, so the band leaves a 4x
# margin for noise while catching a wrong flux scale (pi, 4 pi), a light emitting to the
# wrong side, lost materials or a wrong transform. The renders leave out the area lights' own
# emitted radiance (--hide-lights): the mean is the photon radiance's, what those errors change
# (tests/checks/visible_lights.sh checks the lights the camera sees).
# level: quick
set -u
cd "$(dirname "$0")/../.."
source scripts/scene-lib.sh
build_scene_stats || { echo "FAIL: cannot build build/scene-stats"; exit 1; }
tmp=build/checks/mesh_scenes; rm -rf "$tmp"; mkdir -p "$tmp"
fail=0
while read -r scene ref; do
  [ -z "$scene" ] && continue
  cmd="./build/pree render scenes/$scene --width 64 --height 48 --photons 20000 --threads 2 --hide-lights --quiet --out $tmp/$scene.exr"
  if ! $cmd 2>"$tmp/err"; then
    echo "FAIL $scene: render failed: $(cat "$tmp/err")"; echo "  reproduce: $cmd"; fail=1; continue
  fi
  st=$(build/scene-stats image "$tmp/$scene.exr")
  echo "$scene: $st (reference mean $ref)"
  if ! awk -v st="$st" -v ref="$ref" 'BEGIN {
      n = split(st, kv, " "); for (i = 1; i <= n; i++) { split(kv[i], p, "="); v[p[1]] = p[2] }
      ok = v["nan"] == 0 && v["inf"] == 0 && v["min"] >= 0 && v["mean"] >= 0.85 * ref && v["mean"] <= 1.15 * ref
      exit ok ? 0 : 1 }'; then
    echo "FAIL $scene: image statistics out of band (mean within 15% of $ref, no NaN/inf, min >= 0)"
    echo "  reproduce: $cmd && build/scene-stats image $tmp/$scene.exr"
    fail=1
  fi
done <<'REF'
cornell-teapot 0.0571132
sibenik 0.35785
conference 0.0841122
cornell-sphere 0.0706771
cornell-water 0.0752217
gold-rings 0.149091
REF
exit $fail
