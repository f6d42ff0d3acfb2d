#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `pree render --eye-rays N` and `--exposure EV` (scenes/examples/room.scene, 64x48 / 20,000
# photons):
# - --eye-rays 1 and --exposure 0 give the default render's hashes and bytes;
# - --eye-rays 4: the same hashes on 1 and 2 threads, about 4x the hit points (between 3.5x and
#   4.5x: rays that escape the open front differ), and a resume from its checkpoint alone equals
#   the uninterrupted render (a resume with another --eye-rays is refused, naming both values);
# - --eye-rays 16 against 1, without the lights' emission: the photon radiance's image mean
#   within 2% (the same estimate, averaged over the pixel instead of at its centre); with it,
#   more pixels see the lamp, some of them only in part (between the lamp-less value and white);
# - the RTL image (pree cosim, 4 PREUs, 32x24 / 4,000 photons, --eye-rays 4) equals the fp32
#   render's, pixel word for pixel word;
# - --exposure 1.5 (fp32): the EXR output's pixels as without it; every PPM value is the tone
#   curve of 2^1.5 times the EXR's value (and of the value itself without --exposure);
# - bad values are one-line errors with exit 2 and nothing written.
# cost: 12 (its seconds in a serial run; 8 CPU s)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
[ -x "$PREE" ] || fail "$PREE not built (make build)"
command -v oiiotool >/dev/null || fail "oiiotool missing (Debian openimageio-tools: scripts/install-deps.sh)"
scene=scenes/examples/room.scene
frame=("$scene" --width 64 --height 48 --photons 20000 --quiet)
hashes() { echo "$(json "$1" image_hash)/$(json "$1" state_hash)"; }
pixels_sha() { iinfo --hash "$1" | sed -n 's/.*SHA-1: //p'; }

run "$PREE" render "${frame[@]}" --out "$TMP/d.png" --stats "$TMP/d.json"
run "$PREE" render "${frame[@]}" --eye-rays 1 --exposure 0 --out "$TMP/one.png" --stats "$TMP/one.json"
expect_eq "--eye-rays 1: hashes" "$(hashes "$TMP/one.json")" "$(hashes "$TMP/d.json")"
cmp -s "$TMP/d.png" "$TMP/one.png" || fail "--exposure 0 changed the PNG"

run "$PREE" render "${frame[@]}" --eye-rays 4 --threads 1 --out "$TMP/r4.png" --stats "$TMP/r4-1.json"
run "$PREE" render "${frame[@]}" --eye-rays 4 --threads 2 --out "$TMP/r4.png" --stats "$TMP/r4-2.json"
expect_eq "--eye-rays 4: hashes on 2 threads" "$(hashes "$TMP/r4-2.json")" "$(hashes "$TMP/r4-1.json")"
[ "$(hashes "$TMP/r4-1.json")" != "$(hashes "$TMP/d.json")" ] || fail "--eye-rays 4 gives the one-ray image"
python3 - "$(json "$TMP/d.json" hit_points)" "$(json "$TMP/r4-1.json" hit_points)" <<'PY' || fail "--eye-rays 4: hit points"
import sys
a, b = int(sys.argv[1]), int(sys.argv[2])
print("hit points: 1 ray %d, 4 rays %d (%.3fx)" % (a, b, b / a))
sys.exit(0 if 3.5 * a <= b <= 4.5 * a else 1)
PY
run "$PREE" render "$scene" --width 64 --height 48 --photons 10000 --eye-rays 4 --checkpoint "$TMP/c.ckpt" \
    --out "$TMP/c.png" --quiet
run "$PREE" render --resume "$TMP/c.ckpt" --photons 20000 --stats "$TMP/c.json" --quiet
expect_eq "--eye-rays 4 resumed alone from 10k to 20k: hashes" "$(hashes "$TMP/c.json")" "$(hashes "$TMP/r4-1.json")"
"$PREE" render --resume "$TMP/c.ckpt" --eye-rays 2 --quiet 2>"$TMP/err"
expect_eq "resume with --eye-rays 2: exit status" $? 1
grep -q -- "--eye-rays 2 conflicts with the checkpoint's --eye-rays 4" "$TMP/err" || fail "resume message: $(cat "$TMP/err")"

for r in 1 16; do
  run "$PREE" render "${frame[@]}" --eye-rays $r --out "$TMP/v$r.ppm"
  run "$PREE" render "${frame[@]}" --eye-rays $r --hide-lights --out "$TMP/h$r.ppm" --out "$TMP/h$r.exr"
  oiiotool --dumpdata "$TMP/h$r.exr" >"$TMP/h$r.txt"
