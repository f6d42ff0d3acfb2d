#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A convergence series in one render (pree render --write-every/--write-at): at each count the
# image and statistics are written as NAME-COUNT.EXT with the bits of a separate render of that
# count (hashes and PNG bytes), in double and fp32, and the render's own outputs are those of its
# full count; counts off the thousands or beyond --photons are one-line errors before any work.
# cost: 6
source "$(dirname "$0")/../lib/check.sh"
cd "$TMP"
SCENE=$ROOT/scenes/examples/caustics.scene
R=(--width 48 --height 36 --threads 2)
for p in double fp32; do
  run "$PREE" render "$SCENE" "${R[@]}" --precision $p --photons 100000 --write-every 40k --write-at 3k,40000 \
      --out s.png --stats s.json 2>err.txt
  expect_eq "$p: last line" "$(tail -1 err.txt)" "pree render: wrote s.png, s.json; the series above"
  expect_eq "$p: series files" "$(ls s-*.png | sort -t- -k2 -n | tr '\n' ' ')" "s-3000.png s-40000.png s-80000.png "
  for n in 3000 40000 80000 100000; do
    run "$PREE" render "$SCENE" "${R[@]}" --precision $p --photons $n --out d.png --stats d.json --quiet
    f=s-$n; [ $n = 100000 ] && f=s
    expect_eq "$p: series at $n = a render of $n (image/state)" "$(json $f.json image_hash)/$(json $f.json state_hash)" \
      "$(json d.json image_hash)/$(json d.json state_hash)"
    expect_eq "$p: photons at $n" "$(json $f.json photons_emitted)" $n
    cmp $f.png d.png || fail "$p: $f.png differs from a render of $n photons"
  done
  rm -f s-* s.*
done
for bad in "--write-at 1500:not a whole number of thousands" "--write-at 200k:is beyond the render's 100000 photons" \
           "--write-every x:is not a photon count"; do
  opt=${bad%%:*} want=${bad#*:}
  "$PREE" render "$SCENE" "${R[@]}" --photons 100000 $opt --out e.png 2>e.txt; rc=$?
  expect_eq "$opt: status" $rc 2
  expect_eq "$opt: lines" "$(wc -l < e.txt)" 1
  grep -q -- "$want" e.txt || fail "$opt: $(cat e.txt)"
  [ ! -e e.png ] || fail "$opt: an image was written"
done
echo "render_series: ok"
