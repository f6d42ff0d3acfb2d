#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# pree_drv on the Verilated pree_axi against the C model (build/drv/pree_drv_test,
# tb/drv/pree_drv_test.c): load hit points, stream 700 photons and their candidates, close the
# batch, read hit points, stream counts and counters, run the radiance pass and read the pixels,
# every word bit for bit with the model's; then the error paths (a photon with too many
# candidates, a command while one runs, an unknown command, a photon over the index table's
# room: ERR). Twice: no gaps, and random back-pressure on every stream and AXI4-Lite channel.
# cost: 6 (two runs of about 2 s)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
[ -x build/drv/pree_drv_test ] || fail "build/drv/pree_drv_test missing (make build/drv/pree_drv_test)"
[ -f build/drv/libpree_drv.a ] || fail "build/drv/libpree_drv.a (the driver with the board back end) missing"
for opts in "" "--gap 0.3 --seed 7"; do
  out="$TMP/drv.txt"
  run build/drv/pree_drv_test $opts >"$out"
  cat "$out"
  grep -q '^FAIL' "$out" && fail "pree_drv_test $opts: a step failed"
  [ "$(tail -1 "$out")" = pass ] || fail "pree_drv_test $opts: no pass line"
done
echo "ok: the driver on the Verilated wrapper equals the model, errors reported"
