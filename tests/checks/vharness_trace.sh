#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The Verilator harness (tb/lib/vharness.h) evaluates a traced run exactly as an untraced one:
# the PREU bench (paper datapath, 3,000 operations) and the top bench (4 PREUs, mixed scenario,
# through host/cosim_rtl.cpp) print the same results, cycle and stall counts with and without an
# FST trace. The trace holds one time step per clock edge after reset (its last time is
# 2 x cycles - 1), and
# a trace that cannot be opened is a one-line error naming the file, with a non-zero exit.
# level: quick
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
preu=build/preu/vl_dp0/preu_bench
top=${BUILD:-build}/cosim/top_bench
make -s "$preu" "$top" || fail "build; rerun: make $preu $top"

# same NAME PLAIN TRACED: a bench's output without and with a trace must be identical.
same() {
  local name=$1 plain=$2 traced=$3
  [ "$plain" = "$traced" ] || { diff <(echo "$plain") <(echo "$traced") | head; fail "$name: traced run differs"; }
  echo "ok: $name: traced and untraced runs print the same: $(echo "$plain" | tail -1)"
}

cmd="$preu 3000 5"
plain=$($cmd) || fail "$cmd"
traced=$($cmd +trace="$TMP/preu.fst") || fail "$cmd +trace=$TMP/preu.fst"
same preu_bench "$plain" "$traced"
# Reset is not traced; each of the bench's cycles is two dumps, one time unit apart.
cycles=$(echo "$plain" | sed -n 's/.* \([0-9]*\) cycles, .*/\1/p')
last=$(fst2vcd "$TMP/preu.fst" 2>/dev/null | grep '^#[0-9]' | tail -1 | tr -d '#')
expect_eq "preu_bench trace: last time" "$last" "$(( 2 * cycles - 1 ))"

cmd="$top --preu 4 --scenario mixed --photons 80 --hp 120"
plain=$($cmd) || fail "$cmd"
traced=$($cmd --trace "$TMP/top.fst") || fail "$cmd --trace $TMP/top.fst"
same top_bench "$plain" "$traced"
[ -s "$TMP/top.fst" ] || fail "top_bench: no trace written ($cmd --trace $TMP/top.fst)"

# A trace that cannot be written: one line naming the file, exit status non-zero.
for c in "$preu 10 1 +trace=$TMP/none/x.fst" "$top --preu 4 --photons 10 --trace $TMP/none/x.fst"; do
  $c >"$TMP/out" 2>"$TMP/err"; rc=$?
  [ $rc -ne 0 ] || fail "$c: exit 0 with an unwritable trace"
  [ "$(wc -l <"$TMP/err")" -eq 1 ] && grep -q "none/x.fst" "$TMP/err" || { cat "$TMP/err"; fail "$c: not one line naming the file"; }
  echo "ok: $(cat "$TMP/err") (exit $rc)"
done
echo "vharness_trace: ok"
