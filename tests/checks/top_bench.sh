#!/usr/bin/env bash
# level: quick
# pree_top against the C model (build/cosim/top_bench): random traces, all photons on one hit
# point, pixels with 40 hit points, idle gaps on the input, unordered candidates (bank
# conflicts), a small hit-point set (radiance hazards), index entries misplaced on purpose (stage-A
# bank conflicts in update mode; the bench also requires its abank counter to be non-zero);
# 4 PREUs here, and the misplaced entries with 8 and 16 too; the other scenarios with 8 and 16
# in `make sim`. The stable PREU datapath (13-cycle update hazard window) with 4 PREUs: random,
# one hit point, dense, gaps and misplaced entries, at alpha 0.7 and 0.3.
set -u
cd "$(dirname "$0")/../.."
bench=${BUILD:-build}/cosim/top_bench
fail=0
run() {
  out=$("$bench" "$@" 2>&1); rc=$?
  echo "$out" | tail -1
  if [ $rc -ne 0 ] || ! echo "$out" | tail -1 | grep -q ': PASS$'; then
    echo "FAIL (rc $rc); reproduce: $bench $*"; echo "$out" | head -20; fail=1
  fi
}
run --preu 4 --scenario random --photons 400
run --preu 4 --scenario one --photons 200
run --preu 4 --scenario dense --photons 300
run --preu 4 --scenario dense --hp 100 --photons 60
run --preu 4 --scenario mixed --photons 300 --gap 0.3
run --preu 4 --scenario mixed --photons 300 --no-reorder
run --preu 4 --scenario abank --photons 300
run --preu 4 --scenario abank --photons 300 --gap 0.3 --seed 2
run --preu 8 --scenario abank --photons 300
run --preu 16 --scenario abank --photons 300 --gap 0.3 --seed 3
run --preu 4 --datapath 1 --scenario random --photons 400
run --preu 4 --datapath 1 --scenario one --photons 200
run --preu 4 --datapath 1 --scenario dense --hp 100 --photons 60
run --preu 4 --datapath 1 --alpha 0.3 --scenario mixed --photons 300 --gap 0.3
run --preu 4 --datapath 1 --scenario abank --photons 300 --seed 2
exit $fail
