#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checkpoints, resume and the time limit (pree render --checkpoint/--resume/--time-limit).
# A render interrupted (SIGINT at its 4th photon block, PREE_TEST_INTERRUPT) or killed (SIGKILL,
# PREE_TEST_KILL: only the periodic checkpoint survives) and then resumed gives the bits of an
# uninterrupted render (image, state hash, counters but the candidates examined), in double and fp32 (paper and stable), from 1
# thread to 2 and from 2 to 1. A checkpoint of another scene or options, a corrupt, truncated or
# foreign file, or one beyond the photon count is a one-line error with nothing written. A time
# limit stops after the block in progress with exit 0, and the image equals a render of the
# photon count the statistics report.
# cost: 46 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
SCENE=$ROOT/scenes/cornell3
R=(render "$SCENE" --width 96 --height 72 --photons 200000 --quiet)
# The candidate count is left out: the grid is re-filtered against the radii after blocks 1, 2, 4,
# 8, ... (model/ppm/grid_refilter.c), and a resumed render starts from a grid built afresh, so it
# examines other candidates (never another accepted photon: the bits are the same).
same() {  # same WHAT A.json B.json: the bits and counters of two renders agree
  for k in image_hash state_hash photons_emitted photon_segments photon_hits skip_photon_hits_no_cell \
           hpuo_accepted; do
    expect_eq "$1: $k" "$(json "$2" $k)" "$(json "$3" $k)"
  done
}
for mode in "double" "fp32" "fp32 --datapath stable"; do
  m=(--precision $mode) tag=${mode// /}
  run "$PREE" "${R[@]}" "${m[@]}" --threads 2 --out "$TMP/full.ppm" --stats "$TMP/full.json"
  for t in "1 2" "2 1"; do
    set -- $t
    rm -f "$TMP/c.ckp"
    PREE_TEST_INTERRUPT=block4 "$PREE" "${R[@]}" "${m[@]}" --threads $1 --checkpoint "$TMP/c.ckp" \
        --checkpoint-every 64000 --out "$TMP/part.ppm"; rc=$?
    expect_eq "$tag: exit status, interrupted at block 4" $rc 130
    run "$PREE" "${R[@]}" "${m[@]}" --threads $2 --resume "$TMP/c.ckp" --out "$TMP/res.ppm" --stats "$TMP/res.json"
    expect_eq "$tag: photons resumed" "$(json "$TMP/res.json" photons_resumed)" 96000
    same "$tag: interrupted on $1 thread(s), resumed on $2" "$TMP/res.json" "$TMP/full.json"
    cmp "$TMP/res.ppm" "$TMP/full.ppm" || fail "$tag: the resumed image differs from the uninterrupted one"
  done
  # Killed at block 4: the periodic checkpoint (64000 photons) survives, and resumes to the same bits.
  rm -f "$TMP/k.ckp" "$TMP/k.ppm"
  PREE_TEST_KILL=block4 "$PREE" "${R[@]}" "${m[@]}" --threads 2 --checkpoint "$TMP/k.ckp" --checkpoint-every 64000 \
      --out "$TMP/k.ppm"; rc=$?
  expect_eq "$tag: exit status, killed at block 4" $rc 137
  [ ! -e "$TMP/k.ppm" ] || fail "$tag: an image was written by the killed render"
  run "$PREE" "${R[@]}" "${m[@]}" --threads 1 --resume "$TMP/k.ckp" --stats "$TMP/k.json" --out "$TMP/k.ppm"
  expect_eq "$tag: photons in the periodic checkpoint" "$(json "$TMP/k.json" photons_resumed)" 64000
  same "$tag: killed, resumed from the periodic checkpoint" "$TMP/k.json" "$TMP/full.json"
done

# The time limit: stops after the block in progress (here the first), exit 0, the photon count in
# the statistics and on stderr; the image equals a render of that many photons.
run "$PREE" "${R[@]}" --time-limit 0.001 --out "$TMP/tl.ppm" --stats "$TMP/tl.json" 2>"$TMP/tl.err"
expect_eq "time limited" "$(json "$TMP/tl.json" time_limited)" True
n=$(json "$TMP/tl.json" photons_emitted)
expect_eq "photons under a 1 ms time limit" "$n" 32000
grep -q "time limit of 0.001 s reached after $n photons" "$TMP/tl.err" || fail "no time-limit line on stderr: $(cat "$TMP/tl.err")"
run "$PREE" render "$SCENE" --width 96 --height 72 --photons "$n" --quiet --out "$TMP/n.ppm" --stats "$TMP/n.json"
same "time-limited render = a render of $n photons" "$TMP/tl.json" "$TMP/n.json"
cmp "$TMP/tl.ppm" "$TMP/n.ppm" || fail "the time-limited image differs from the render of $n photons"
# A generous limit changes nothing.
run "$PREE" "${R[@]}" --time-limit 100000 --out "$TMP/tg.ppm" --stats "$TMP/tg.json"
expect_eq "time limited (100000 s)" "$(json "$TMP/tg.json" time_limited)" False
expect_eq "photons under a generous limit" "$(json "$TMP/tg.json" photons_emitted)" 200000

# Bad checkpoints: one line naming the file and the reason, status 1, nothing written.
PREE_TEST_INTERRUPT=block4 "$PREE" "${R[@]}" --checkpoint "$TMP/d.ckp" --out "$TMP/d.ppm" 2>/dev/null
size=$(stat -c %s "$TMP/d.ckp")
head -c $((size / 2)) "$TMP/d.ckp" > "$TMP/trunc.ckp"
head -c 60 "$TMP/d.ckp" > "$TMP/trunc_head.ckp"
cp "$TMP/d.ckp" "$TMP/corrupt.ckp"
printf '\x5a' | dd of="$TMP/corrupt.ckp" bs=1 seek=$((size / 2)) conv=notrunc status=none
cp "$TMP/d.ckp" "$TMP/long.ckp"; printf 'x' >> "$TMP/long.ckp"
bad() {  # bad WHAT EXPECTED-TEXT ARGS...: a one-line error, status 1, no output
  local what=$1 text=$2; shift 2
  rm -f "$TMP/o.ppm"
  "$PREE" "$@" --out "$TMP/o.ppm" 2>"$TMP/err"; local rc=$?
  expect_eq "$what: exit status" $rc 1
  [ "$(wc -l < "$TMP/err")" -eq 1 ] || fail "$what: not one line: $(cat "$TMP/err")"
  grep -q -- "$text" "$TMP/err" || fail "$what: '$(cat "$TMP/err")' does not say '$text'"
  [ ! -e "$TMP/o.ppm" ] || fail "$what: an image was written"
  echo "ok: $what: $(cat "$TMP/err")"
}
bad "truncated checkpoint" "trunc.ckp: truncated checkpoint" "${R[@]}" --resume "$TMP/trunc.ckp"
bad "truncated header" "trunc_head.ckp: truncated checkpoint" "${R[@]}" --resume "$TMP/trunc_head.ckp"
bad "corrupt checkpoint" "corrupt.ckp: corrupt checkpoint" "${R[@]}" --resume "$TMP/corrupt.ckp"
bad "trailing bytes" "long.ckp: corrupt checkpoint" "${R[@]}" --resume "$TMP/long.ckp"
bad "not a checkpoint" "cornell3: not a PREE checkpoint" "${R[@]}" --resume "$SCENE"
bad "missing checkpoint" "none.ckp: No such file" "${R[@]}" --resume "$TMP/none.ckp"
bad "other options (width)" "width 80 conflicts with the checkpoint's --width 96" render "$SCENE" --width 80 --height 72 \
    --photons 200000 --quiet --resume "$TMP/d.ckp"
bad "other options (alpha)" "alpha 0.8 conflicts with the checkpoint's --alpha 0.7" "${R[@]}" --alpha 0.8 --resume "$TMP/d.ckp"
bad "other precision" "precision fp32 conflicts with the checkpoint's --precision double" "${R[@]}" --precision fp32 --resume "$TMP/d.ckp"
bad "a flag added" "no-skip is given, but the checkpoint's render ran without it" "${R[@]}" --no-skip --resume "$TMP/d.ckp"
bad "other scene" "another scene, options or build" render "$ROOT/scenes/cornell-sphere" --width 96 --height 72 \
    --photons 200000 --quiet --resume "$TMP/d.ckp"
bad "fewer photons than the checkpoint" "holds 96000 photons" render "$SCENE" --width 96 --height 72 \
    --photons 64000 --quiet --resume "$TMP/d.ckp"
bad "checkpoint in a missing directory" "no/such/dir/c.ckp: cannot write a checkpoint here" "${R[@]}" \
    --checkpoint "$TMP/no/such/dir/c.ckp"
# Resuming with more photons than the first render asked for extends it.
run "$PREE" "${R[@]}" --resume "$TMP/d.ckp" --photons 256000 --stats "$TMP/x.json" --out "$TMP/x.ppm"
run "$PREE" render "$SCENE" --width 96 --height 72 --photons 256000 --quiet --stats "$TMP/y.json" --out "$TMP/y.ppm"
same "extended by a resume" "$TMP/x.json" "$TMP/y.json"
[ -z "$(ls "$TMP" | grep '\.tmp\.')" ] || fail "a temporary file was left: $(ls "$TMP")"