done
python3 - "$TMP" <<'PY' || fail "--eye-rays 16 against 1, as above"
import sys
d = sys.argv[1]
def mean(path):
    v = [float(x) for line in open(path) if "Pixel" in line for x in line.split(":")[1].split()]
    return sum(v) / len(v)
def ppm(path):
    t = open(path).read().split()
    v = list(map(int, t[4:]))
    return [v[3 * i:3 * i + 3] for i in range(len(v) // 3)]
m1, m16 = mean(d + "/h1.txt"), mean(d + "/h16.txt")
print("photon radiance mean: 1 ray %.6f, 16 rays %.6f (%+.2f%%)" % (m1, m16, 100 * (m16 / m1 - 1)))
seen = {}
for r in (1, 16):
    v, h = ppm("%s/v%d.ppm" % (d, r)), ppm("%s/h%d.ppm" % (d, r))
    diff = [k for k in range(len(v)) if v[k] != h[k]]
    part = [k for k in diff if v[k] != [255, 255, 255]]
    seen[r] = (len(diff), len(part))
    print("%d ray(s): %d pixels see the lamp, %d of them in part" % (r, len(diff), len(part)))
sys.exit(0 if abs(m16 / m1 - 1) < 0.02 and seen[16][0] > seen[1][0] and seen[16][1] > 0 else 1)
PY

small=("$scene" --width 32 --height 24 --photons 4000 --quiet --preu 4 --eye-rays 4)
run "$PREE" cosim "${small[@]}" --no-reference --out "$TMP/rtl.exr"
run "$PREE" render "${small[@]}" --precision fp32 --threads 2 --out "$TMP/model.exr"
expect_eq "--eye-rays 4: RTL image = fp32 render: pixel SHA-1" "$(pixels_sha "$TMP/rtl.exr")" "$(pixels_sha "$TMP/model.exr")"

run "$PREE" render "${frame[@]}" --precision fp32 --out "$TMP/e0.exr" --out "$TMP/e0.ppm"
run "$PREE" render "${frame[@]}" --precision fp32 --exposure 1.5 --out "$TMP/e1.exr" --out "$TMP/e1.ppm"
expect_eq "--exposure 1.5: EXR pixels" "$(pixels_sha "$TMP/e1.exr")" "$(pixels_sha "$TMP/e0.exr")"
oiiotool --dumpdata "$TMP/e0.exr" >"$TMP/e0.txt"
python3 - "$TMP" <<'PY' || fail "--exposure: the PPM values are not the tone curve of 2^EV L"
import math, struct, sys
d = sys.argv[1]
L = [struct.unpack("f", struct.pack("f", float(x)))[0]   # the EXR's binary32 values (9 digits read back)
     for line in open(d + "/e0.txt") if "Pixel" in line for x in line.split(":")[1].split()]
def tone(x):   # pree_tonemap8
    return int(math.pow(1 - math.exp(-x), 1 / 2.2) * 255 + .5)
for name, s in (("e0", 1.0), ("e1", 2 ** 1.5)):
    v = list(map(int, open("%s/%s.ppm" % (d, name)).read().split()[4:]))
    bad = sum(1 for a, b in zip(v, L) if a != tone(s * b))
    print("%s.ppm: %d values, %d not tone(%g L)" % (name, len(v), bad, s))
    if bad or len(v) != len(L): sys.exit(1)
PY

for bad in "--eye-rays 0|--eye-rays: 0 is out of range" "--eye-rays 257|--eye-rays: 257 is out of range" \
           "--eye-rays 2.5|--eye-rays: '2.5'" "--exposure 31|--exposure: 31 is out of range" \
           "--exposure nan|--exposure: 'nan' is not a number" "--exposure x|--exposure: 'x' is not a number"; do
  args=${bad%%|*}; want=${bad#*|}
  "$PREE" render "${frame[@]}" $args --out "$TMP/bad.png" 2>"$TMP/err"; rc=$?
  expect_eq "$args: exit status" $rc 2
  expect_eq "$args: error lines" "$(wc -l <"$TMP/err")" 1
  grep -qF -- "$want" "$TMP/err" || fail "$args: '$(cat "$TMP/err")' does not say '$want'"
  [ ! -e "$TMP/bad.png" ] || fail "$args: an image was written"
done
echo "eye_rays_exposure: ok"
