#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Area-light photometry against a closed form: a 5e-5 area triangle of radiance 2e4 (on-axis
# intensity L*A = 1, flux 2e4*pi*5e-5) 1 unit above a large diffuse floor (rho 0.5), seen from
# straight above (floor region about 0.4 x 0.4), and the same with a point light of intensity 1.
# Expected image means: rho/pi * E averaged over the pixels' floor points, E = h/d^3 (point)
# and h^2/d^4 (one-sided Lambertian emitter), computed below from the camera formula of
# docs/scene_format.md: 0.1531 (point), 0.1512 (area). Measured means were within 2.3% of
# these at 20k-400k photons; the band is +-5%, so flux (pi), side (front = counter-clockwise)
# or direction-distribution (uniform vs cosine) errors fail it.
# level: quick
set -u
cd "$(dirname "$0")/../.."
source scripts/scene-lib.sh
build_scene_stats || { echo "FAIL: cannot build build/scene-stats"; exit 1; }
d=build/checks/mesh_area_light; rm -rf "$d"; mkdir -p "$d"
head='camera origin 0 3 0 dir 0 -1 0 scale 0.133 near 0 up 0 0 -1
material floor diffuse .5 .5 .5
triangle -50 0 -50  50 0 -50  50 0 50 floor
triangle -50 0 -50  50 0 50  -50 0 50 floor'
printf '%s\nlight triangle 0 1 0  0.01 1 0  0 1 0.01 radiance 2e4 2e4 2e4\n' "$head" > "$d/area"
printf '%s\nlight point 0.003333 1 0.003333 intensity 1 1 1\n' "$head" > "$d/point"
expect=$(python3 - <<'PY'
import math
W = H = 32; S = 0.133; h = 1.0; cam = 3.0; lx = lz = 0.01 / 3
ep = ea = 0.0
for y in range(H):
    for x in range(W):
        fx = cam * ((x + .5) / W - .5) * W * S / H - lx
        fz = -cam * (-(y + .5) / H + .5) * S - lz   # the image's up is world -z (up 0 0 -1)
        d2 = fx * fx + fz * fz + h * h
        ep += 0.5 / math.pi * h / d2 ** 1.5
        ea += 0.5 / math.pi * h * h / (d2 * d2)
print("%.6f %.6f" % (ep / (W * H), ea / (W * H)))
PY
)
read -r exp_point exp_area <<<"$expect"
fail=0
for s in point area; do
  e=$([ $s = point ] && echo "$exp_point" || echo "$exp_area")
  cmd="./build/pree render $d/$s --width 32 --height 32 --photons 100000 --threads 2 --quiet --out $d/$s.exr"
  if ! $cmd 2>"$d/$s.err"; then echo "FAIL $s: $(cat "$d/$s.err")"; echo "  reproduce: $cmd"; fail=1; continue; fi
  st=$(build/scene-stats image "$d/$s.exr")
  m=$(sed -n 's/.* mean=\([^ ]*\) .*/\1/p' <<<"$st")
  echo "$s: mean $m, expected $e ($st)"
  if ! awk -v m="$m" -v e="$e" 'BEGIN { exit (m >= 0.95 * e && m <= 1.05 * e) ? 0 : 1 }'; then
    echo "FAIL $s: mean $m not within 5% of $e"; echo "  reproduce: $cmd && build/scene-stats image $d/$s.exr"; fail=1
  fi
done
exit $fail
