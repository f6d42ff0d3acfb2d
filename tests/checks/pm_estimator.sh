#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The photon-map estimator (--estimator pm, docs/photon_map.md): the clustered search gives the
# same image and per-hit-point radiance bits as the naive oracle (nanoflann) on cornell3 and a
# mesh scene (cornell-teapot), at two k; the bits do not depend on the thread count, the tracing
# schedule or the task size; bad combinations are one-line errors.
# level: quick
. "$(dirname "$0")/../lib/check.sh"

render() {  # render NAME SCENE ARGS...: stats in $TMP/NAME.json
  local name=$1 scene=$2; shift 2
  run "$PREE" render "$ROOT/scenes/$scene" --width 64 --height 48 --photons 20000 --estimator pm \
      --quiet --out "$TMP/$name.ppm" --stats "$TMP/$name.json" "$@"
}
hashes() { echo "$(json "$TMP/$1.json" image_hash)/$(json "$TMP/$1.json" state_hash)"; }

for scene in cornell3 cornell-teapot; do
  for k in 50 200; do
    render "$scene-c$k" "$scene" --k "$k" --max-radius 4 --threads 2
    render "$scene-n$k" "$scene" --k "$k" --max-radius 4 --threads 2 --knn-search naive
    expect_eq "$scene k=$k clustered = naive" "$(hashes "$scene-c$k")" "$(hashes "$scene-n$k")"
    [ "$(json "$TMP/$scene-c$k.json" pm.neighbours)" = "$(json "$TMP/$scene-n$k.json" pm.neighbours)" ] \
      || fail "$scene k=$k: neighbour counts differ"
  done
  # The default radius (the PPM initial radius) and the default k.
  render "$scene-d" "$scene" --threads 2
  render "$scene-d1" "$scene" --threads 1 --task-schedule static --task-photons 333
  render "$scene-dn" "$scene" --threads 1 --knn-search naive
  expect_eq "$scene: threads, schedule and task size" "$(hashes "$scene-d1")" "$(hashes "$scene-d")"
  expect_eq "$scene: default k clustered = naive" "$(hashes "$scene-dn")" "$(hashes "$scene-d")"
done
clusters=$(json "$TMP/cornell3-c50.json" pm.clusters)
[ "$clusters" -gt 0 ] 2>/dev/null || fail "no clusters reported ($clusters)"
frac=$(json "$TMP/cornell3-c50.json" pm.coherent_fraction)
python3 -c "import sys; f=float(sys.argv[1]); sys.exit(0 if 0 < f <= 1 else 1)" "$frac" || fail "coherent fraction $frac"
echo "ok: cornell3 k=50: $clusters clusters, coherent fraction $frac"

# Bad combinations.
for args in "--estimator pm --precision fp32" "--k 50" "--estimator pm --k 0" "--estimator pm --max-radius -1" \
            "--estimator pm --knn-search fast" "--estimator pm --task-schedule guided"; do
  if "$PREE" render "$ROOT/scenes/cornell3" --width 8 --height 6 --photons 1000 --quiet --out "$TMP/bad.png" $args \
       2>"$TMP/err"; then fail "accepted: $args"; fi
  [ "$(wc -l < "$TMP/err")" -eq 1 ] || fail "$args: not one error line: $(cat "$TMP/err")"
  [ ! -e "$TMP/bad.png" ] || fail "$args: an image was written"
  echo "ok: refused $args: $(cat "$TMP/err")"
done
