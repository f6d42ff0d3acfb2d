#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The pree program under Open MPI's mpirun (cli/cli_mpi.c, docs/scale_out.md): built with MPI
# when mpicc is present; one rank renders the same bits as a run without mpirun, in both
# precisions; a command other than render (and cosim) under two ranks stops with one message from rank 0
# and a non-zero exit (two-rank renders: mpi_render.sh).
# level: quick
. "$(dirname "$0")/../lib/check.sh"
command -v mpirun >/dev/null || fail "mpirun missing (Debian openmpi-bin: scripts/install-deps.sh)"
"$PREE" --version | grep -q '^MPI: Open MPI ' || fail "$PREE is built without MPI ('$PREE --version': $("$PREE" --version | tr '\n' ' '))"
echo "ok: $("$PREE" --version | sed -n 2p)"
MPIRUN=(mpirun --oversubscribe --allow-run-as-root)
args=(render "$ROOT/scenes/cornell3" --width 48 --height 36 --photons 20000)
for prec in double fp32; do
  run "$PREE" "${args[@]}" --precision $prec --out "$TMP/a.ppm" --stats "$TMP/a.json" --quiet
  run "${MPIRUN[@]}" -np 1 "$PREE" "${args[@]}" --precision $prec --out "$TMP/b.ppm" --stats "$TMP/b.json" --quiet
  for k in image_hash state_hash; do
    expect_eq "$prec mpirun -np 1 $k" "$(json "$TMP/b.json" $k)" "$(json "$TMP/a.json" $k)"
  done
done
echo "+ ${MPIRUN[*]} -np 2 $PREE check $ROOT/scenes/cornell3"
"${MPIRUN[@]}" -np 2 "$PREE" check "$ROOT/scenes/cornell3" 2>"$TMP/err" && fail "two ranks of pree check exited 0"
sed 's/^/  | /' "$TMP/err"
expect_eq "two ranks of pree check: pree messages" "$(grep -c '^pree' "$TMP/err")" 1
grep -q "^pree: 2 MPI ranks: only 'pree render'" "$TMP/err" || fail "two ranks: the message does not say what runs distributed"
echo "ok: a command other than render stops under two ranks with one message"
