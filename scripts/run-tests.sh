#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regression runner: every cmocka unit binary in build/tests and every script in tests/checks (a
# parameterised one, "# cases:" below, once per case).
# Usage: run-tests.sh [quick|full]. A check script declares "# level: quick" to run in both;
# the rest run only at the full level. Writes build/test-results.xml (JUnit XML: one testcase
# per unit test and per check, with time, failure message, log and rerun command; see
# scripts/junit-xml.py), lists the slowest checks, and ends with one line "N passed, N failed".
# PREE_TEST_UNITS, PREE_TEST_CHECKS, PREE_TEST_XML: other unit-binary and check folders and XML
# path (tests/checks/junit_xml.sh runs the runner on a folder of its own). PREE_TEST_JOBS: how
# many checks run at once (below); PREE_TEST_TIMEOUT: seconds a check may run before it and its
# processes are killed and it fails (1200; the slowest, preu_sim, takes about 270 on CI).
set -u
level=${1:-full}
jobs=${PREE_TEST_JOBS:-$(nproc)}
limit=${PREE_TEST_TIMEOUT:-1200}
for v in jobs limit; do
  if ! [[ ${!v} =~ ^[1-9][0-9]*$ ]]; then
    echo "run-tests: PREE_TEST_$([ $v = jobs ] && echo JOBS || echo TIMEOUT) must be a whole number of at least 1, not '${!v}'" >&2
    exit 2
  fi
done
cd "$(dirname "$0")/.."
units=${PREE_TEST_UNITS:-build/tests}; checks=${PREE_TEST_CHECKS:-tests/checks}
xml=${PREE_TEST_XML:-build/test-results.xml}
pass=0; fail=0; failed=()
logdir=$(dirname "$xml")/test-logs; mkdir -p "$logdir"
results=$logdir/results.tsv; : >"$results"
now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }

for bin in "$units"/test_*; do
  [ -x "$bin" ] && [ -f "$bin" ] || continue
  name=$(basename "$bin"); log="$logdir/$name.log"; report="$logdir/$name.xml"
  rm -f "$report"   # cmocka does not overwrite an existing report
  start=$(now)
  CMOCKA_MESSAGE_OUTPUT=xml CMOCKA_XML_FILE="$report" "$bin" >"$log" 2>&1; rc=$?
  t=$(secs "$start" "$(now)")
  read -r p f < <(python3 scripts/junit-xml.py counts "$report")
  if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  pass=$((pass + p)); fail=$((fail + f))
  printf 'unit\t%s\t%s\t%d\t%s\t%s\t%s\n' "$name" "$t" "$rc" "$log" "$bin" "$report" >>"$results"
  if [ "$f" -ne 0 ]; then
    failed+=("$name  (log: $log, report: $report; rerun: $bin)")
    grep -o 'testcase name="[^"]*"[^>]*>[^<]*<failure' "$report" 2>/dev/null | sed 's/ time.*//; s/^/    FAILED /' | head -5
  fi
  printf '%-40s %d passed, %d failed\n' "$name" "$p" "$f"
done

# The checks run PREE_TEST_JOBS at a time (default: the core count; 1 runs them in turn). Each
# check owns its temporary folder and build outputs; what several share is built beforehand by
# make test-prereqs. Checks that declare "# cost: SECONDS" (their time in a serial run; it only
# orders the start) start first, longest first, so that the slowest do not start last; the rest
# follow in name order. Results print as checks end.
# A parameterised check declares "# cases: COMMAND": the command (run in the repository) prints
# one "name level [what]" line per case, and the check runs once per case (`bash CHECK name`), counted
# and reported under the case's name, at the case's level.
mapfile -t order < <(for chk in "$checks"/*.sh; do
  [ -f "$chk" ] || continue
  cases=$(sed -n 's/^# cases: //p' "$chk" | head -1)
  if [ -n "$cases" ]; then
    bash -c "$cases" | while read -r name clevel _; do
      if [ "$level" = quick ] && [ "$clevel" != quick ]; then continue; fi
      printf '0\t%s\t%s\n' "$chk" "$name"
    done
    continue
  fi
  if [ "$level" = quick ] && ! grep -q '^# level: quick' "$chk"; then continue; fi
  cost=$(sed -n 's/^# cost: \([0-9]*\).*/\1/p' "$chk" | head -1)
  printf '%s\t%s\t\n' "${cost:-0}" "$chk"
done | sort -t$'\t' -k1,1nr -k2,2 -k3,3 | cut -f2,3)

declare -A running=()   # pid -> check script and case ("chk<TAB>case"; no case: a plain check)
trap 'kill "${!running[@]}" 2>/dev/null; exit 130' INT TERM

start_check() {
  local chk=${1%%$'\t'*} case=${1#*$'\t'} name
  name=${case:-$(basename "$chk" .sh)}
  ( s=$(now); timeout -k 10 "$limit" bash "$chk" ${case:+"$case"} >"$logdir/$name.log" 2>&1; rc=$?
    [ $rc -eq 124 ] && echo "(timed out after ${limit} s: PREE_TEST_TIMEOUT)" >>"$logdir/$name.log"
    printf '%d %s\n' $rc "$(secs "$s" "$(now)")" >"$logdir/$name.rc" ) &
  running[$!]=$1
}

finish_check() {
  local pid chk case name rerun log rc t r
  wait -n -p pid "${!running[@]}"
  chk=${running[$pid]%%$'\t'*}; case=${running[$pid]#*$'\t'}; unset "running[$pid]"
  name=${case:-$(basename "$chk" .sh)}; rerun="bash $chk${case:+ $case}"; log="$logdir/$name.log"
  read -r rc t <"$logdir/$name.rc" 2>/dev/null || { rc=1; t=0; echo "(no result: the check's shell died)" >>"$log"; }
  rm -f "$logdir/$name.rc"
  if [ "$rc" -eq 0 ]; then
    pass=$((pass + 1)); r=ok
  else
    fail=$((fail + 1)); r=FAIL; failed+=("$name  (log: $log; rerun: $rerun)")
    tail -5 "$log" | sed 's/^/    /'
  fi
  printf 'check\t%s\t%s\t%d\t%s\t%s\n' "$name" "$t" "$rc" "$log" "$rerun" >>"$results"
  printf '%-40s %s (%.0fs)\n' "$name" "$r" "$t"
}

for chk in "${order[@]}"; do
  while [ ${#running[@]} -ge "$jobs" ]; do finish_check; done
  start_check "$chk"
done
while [ ${#running[@]} -gt 0 ]; do finish_check; done
trap - INT TERM

if python3 scripts/junit-xml.py write "$results" "$xml"; then
  echo "JUnit XML: $xml"
else
  echo "JUnit XML: could not write $xml"; fail=$((fail + 1))
fi
echo "slowest checks:"
awk -F'\t' '$1 == "check" { printf "  %8.1fs  %s\n", $3, $2 }' "$results" | sort -rn | head -8
if [ ${#failed[@]} -ne 0 ]; then
  echo "failed:"; printf '  %s\n' "${failed[@]}"
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
