#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Multi-PREE co-simulation (host/cosim_main.c and cosim_dist.c, docs/scale_out.md "Multi-PREE co-simulation"):
# `mpirun -np 2 pree cosim` of cornell3 at 64x48 / 20k photons through the shared 4-PREU model
# (build/pree-cosim-p4). Each rank's PREE holds its partition of the hit points (render_dist_lo,
# the distributed render's) and is sent only the operations on them. The combined hit-point
# memory and image must match the fp32 model with 0 differing words, both ranks must report
# (hit points, operations, cycles), their hit points must add up to the frame's and their
# operations to a one-process co-simulation's. Then the failure path: PREE_TEST_CORRUPT_HP=N
# flips a bit of the model's hit point N, once in rank 0's partition and once in rank 1's (at
# 32x24 / 2k photons: hit points 300 and 1200); each run must exit 1 and name the hit point and
# its rank.
# level: quick
# cost: 14 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
command -v mpirun >/dev/null || fail "mpirun missing (Debian openmpi-bin: scripts/install-deps.sh)"
[ -x build/pree-cosim-p4 ] || fail "build/pree-cosim-p4 missing; rerun: make build/pree-cosim-p4"
MPIRUN=(mpirun --oversubscribe --allow-run-as-root --bind-to none -np 2)
base=(cosim scenes/cornell3 --width 64 --height 48 --photons 20000 --preu 4 --no-reference)

run "$PREE" "${base[@]}" --quiet --stats "$TMP/one.json"
echo "+ ${MPIRUN[*]} $PREE ${base[*]} --stats $TMP/two.json"
"${MPIRUN[@]}" "$PREE" "${base[@]}" --stats "$TMP/two.json" 2>"$TMP/err" || { rc=$?; cat "$TMP/err"; fail "two ranks: exit $rc"; }
grep '^pree cosim' "$TMP/err" | sed 's/^/  | /'
for r in 0 1; do
  grep -q "^pree cosim: rank $r of 2: 4 PREUs, [0-9]* hit points: [0-9]* ops in [0-9]* cycles" "$TMP/err" ||
    fail "rank $r did not report"
done
python3 - "$TMP/one.json" "$TMP/two.json" <<'EOF' || fail "two-rank co-simulation; reproduce: mpirun --oversubscribe --allow-run-as-root -np 2 build/pree ${base[*]}"
import json, sys
one, two = (json.load(open(p)) for p in sys.argv[1:3])
m = two.get("mpi", {})
bad = []
if two["hp_words_differing"] != 0 or two["image_words_differing"] != 0 or two["pass"] is not True:
    bad.append("differing words: hit points %s, image %s, pass %s"
               % (two["hp_words_differing"], two["image_words_differing"], two["pass"]))
per = m.get("per_rank", [])
if m.get("ranks") != 2 or len(per) != 2:
    bad.append("the report holds %s ranks, %d entries" % (m.get("ranks"), len(per)))
for q in per:
    if q["hit_points"] == 0 or q["update_operations"] == 0 or q["update_cycles"] == 0 or q["image_words_differing"]:
        bad.append("rank %d: %s" % (q["rank"], q))
if sum(q["hit_points"] for q in per) != one["hit_points"]:
    bad.append("the ranks hold %d hit points, the frame %d" % (sum(q["hit_points"] for q in per), one["hit_points"]))
if sum(q["update_operations"] for q in per) != one["update"]["operations"]:
    bad.append("the ranks applied %d operations, one process %d"
               % (sum(q["update_operations"] for q in per), one["update"]["operations"]))
if not 1 <= m.get("load_imbalance", 0) < 1.5:
    bad.append("load imbalance %s" % m.get("load_imbalance"))
print("  per rank (hit points, ops, cycles, utilization):",
      [(q["hit_points"], q["update_operations"], q["update_cycles"], round(q["update_preu_utilization"], 6)) for q in per])
print("  load imbalance %.6f, utilization over the longest %.6f; one process: %d cycles"
      % (m.get("load_imbalance", 0), m.get("update_preu_utilization", 0), one["update"]["cycles"]))
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
EOF
echo "ok: 2 ranks, 0 differing words, both ranks reported"

# The failure path: a corrupted model word in each rank's partition.
small=(cosim scenes/cornell3 --width 32 --height 24 --photons 2000 --preu 4 --no-reference --quiet)
for case in "300 0" "1200 1"; do
  set -- $case
  echo "+ PREE_TEST_CORRUPT_HP=$1 ${MPIRUN[*]} $PREE ${small[*]}"
  PREE_TEST_CORRUPT_HP=$1 "${MPIRUN[@]}" "$PREE" "${small[@]}" --stats "$TMP/bad.json" >"$TMP/bad.out" 2>&1 &&
    fail "PREE_TEST_CORRUPT_HP=$1: two ranks exited 0 with a corrupted word"
  grep -q "^pree cosim: hit point $1 differs (rank $2's PREE" "$TMP/bad.out" ||
    { cat "$TMP/bad.out"; fail "PREE_TEST_CORRUPT_HP=$1: no message naming hit point $1 in rank $2's PREE"; }
  expect_eq "PREE_TEST_CORRUPT_HP=$1 hp_words_differing" "$(json "$TMP/bad.json" hp_words_differing)" 1
  expect_eq "PREE_TEST_CORRUPT_HP=$1 pass" "$(json "$TMP/bad.json" pass)" False
done
