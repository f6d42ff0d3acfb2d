#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Distributed render (model/ppm/render_round.c, docs/scale_out.md): `mpirun -np 2` renders of
# cornell3 (1 thread a rank) and a mesh scene (cornell3-teapot, 2 threads a rank), in double, fp32
# (paper) and fp32 (stable), hold the image and state hashes and the accepted count of one process;
# rank 0 alone writes, and the communication figures are in the statistics. 100000 photons are
# four blocks of RENDER_PHOTON_BLOCK (the last partial): both ranks trace. Last, three ranks
# over five blocks (a round with an idle rank). About 45 s on a shared 2-core machine: full
# level only (mpi_launch.sh is the quick check).
. "$(dirname "$0")/../lib/check.sh"
command -v mpirun >/dev/null || fail "mpirun missing (Debian openmpi-bin: scripts/install-deps.sh)"
MPIRUN=(mpirun --oversubscribe --allow-run-as-root --bind-to none -np 2)
for scene in cornell3 cornell3-teapot; do
  for prec in double "fp32 --datapath paper" "fp32 --datapath stable"; do
    args=(render "$ROOT/scenes/$scene" --width 40 --height 30 --photons 100000 --precision $prec --quiet)
    run "$PREE" "${args[@]}" --out "$TMP/a.ppm" --stats "$TMP/a.json"
    want="$(json "$TMP/a.json" image_hash)/$(json "$TMP/a.json" state_hash)/$(json "$TMP/a.json" hpuo_accepted)"
    for t in $([ $scene = cornell3 ] && echo 1 || echo 2); do
      rm -f "$TMP/b.ppm" "$TMP/b.json"
      run "${MPIRUN[@]}" "$PREE" "${args[@]}" --threads $t --out "$TMP/b.ppm" --stats "$TMP/b.json"
      got="$(json "$TMP/b.json" image_hash)/$(json "$TMP/b.json" state_hash)/$(json "$TMP/b.json" hpuo_accepted)"
      expect_eq "$scene $prec -np 2 --threads $t hashes/accepted" "$got" "$want"
      cmp -s "$TMP/a.ppm" "$TMP/b.ppm" || fail "$scene $prec -np 2: the image files differ"
      expect_eq "$scene $prec -np 2 mpi_ranks" "$(json "$TMP/b.json" mpi_ranks)" 2
      [ "$(json "$TMP/b.json" mpi_bytes_sent)" -gt 0 ] || fail "$scene $prec -np 2: no bytes sent"
    done
  done
done
args=(render "$ROOT/scenes/cornell3" --width 48 --height 36 --photons 150000 --precision fp32 --quiet)
run "$PREE" "${args[@]}" --out "$TMP/a.ppm" --stats "$TMP/a.json"
run mpirun --oversubscribe --allow-run-as-root --bind-to none -np 3 "$PREE" "${args[@]}" --threads 1 --out "$TMP/c.ppm" --stats "$TMP/c.json"
expect_eq "cornell3 fp32 -np 3 hashes/accepted" \
  "$(json "$TMP/c.json" image_hash)/$(json "$TMP/c.json" state_hash)/$(json "$TMP/c.json" hpuo_accepted)" \
  "$(json "$TMP/a.json" image_hash)/$(json "$TMP/a.json" state_hash)/$(json "$TMP/a.json" hpuo_accepted)"
# Ctrl-C on one rank (PREE_TEST_INTERRUPT raises SIGINT in the rank that begins block 3: rank 0,
# in the second round): every rank stops after that round's tracing, the first round (blocks 1-2,
# 64000 photons) is applied, and rank 0 writes its image: the bits of one process interrupted at
# block 3, with its exit status.
args=(render "$ROOT/scenes/cornell3" --width 40 --height 30 --photons 200000 --quiet)
PREE_TEST_INTERRUPT=block3 "$PREE" "${args[@]}" --out "$TMP/i1.ppm" --stats "$TMP/i1.json"; rc1=$?
PREE_TEST_INTERRUPT=block3 "${MPIRUN[@]}" "$PREE" "${args[@]}" --threads 1 --out "$TMP/i2.ppm" --stats "$TMP/i2.json" \
  2>"$TMP/i2.err"; rc2=$?
expect_eq "exit status, interrupted at block 3, one process" $rc1 130
expect_eq "exit status, interrupted at block 3, -np 2" $rc2 130
expect_eq "photons after an interrupt at block 3, -np 2" "$(json "$TMP/i2.json" photons_emitted)" 64000
expect_eq "image after an interrupt at block 3, -np 2" "$(json "$TMP/i2.json" image_hash)" "$(json "$TMP/i1.json" image_hash)"
# An error on the ranks (fp32: the light's flux beyond binary32 at the PREE boundary): one
# message (rank 0's), a non-zero exit, and nothing written.
sed 's/intensity 2500 2500 2500/intensity 1e38 1e38 1e38/' "$ROOT/scenes/cornell3" > "$TMP/hot.scene"
rm -f "$TMP/h.ppm" "$TMP/h.json"
"${MPIRUN[@]}" "$PREE" render "$TMP/hot.scene" --width 16 --height 12 --photons 1000 --precision fp32 --quiet \
  --threads 1 --out "$TMP/h.ppm" --stats "$TMP/h.json" 2>"$TMP/h.err"; rc=$?
[ $rc -ne 0 ] || fail "-np 2 with a flux beyond binary32: exit 0"
expect_eq "-np 2 error: pree messages" "$(grep -c '^pree' "$TMP/h.err")" 1
grep -q "^pree render: .*photon 0's flux .* beyond binary32's range" "$TMP/h.err" \
  || fail "-np 2 error: message '$(grep '^pree' "$TMP/h.err")'"
[ ! -e "$TMP/h.ppm" ] && [ ! -e "$TMP/h.json" ] || fail "-np 2 error: an output was written"
echo "ok: -np 2: an error on the ranks is one message, nothing written"
