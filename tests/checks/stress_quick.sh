#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# The stress suite's quick level (issue 10; docs/numerics.md): one hit point through both fp32
# datapaths. Fails unless the references agree with each other (--selftest); the stable
# datapath's r2 and radiance stay within 1e-5 of the reference at 1e6 accepts (alpha 0.7), its
# radius shrinks and its count counts at every one of them; the paper datapath shows its known
# freeze when run to 2.5e7 accepts (r2 stops once N reaches 2^23, N stops at 2^24); N_emitted
# rounds within 2^-24 beyond 2^24 and 2^32; the non-finite table runs; and the suite's scripts
# (scripts/stress-hitpoint.sh --quick, the plots) still run and draw.
# Usage: tests/checks/stress_quick.sh   (STRESS_HP=path to test another build)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
HP=${STRESS_HP:-$ROOT/build/stress/stress_hitpoint}
REPRO="bash tests/checks/stress_quick.sh"
[ -x "$HP" ] || fail "$HP not built (make build/stress/stress_hitpoint); reproduce: $REPRO"

run "$HP" --selftest > "$TMP/self.txt"
grep -q '^selftest passed' "$TMP/self.txt" || { cat "$TMP/self.txt"; fail "closed form and recurrences disagree; reproduce: $HP --selftest"; }
echo "ok: closed form, double and long-double recurrences agree"

# The stable datapath at alpha 0.7, 1e6 accepts.
run "$HP" --accepts 1e6 --alpha 0.7 --csv "$TMP/q.csv" --label q > "$TMP/q.txt"
cat "$TMP/q.txt"
row() { awk -F, -v m="$1" -v k="$2" -v c="$3" '$2 == m && $8 == k { v = $c + 0; print (v < 0 ? -v : v) }' "$TMP/q.csv"; }
within() {  # within WHAT VALUE LIMIT
  [ -n "$2" ] || fail "$1: no value; reproduce: $HP --accepts 1e6 --alpha 0.7"
  awk -v v="$2" -v l="$3" 'BEGIN { exit !(v <= l) }' || fail "$1 = $2 > $3; reproduce: $HP --accepts 1e6 --alpha 0.7"
  echo "ok: $1 = $2 <= $3"
}
within "stable |r2 error| vs closed form at 1e6" "$(row stable 1000000 10)" 1e-5
within "stable |r2 error| vs double at 1e6" "$(row stable 1000000 9)" 1e-5
within "stable |radiance error| (L word) at 1e6" "$(row stable 1000000 15)" 1e-5
within "stable |tau / r2 error| at 1e6" "$(row stable 1000000 14)" 1e-5
grep -q '^event stable w    first_unchanged=never last_changed=1000000 ' "$TMP/q.txt" \
  || fail "stable r2 stopped shrinking within 1e6 accepts; reproduce: $HP --accepts 1e6"
echo "ok: stable w changed at every accept"
grep -q '^event stable k final=1000000 expected=1000000 mismatched_steps=0 ' "$TMP/q.txt" \
  || fail "stable count is not exact; reproduce: $HP --accepts 1e6"
echo "ok: stable k counted every accept"
# ...while the paper datapath has drifted by then (its error is the point of the comparison).
v=$(row paper 1000000 10)
awk -v v="$v" 'BEGIN { exit !(v > 1e-3) }' || fail "paper |r2 error| at 1e6 = $v, expected the known drift > 1e-3"
echo "ok: paper |r2 error| at 1e6 = $v > 1e-3 (its known drift)"

# The paper datapath's freeze.
run "$HP" --accepts 2.5e7 --datapaths paper --no-ld > "$TMP/p.txt"
grep -E '^(paper +25000000|event paper)' "$TMP/p.txt"
r2first=$(sed -n 's/^event paper  r2   first_unchanged=\([0-9]*\) last_changed=\([0-9]*\) .*/\1 \2/p' "$TMP/p.txt")
nfirst=$(sed -n 's/^event paper  N    first_unchanged=\([0-9]*\) last_changed=\([0-9]*\) .* final_N=\(.*\)/\1 \2 \3/p' "$TMP/p.txt")
read -r r2_first r2_last <<<"$r2first"
read -r n_first n_last n_final <<<"$nfirst"
[ -n "${r2_first:-}" ] && [ -n "${n_first:-}" ] || fail "paper datapath: no freeze within 2.5e7 accepts; reproduce: $HP --accepts 2.5e7 --datapaths paper"
[ "$r2_last" -lt "$r2_first" ] && [ "$r2_first" -lt 20000000 ] \
  || fail "paper r2 should stop before 2e7 accepts and stay: first unchanged $r2_first, last changed $r2_last"
echo "ok: paper r2 frozen from accept $r2_first on (last change $r2_last)"
[ "$n_last" -lt "$n_first" ] || fail "paper N changed after it first stopped ($n_first, $n_last)"
expect_eq "paper N stops at 2^24" "$n_final" 16777216
echo "ok: paper N frozen from accept $n_first"

run "$HP" --ne-table > "$TMP/ne.txt"
grep -q 'for every count: yes' "$TMP/ne.txt" || fail "N_emitted rounding beyond 2^-24; reproduce: $HP --ne-table"
echo "ok: N_emitted rounds within 2^-24 through 2^64"
run "$HP" --nonfinite > "$TMP/nf.txt"
expect_eq "non-finite table rows" "$(grep -cE ' (paper|stable) +[01] [01] [01] ' "$TMP/nf.txt")" 69

run scripts/stress-hitpoint.sh "$HP" "$TMP/suite" --quick > "$TMP/suite.log" 2>&1 || { tail -20 "$TMP/suite.log"; fail "stress-hitpoint --quick"; }
for p in r2 radiance alpha; do
  expect_eq "numerics-$p plot is a PNG" "$(head -c 4 "$TMP/suite/numerics-$p.png" | od -An -c | tr -d ' ')" "211PNG"
done
expect_eq "sweep summary rows" "$(grep -cE '^\| [a-z0-9.-]+ \| (paper|stable) \|' "$TMP/suite/sweeps.md")" 39
echo "stress_quick: all checks passed"
