#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A checkpoint carries its render's options (cli/cli_resume.c): `pree render --resume FILE` with
# no other option, from another folder, continues an interrupted render to the photon count and
# outputs it was started with, and gives the bits of the uninterrupted render (fp32 stable, a mesh
# scene with an area light). A resume with more photons from a checkpoint off the 32,000-photon
# blocks (50,000 -> 130,000) gives the bits of a render of 130,000 in one go, in double and fp32.
# cost: 6
source "$(dirname "$0")/../lib/check.sh"
cd "$TMP"
SCENE=$ROOT/scenes/examples/mesh.scene
R=(--width 64 --height 48 --threads 2)
mkdir -p run other
(cd run && PREE_TEST_INTERRUPT=block3 "$PREE" render "$SCENE" "${R[@]}" --photons 150000 --datapath stable \
    --checkpoint c.ckp --out part.png --stats part.json --quiet); rc=$?
expect_eq "interrupted: exit status" $rc 130
expect_eq "interrupted after" "$(json run/part.json photons_emitted)" 64000
(cd other && "$PREE" render --resume ../run/c.ckp 2>err.txt) || fail "resume alone failed: $(cat other/err.txt)"
expect_eq "resume alone: last line" "$(tail -1 other/err.txt)" "pree render: wrote $TMP/run/part.png, $TMP/run/part.json, ../run/c.ckp"
run "$PREE" render "$SCENE" "${R[@]}" --photons 150000 --precision fp32 --datapath stable --out full.png --stats full.json --quiet
for k in image_hash state_hash photons_emitted precision datapath; do
  expect_eq "resume alone = uninterrupted: $k" "$(json run/part.json $k)" "$(json full.json $k)"
done
expect_eq "resume alone: photons resumed" "$(json run/part.json photons_resumed)" 64000
cmp run/part.png full.png || fail "the resumed image differs from the uninterrupted one"
for p in double fp32; do
  run "$PREE" render "$SCENE" "${R[@]}" --photons 50000 --precision $p --checkpoint e.ckp --out e.png --quiet
  run "$PREE" render --resume e.ckp --photons 130000 --out x.png --stats x.json --quiet
  run "$PREE" render "$SCENE" "${R[@]}" --photons 130000 --precision $p --out y.png --stats y.json --quiet
  expect_eq "$p: 50,000 extended to 130,000 = 130,000 (image/state)" \
    "$(json x.json image_hash)/$(json x.json state_hash)" "$(json y.json image_hash)/$(json y.json state_hash)"
done
echo "resume_alone: ok"
