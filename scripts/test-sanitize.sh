#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The sanitizer run (make test-sanitize): the unit tests and the bad-input checks against the
# AddressSanitizer + UndefinedBehaviorSanitizer build in DIR (default build-san). A sanitizer
# report stops the process (halt_on_error) and fails the run; leaks are reported too.
# Ends with one line "N passed, N failed".
set -u
cd "$(dirname "$0")/.."
dir=${1:-build-san}
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0   # Debian libraries' leaks
logdir=$dir/test-logs; mkdir -p "$logdir"
pass=0; fail=0
run_one() {   # run_one NAME COMMAND...: pass when it exits 0 and no sanitizer wrote a report
  local name=$1 log="$logdir/$1.log"; shift
  if "$@" >"$log" 2>&1 && ! grep -qE '^(==[0-9]+==ERROR|SUMMARY: (Address|Undefined|Leak)Sanitizer)|runtime error:' "$log"; then
    pass=$((pass + 1)); echo "ok    $name"
  else
    fail=$((fail + 1)); echo "FAIL  $name (log: $log)"
    grep -E '==ERROR|runtime error|SUMMARY|FAIL' "$log" | head -5
  fi
}
for bin in "$dir"/tests/test_*; do
  [ -x "$bin" ] && [ "${bin%.o}" = "$bin" ] && [ "${bin%.d}" = "$bin" ] || continue
  run_one "$(basename "$bin")" "$bin"
done
for chk in engine_bad_input mesh_bad_input compare_cli; do
  run_one "$chk" env PREE="$PWD/$dir/pree" bash "tests/checks/$chk.sh"
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
