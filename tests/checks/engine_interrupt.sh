#!/usr/bin/env bash
# Ctrl-C during the photon pass: the render stops after the current block, writes the image
# and statistics of the whole photon batches done so far, and exits with status 130.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
"$PREE" render "$ROOT/scenes/cornell3" --width 160 --height 120 --photons 200000000 --quiet \
    --out "$TMP/i.png" --stats "$TMP/i.json" &
pid=$!
# Wait until the photon pass is under way (the eye pass and grid take well under a second).
sleep 3
kill -INT $pid
wait $pid; rc=$?
expect_eq "exit status after SIGINT" $rc 130
[ -s "$TMP/i.png" ] || fail "no image written after the interrupt"
expect_eq interrupted "$(json "$TMP/i.json" interrupted)" True
n=$(json "$TMP/i.json" photons_emitted)
[ "$n" -gt 0 ] && [ "$n" -lt 200000000 ] && [ $((n % 1000)) -eq 0 ] \
  || fail "photons_emitted $n is not a positive whole number of batches below the request"
echo "ok: stopped after $n photons"
