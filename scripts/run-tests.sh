#!/usr/bin/env bash
# Regression runner: every cmocka unit binary in build/tests and every script in tests/checks.
# Usage: run-tests.sh [quick|full]. A check script declares "# level: quick" to run in both;
# the rest run only at the full level. Ends with one line "N passed, N failed".
set -u
level=${1:-full}
cd "$(dirname "$0")/.."
pass=0; fail=0; failed=()
logdir=build/test-logs; mkdir -p "$logdir"

for bin in build/tests/test_*; do
  [ -x "$bin" ] || continue
  name=$(basename "$bin"); log="$logdir/$name.log"
  CMOCKA_MESSAGE_OUTPUT=stdout "$bin" >"$log" 2>&1; rc=$?
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -1)
  f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -1)
  p=${p:-0}; f=${f:-0}
  if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  pass=$((pass + p)); fail=$((fail + f))
  if [ "$f" -ne 0 ]; then failed+=("$name  (log: $log; rerun: $bin)"); grep -E '^\[  (FAILED|  ERROR)' "$log" | head -5; fi
  printf '%-40s %d passed, %d failed\n' "$name" "$p" "$f"
done

for chk in tests/checks/*.sh; do
  [ -f "$chk" ] || continue
  if [ "$level" = quick ] && ! grep -q '^# level: quick' "$chk"; then continue; fi
  name=$(basename "$chk" .sh); log="$logdir/$name.log"
  start=$(date +%s)
  if bash "$chk" >"$log" 2>&1; then
    pass=$((pass + 1)); r=ok
  else
    fail=$((fail + 1)); r=FAIL; failed+=("$name  (log: $log; rerun: bash $chk)")
    tail -5 "$log" | sed 's/^/    /'
  fi
  printf '%-40s %s (%ss)\n' "$name" "$r" "$(( $(date +%s) - start ))"
done

if [ ${#failed[@]} -ne 0 ]; then
  echo "failed:"; printf '  %s\n' "${failed[@]}"
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
