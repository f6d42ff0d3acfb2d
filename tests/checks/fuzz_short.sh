#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The short fuzz run of make test: each libFuzzer harness (tests/fuzz, make fuzz for long runs)
# for FUZZ_SHORT seconds (default 20) on a copy of its seed corpus. Fails on any crash, hang
# (10 s a unit), leak or sanitizer report, naming the input that gave it.
# cost: 63 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
secs=${FUZZ_SHORT:-20}
export LSAN_OPTIONS=suppressions=$ROOT/tests/lsan.supp:print_suppressions=0
for n in scene mesh pbrt; do
  bin="$ROOT/build/fuzz/fuzz_$n"
  [ -x "$bin" ] || fail "$bin not built (make fuzz-build)"
  mkdir -p "$TMP/corpus-$n"
  cp "$ROOT/tests/fuzz/corpus/$n/"* "$TMP/corpus-$n/"
  (cd "$TMP" && "$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
     -artifact_prefix="$TMP/crash-$n-" "corpus-$n" >"$TMP/fuzz-$n.log" 2>&1)
  rc=$?
  if [ $rc -ne 0 ]; then
    grep -E '==ERROR|SUMMARY|runtime error|Test unit written' "$TMP/fuzz-$n.log" | head -5
    cp "$TMP"/crash-$n-* "$ROOT/build/fuzz/" 2>/dev/null
    fail "fuzz_$n: exit $rc (the input is saved in build/fuzz/; reproduce: build/fuzz/fuzz_$n build/fuzz/crash-$n-...)"
  fi
  echo "ok: fuzz_$n, $secs s: $(grep -E '^stat::number_of_executed_units' "$TMP/fuzz-$n.log" | awk '{print $2}') executions," \
       "$(grep -E '^#[0-9]+[[:space:]]+DONE' "$TMP/fuzz-$n.log" | grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+')"
done
