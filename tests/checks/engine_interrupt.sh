#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Interrupts and a closed stderr. SIGINT during the photon pass stops the render within the
# block in progress (abandoned), writes the image and statistics of the whole blocks done, which
# equal an uninterrupted render of that photon count, and exits with status 130. An interrupt in
# any earlier phase (BVH build, eye pass, grid build, the first photon block; injected with
# PREE_TEST_INTERRUPT=PHASE, which raises SIGINT through the program's handler as the phase
# begins) exits 130 naming the phase, with nothing written. A stderr whose reader is gone (EPIPE,
# SIGPIPE) stops the progress only: the render completes, with the same bits.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
SCENE=$ROOT/scenes/cornell3
# signal_render SIG WAIT W H NAME: send SIG WAIT seconds into a render of 2e8 photons; status 130
# and an image (NAME.ppm, NAME.json) of a positive whole number of blocks below the request.
signal_render() {
  "$PREE" render "$SCENE" --width "$3" --height "$4" --photons 200000000 --quiet \
      --out "$TMP/$5.ppm" --stats "$TMP/$5.json" &
  local pid=$!
  sleep "$2"   # the photon pass is under way (the eye pass and grid take well under a second)
  kill -"$1" $pid
  wait $pid; local rc=$?
  expect_eq "exit status after SIG$1" $rc 130
  [ -s "$TMP/$5.ppm" ] || fail "no image written after SIG$1"
  expect_eq "interrupted (SIG$1)" "$(json "$TMP/$5.json" interrupted)" True
  n=$(json "$TMP/$5.json" photons_emitted)
  [ "$n" -gt 0 ] && [ "$n" -lt 200000000 ] && [ $((n % 32000)) -eq 0 ] \
    || fail "photons_emitted $n is not a positive whole number of blocks below the request"
  echo "ok: SIG$1: stopped after $n photons"
}
signal_render INT 3 160 120 i
run "$PREE" render "$SCENE" --width 160 --height 120 --photons "$n" --quiet --out "$TMP/n.ppm" --stats "$TMP/n.json"
expect_eq "interrupted image = a render of $n photons" "$(json "$TMP/i.json" image_hash)" "$(json "$TMP/n.json" image_hash)"
expect_eq "interrupted state = a render of $n photons" "$(json "$TMP/i.json" state_hash)" "$(json "$TMP/n.json" state_hash)"
cmp "$TMP/i.ppm" "$TMP/n.ppm" || fail "the interrupted image differs from the render of $n photons"
signal_render TERM 2 96 72 t

# An interrupt in each phase before a photon block is done: status 130, the phase named, nothing written.
for phase in bvh:"BVH build" eye:"eye pass" grid:"grid build" block1:"first photon block"; do
  key=${phase%%:*} name=${phase#*:}
  rm -f "$TMP/p.ppm" "$TMP/p.json"
  PREE_TEST_INTERRUPT=$key "$PREE" render "$SCENE" --width 96 --height 72 --photons 200000 --quiet \
      --out "$TMP/p.ppm" --stats "$TMP/p.json" 2>"$TMP/p.err"; rc=$?
  expect_eq "exit status, interrupted at $key" $rc 130
  grep -q "interrupted during the $name; nothing written" "$TMP/p.err" \
    || fail "interrupted at $key: message '$(cat "$TMP/p.err")' does not name the $name"
  [ "$(wc -l < "$TMP/p.err")" -eq 1 ] || fail "interrupted at $key: more than one line on stderr"
  [ ! -e "$TMP/p.ppm" ] && [ ! -e "$TMP/p.json" ] || fail "interrupted at $key: an output was written"
  [ -z "$(ls "$TMP" | grep '\.tmp\.')" ] || fail "interrupted at $key: a temporary file was left"
  echo "ok: interrupted during the $name: status 130, nothing written"
done
# An interrupt at the third block: the image of the first two (64000 photons).
PREE_TEST_INTERRUPT=block3 "$PREE" render "$SCENE" --width 96 --height 72 --photons 200000 --quiet \
    --out "$TMP/b.ppm" --stats "$TMP/b.json"; rc=$?
expect_eq "exit status, interrupted at block 3" $rc 130
expect_eq "photons after an interrupt at block 3" "$(json "$TMP/b.json" photons_emitted)" 64000

# Progress to a pipe whose reader has gone: every write fails with EPIPE (SIGPIPE at its default
# in the child). The render completes and writes its outputs, with the bits of a quiet render.
run "$PREE" render "$SCENE" --width 96 --height 72 --photons 320000 --quiet --out "$TMP/q.ppm" --stats "$TMP/q.json"
rc=$(python3 -c 'import os, subprocess, sys
r, w = os.pipe(); os.close(r)
print(subprocess.run(sys.argv[1:], stderr=w).returncode)' "$PREE" render "$SCENE" --width 96 --height 72 \
    --photons 320000 --out "$TMP/e.ppm" --stats "$TMP/e.json")
expect_eq "exit status with stderr a broken pipe" "$rc" 0
expect_eq "image with stderr a broken pipe" "$(json "$TMP/e.json" image_hash)" "$(json "$TMP/q.json" image_hash)"
cmp "$TMP/e.ppm" "$TMP/q.ppm" || fail "the image differs with stderr a broken pipe"
# And `pree render ... 2>&1 | head -1`, the way a user meets it.
"$PREE" render "$SCENE" --width 96 --height 72 --photons 320000 --out "$TMP/h.ppm" 2>&1 | head -1 >/dev/null
expect_eq "exit status under '2>&1 | head -1'" "${PIPESTATUS[0]}" 0
cmp "$TMP/h.ppm" "$TMP/q.ppm" || fail "the image differs under '2>&1 | head -1'"
# A closed stderr: nothing can land in an output file through descriptor 2.
"$PREE" render "$SCENE" --width 96 --height 72 --photons 320000 --out "$TMP/c.ppm" 2>&-
expect_eq "exit status with stderr closed" $? 0
cmp "$TMP/c.ppm" "$TMP/q.ppm" || fail "the image differs with stderr closed"
