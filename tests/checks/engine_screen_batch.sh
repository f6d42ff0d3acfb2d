#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Screening batches (model/ppm/render_step.c): the update of several photon blocks at once,
# screened against the radii at the batch's start and applied in photon order, gives the bits and
# counters of block-by-block updates (PREE_SCREEN_BLOCKS=1), in double (batches of 2 and 4, 1 and 2
# threads) and fp32 (paper and stable), with and without the skips (--no-skip: no re-filter cuts
# the batches), and so does the default. A batch ends
# at a checkpoint that falls due (a render killed mid-batch resumes from the checkpoint
# block-by-block updates would have written) and at an interrupt (the whole blocks traced are
# kept). A PREE_SCREEN_BLOCKS out of range is a one-line error with nothing written.
# level: quick
# cost: 30 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
SCENE=$ROOT/scenes/cornell3
R=(render "$SCENE" --width 96 --height 72 --quiet)
counts() {
  local out=
  for k in image_hash state_hash photons_emitted photon_hits hpuo_candidates hpuo_normal_passed hpuo_accepted \
           skip_candidates_outside_radius grid_refilters grid_entries_final; do
    out+="$k=$(json "$1" $k) "
  done
  echo "$out"
}
# 10 blocks: batches of 4 are blocks 1 | 2 | 3-4 | 5-8 | 9-10 (cut at the re-filters after 1, 2, 4
# and 8); without skips (no re-filter) 1-4 | 5-8 | 9-10.
for mode in "double" "fp32" "fp32 --datapath stable" "double --no-skip"; do
  m=(--precision $mode) tag=${mode// /}
  kts="4 2"; [ "$mode" = double ] && kts="2 2:4 1:4 2"
  run env PREE_SCREEN_BLOCKS=1 "$PREE" "${R[@]}" "${m[@]}" --photons 320000 --threads 2 --out "$TMP/one.ppm" --stats "$TMP/one.json"
  IFS=: read -ra kt_list <<<"$kts"
  for kt in "${kt_list[@]}"; do
    set -- $kt
    run env PREE_SCREEN_BLOCKS=$1 "$PREE" "${R[@]}" "${m[@]}" --photons 320000 --threads $2 --out "$TMP/b.ppm" --stats "$TMP/b.json"
    expect_eq "$tag: batches of $1, $2 thread(s) = one block at a time" "$(counts "$TMP/b.json")" "$(counts "$TMP/one.json")"
    cmp "$TMP/b.ppm" "$TMP/one.ppm" || fail "$tag: the image of batches of $1 differs"
  done
done
# The default (batches as the memory the re-filters give back allows) as well.
run "$PREE" "${R[@]}" --photons 320000 --threads 2 --out "$TMP/d.ppm" --stats "$TMP/d.json"
run env PREE_SCREEN_BLOCKS=1 "$PREE" "${R[@]}" --photons 320000 --threads 2 --out "$TMP/one.ppm" --stats "$TMP/one.json"
expect_eq "default batches = one block at a time" "$(counts "$TMP/d.json")" "$(counts "$TMP/one.json")"

# Checkpoints every 3 blocks with batches of 4: killed as block 8 begins (block 7 traced, not
# applied), the checkpoint after block 6 survives and resumes to the bits of the whole render.
run env PREE_SCREEN_BLOCKS=1 "$PREE" "${R[@]}" --photons 320000 --threads 2 --out "$TMP/full.ppm" --stats "$TMP/full.json"
rm -f "$TMP/k.ckp"
PREE_SCREEN_BLOCKS=4 PREE_TEST_KILL=block8 "$PREE" "${R[@]}" --photons 320000 --threads 2 --checkpoint "$TMP/k.ckp" \
    --checkpoint-every 96000 --out "$TMP/k.ppm"; rc=$?
expect_eq "exit status, killed at block 8" $rc 137
run env PREE_SCREEN_BLOCKS=4 "$PREE" "${R[@]}" --photons 320000 --threads 2 --resume "$TMP/k.ckp" --out "$TMP/r.ppm" --stats "$TMP/r.json"
expect_eq "photons resumed from the checkpoint" "$(json "$TMP/r.json" photons_resumed)" 192000
for k in image_hash state_hash photon_hits hpuo_accepted; do
  expect_eq "resumed after a kill mid-batch: $k" "$(json "$TMP/r.json" $k)" "$(json "$TMP/full.json" $k)"
done

# An interrupt as block 7 begins (blocks 5 to 8 a batch): the image of blocks 1 to 6.
PREE_SCREEN_BLOCKS=4 PREE_TEST_INTERRUPT=block7 "$PREE" "${R[@]}" --photons 320000 --threads 2 \
    --out "$TMP/i.ppm" --stats "$TMP/i.json"; rc=$?
expect_eq "exit status, interrupted at block 7" $rc 130
expect_eq "photons after an interrupt at block 7" "$(json "$TMP/i.json" photons_emitted)" 192000
run env PREE_SCREEN_BLOCKS=1 "$PREE" "${R[@]}" --photons 192000 --threads 2 --out "$TMP/n.ppm" --stats "$TMP/n.json"
expect_eq "interrupted mid-batch = a render of 192000 photons" "$(json "$TMP/i.json" state_hash)" "$(json "$TMP/n.json" state_hash)"
cmp "$TMP/i.ppm" "$TMP/n.ppm" || fail "the image interrupted mid-batch differs from a render of 192000 photons"

# A batch size out of range.
for v in 0 5 x; do
  rm -f "$TMP/e.ppm"
  PREE_SCREEN_BLOCKS=$v "$PREE" "${R[@]}" --photons 64000 --out "$TMP/e.ppm" 2>"$TMP/e.err"; rc=$?
  [ $rc -ne 0 ] || fail "PREE_SCREEN_BLOCKS=$v: exit status 0"
  grep -q "PREE_SCREEN_BLOCKS=$v: expected a whole number from 1 to 4" "$TMP/e.err" || fail "PREE_SCREEN_BLOCKS=$v: message '$(cat "$TMP/e.err")'"
  [ "$(wc -l < "$TMP/e.err")" -eq 1 ] || fail "PREE_SCREEN_BLOCKS=$v: more than one line on stderr"
  [ ! -e "$TMP/e.ppm" ] || fail "PREE_SCREEN_BLOCKS=$v: an image was written"
done
echo "ok: screening batches"
