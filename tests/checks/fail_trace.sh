#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A failing bench or co-simulation leaves an FST trace of the cycles around its first mismatch
# and names it in its message (tb/lib/fail_trace.h). Failures are injected on purpose: the PREU
# bench with +inject_error=N (one bit of op N's expected result flipped), pree cosim with
# PREE_TEST_CORRUPT_HP=N (one bit of the model's hit point N flipped before the comparison).
# Each must exit 1, print "cycles A..B traced in FILE", and FILE must hold exactly those cycles
# (fst2vcd: first and last time stamps), with the mismatch's cycle inside; a bench given +trace
# itself does not rerun.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
preu=build/preu/vl_dp0/preu_bench
make -s "$preu" "$PREE" build/pree-cosim-p4 || fail "build; rerun: make $preu build/pree build/pree-cosim-p4"
export FAIL_TRACE_DIR=$TMP

# window_of OUTPUT: "A B FILE C" from a message "... cycle C; cycles A..B traced in FILE".
window_of() {
  sed -n 's/.*at cycle \([0-9]*\); cycles \([0-9]*\)[.:]*\([0-9]*\) traced in \(.*\)$/\2 \3 \4 \1/p' <<<"$1" | tail -1
}
# check_trace NAME A B FILE C PS: FILE's time stamps run from A to B+1/2 cycles of PS each.
check_trace() {
  local name=$1 a=$2 b=$3 f=$4 c=$5 ps=$6
  [ -s "$f" ] || fail "$name: no trace $f"
  [ "$a" -le "$c" ] && [ "$c" -le "$b" ] || fail "$name: mismatch cycle $c outside the window $a..$b"
  local ts; ts=$(fst2vcd "$f" 2>/dev/null | grep '^#[0-9]' | tr -d '#')
  expect_eq "$name: first time stamp" "$(head -1 <<<"$ts")" "$(( a * ps ))"
  expect_eq "$name: last time stamp" "$(tail -1 <<<"$ts")" "$(( b * ps + ps / 2 ))"
  expect_eq "$name: time stamps (two per cycle)" "$(wc -l <<<"$ts")" "$(( 2 * (b - a + 1) ))"
}

# The PREU bench: one time unit per edge.
cmd="$preu 3000 5 +inject_error=1500"
out=$($cmd); rc=$?
expect_eq "$cmd: exit status" "$rc" 1
grep -q "^MISMATCH op 1500 " <<<"$out" || fail "$cmd: the injected mismatch is not reported"
read -r a b f c <<<"$(window_of "$out")"
[ -n "${f:-}" ] || fail "$cmd: no trace named: $(tail -2 <<<"$out")"
check_trace preu_bench "$a" "$b" "$f" "$c" 2
# The rerun itself, and a run traced by request, do not rerun.
n=$(ls "$TMP"/*.fst | wc -l)
$cmd +trace="$TMP/asked.fst" >"$TMP/out2"
grep -q "traced in" "$TMP/out2" && fail "$cmd +trace=...: reran although traced"
expect_eq "trace files after a traced failing run" "$(ls "$TMP"/*.fst | wc -l)" "$(( n + 1 ))"
# A passing run leaves none.
$preu 3000 5 >/dev/null || fail "$preu 3000 5"
expect_eq "trace files after a passing run" "$(ls "$TMP"/*.fst | wc -l)" "$(( n + 1 ))"

# The co-simulation: the paper's 8 ns clock, 8000 ps a cycle.
cmd="$PREE cosim scenes/cornell3 --width 32 --height 24 --photons 2000 --no-reference --quiet"
err=$(PREE_TEST_CORRUPT_HP=100 $cmd 2>&1 >/dev/null); rc=$?
expect_eq "PREE_TEST_CORRUPT_HP=100 $cmd: exit status" "$rc" 1
grep -q "hit point 100 differs" <<<"$err" || fail "cosim: the injected difference is not reported: $err"
read -r a b f c <<<"$(window_of "$err")"
[ -n "${f:-}" ] || fail "cosim: no trace named: $err"
check_trace "pree cosim" "$a" "$b" "$f" "$c" 8000
$cmd || fail "$cmd (without the injected difference)"
echo "fail_trace: PASS"
