#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The `make bench` scripts still run and say what they should (their figures are timings, which
# no test judges): bench-convergence at its reduced size must give the table for both precisions
# with the error falling as the photons double (deterministic: fixed renders against a fixed,
# disjoint reference) and draw its plot; bench-engine with one run a row must print every row,
# both target lines, the smallppm byte-identity line and draw its picture (it fails by itself when
# an image changes with the thread count, the scan or the screening's lanes); bench-count must
# give its rows, the same twice; bench-scale at a small frame must give its three rows (screening
# batches, one block at a time, no re-filter) with one image hash, the same candidates with and
# without the batches and fewer with the re-filter.
# cost: 51 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
run scripts/bench-convergence.sh "$PREE" "$TMP/conv" --quick
for prec in double fp32; do
  rows=$(awk -v p=$prec '$2 == p' "$TMP/conv/convergence.txt" | wc -l)
  expect_eq "convergence rows, $prec" "$rows" 4
  falling=$(awk -v p=$prec '$2 == p { if (n++ && !($5 < last)) bad = 1; last = $5 } END { print bad ? "no" : "yes" }' \
      "$TMP/conv/convergence.txt")
  expect_eq "RMSE falls at every doubling, $prec" "$falling" yes
done
expect_eq "convergence plot is a PNG" "$(head -c 4 "$TMP/conv/convergence.png" | od -An -c | tr -d ' ')" "211PNG"
SCALE_SIZES="96x72:60000" run scripts/bench-scale.sh "$PREE" "$TMP/scale"
expect_eq "bench-scale rows" "$(tail -n +3 "$TMP/scale/scale.txt" | wc -l)" 3
cand() { awk -v m="$1" '$3 == m { print $8 }' "$TMP/scale/scale.txt"; }
expect_eq "bench-scale: candidates with batches = one block at a time" "$(cand batches)" "$(cand one-block)"
[ "$(cand batches)" -lt "$(cand no-refilter)" ] || fail "bench-scale: the re-filter examined $(cand batches) candidates, not fewer than $(cand no-refilter)"
RUNS=1 run scripts/bench-engine.sh "$PREE" "$TMP/eng"
expect_eq "engine rows" "$(grep -cE '^(smallppm|cells) (double|fp32) [12] (bucket|photon) ' "$TMP/eng/engine.txt")" 8
expect_eq "target lines" "$(grep -c '^target: ' "$TMP/eng/engine.txt")" 2
grep -q 'byte-identical to the reference' "$TMP/eng/engine.txt" || fail "bench-engine: no byte-identity line"
expect_eq "engine picture is a PNG" "$(head -c 4 "$TMP/eng/engine.png" | od -An -c | tr -d ' ')" "211PNG"
# bench-count at its reduced size: three rows, and the same counts twice within 0.1% per figure.
# Callgrind's counts repeat to within a few ten thousand instructions of 4e8 (glibc's memcpy and
# malloc paths depend on where the address space puts things), which can flip the table's last
# printed digit; a real change of the code moves them by far more.
run scripts/bench-count.sh "$PREE" "$TMP/cnt1" --quick
run scripts/bench-count.sh "$PREE" "$TMP/cnt2" --quick
expect_eq "count rows" "$(grep -cE '^(smallppm|cells) ' "$TMP/cnt1/count.txt")" 3
# every phase found under its function's name (a renamed function would print 0.0)
expect_eq "phases with no count" "$(awk '/^(smallppm|cells) /{for (i = 3; i <= NF; i++) if ($i + 0 == 0) n++} END{print n + 0}' "$TMP/cnt1/count.txt")" 0
rep=$(python3 - "$TMP/cnt1/count.txt" "$TMP/cnt2/count.txt" <<'PY'
import re, sys
rows = [[l.split() for l in open(f) if re.match(r"(smallppm|cells) ", l)] for f in sys.argv[1:]]
bad = [(a[0] + " " + a[1], x, y) for a, b in zip(*rows) for x, y in zip(a[2:], b[2:])
       if abs(float(x) - float(y)) > 1e-3 * max(abs(float(x)), abs(float(y))) + 0.1]
print("ok" if len(rows[0]) == len(rows[1]) == 3 and not bad else "differ: %s" % bad)
PY
)
expect_eq "counts repeat within 0.1%" "$rep" "ok"
