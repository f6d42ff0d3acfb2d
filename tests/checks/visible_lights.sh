#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The camera sees the area lights (docs/scene_format.md, "Lights"), as a term beside the photon
# radiance. scenes/examples/room.scene (a triangular lamp below the ceiling, a mirror ball) at
# 64x48 / 20,000 photons, in double and fp32:
# - with --hide-lights the image and state hashes are those of the photon radiance alone, as
#   measured before the lights were visible (so the radiance estimate is unchanged), and the
#   default render has the same state hash and emitter_hits > 0;
# - the pixels the lamp covers (its corners projected with the scene's camera, which looks along
#   -z) show it: the pixel of its centroid is white (255 after the tone curve) and darker
#   without it; every pixel that differs between the two renders is brighter with the light, in
#   every channel, and no more pixels differ than eye segments met the light;
# - the RTL image (pree cosim, 4 PREUs, 32x24 / 4,000 photons) equals the fp32 render's, pixel
#   word for pixel word, and not the --hide-lights one (without area lights the RTL image is
#   checked by render_cosim_image.sh).
# cost: 7 (its seconds in a serial run; 4 CPU s)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
[ -x "$PREE" ] || fail "$PREE not built (make build)"
scene=scenes/examples/room.scene
frame=(--width 64 --height 48 --photons 20000 --quiet)
# The photon radiance alone, 64x48 / 20k: image/state hashes per precision.
declare -A hidden=([double]=8c57d794ad86c8f4/a75dabb2c8d4338c [fp32]=a63fda3f6f8515e3/f1796cb1df5c9bdb)
hashes() { echo "$(json "$1" image_hash)/$(json "$1" state_hash)"; }
for p in double fp32; do
  run "$PREE" render "$scene" "${frame[@]}" --precision "$p" --out "$TMP/$p.ppm" --stats "$TMP/$p.json"
  run "$PREE" render "$scene" "${frame[@]}" --precision "$p" --hide-lights --out "$TMP/$p-hidden.ppm" \
      --stats "$TMP/$p-hidden.json"
  expect_eq "$p --hide-lights: image/state hashes" "$(hashes "$TMP/$p-hidden.json")" "${hidden[$p]}"
  expect_eq "$p: state hash with the light seen" "$(json "$TMP/$p.json" state_hash)" "${hidden[$p]#*/}"
  expect_eq "$p --hide-lights: emitter_hits" "$(json "$TMP/$p-hidden.json" emitter_hits)" 0
  hits=$(json "$TMP/$p.json" emitter_hits)
  [ "$hits" -gt 0 ] 2>/dev/null || fail "$p: emitter_hits $hits: no eye segment met the lamp"
  python3 - "$TMP/$p.ppm" "$TMP/$p-hidden.ppm" "$hits" "$p" <<'PY' || fail "$p: the lamp is not seen as above"
import math, sys
def ppm(path):
    t = open(path).read().split()
    w, h = int(t[1]), int(t[2])
    v = list(map(int, t[4:]))
    return w, h, [v[3 * i:3 * i + 3] for i in range(w * h)]
w, h, seen = ppm(sys.argv[1])
_, _, hid = ppm(sys.argv[2])
hits, what = int(sys.argv[3]), sys.argv[4]
# room.scene: camera position 1 1 4.6 lookat 1 1 0 fov 40; the lamp's corners.
o, scale = (1.0, 1.0, 4.6), 2 * math.tan(math.radians(20))
lamp = [(0.7, 1.99, 0.7), (1.3, 1.99, 0.7), (1.0, 1.99, 1.3)]
def pixel(p):
    v = [p[k] - o[k] for k in range(3)]
    sx, sy = v[0] / -v[2] / (w * scale / h), v[1] / -v[2] / scale
    return (sx + 0.5) * w, (0.5 - sy) * h
cx, cy = pixel(tuple(sum(c[k] for c in lamp) / 3 for k in range(3)))
i = int(cy) * w + int(cx)
print("%s: the lamp's centroid at pixel (%d, %d): %s with the light, %s without" % (what, cx, cy, seen[i], hid[i]))
ok = seen[i] == [255, 255, 255] and hid[i] != seen[i]
diff = [k for k in range(w * h) if seen[k] != hid[k]]
darker = [k for k in diff if any(a < b for a, b in zip(seen[k], hid[k]))]
print("%s: %d pixels differ (%d eye segments met the lamp), %d darker with the light" % (what, len(diff), hits, len(darker)))
sys.exit(0 if ok and diff and not darker and len(diff) <= hits else 1)
PY
done
pixels_sha() { iinfo --hash "$1" | sed -n 's/.*SHA-1: //p'; }
small=("$scene" --width 32 --height 24 --photons 4000 --quiet --preu 4)
run "$PREE" cosim "${small[@]}" --no-reference --out "$TMP/rtl.exr"
run "$PREE" render "${small[@]}" --precision fp32 --threads 2 --out "$TMP/model.exr"
run "$PREE" render "${small[@]}" --precision fp32 --hide-lights --out "$TMP/hidden.exr"
rtl=$(pixels_sha "$TMP/rtl.exr")
[ -n "$rtl" ] || fail "no pixel hash from iinfo --hash $TMP/rtl.exr"
expect_eq "RTL image = fp32 render (lights seen): pixel SHA-1" "$rtl" "$(pixels_sha "$TMP/model.exr")"
[ "$rtl" != "$(pixels_sha "$TMP/hidden.exr")" ] || fail "the RTL image is the photon radiance alone: no light seen"
echo "visible_lights: ok"
