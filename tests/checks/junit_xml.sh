#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# The regression runner's CI output: scripts/run-tests.sh run over a folder of its own (a real
# cmocka binary, a unit binary that crashes, a passing, a failing and a hanging check, the last
# killed with its child after PREE_TEST_TIMEOUT seconds) must write JUnit XML
# that tests/lib/junit_validate.py accepts, with each case's status, failure message, log and
# rerun command, list the slowest checks, and keep the closing line "N passed, N failed".
# Then a validator self-test: three broken reports must be rejected.
# Usage: tests/checks/junit_xml.sh   (needs build/tests/test_compare: make build/tests/test_compare)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
V="python3 tests/lib/junit_validate.py"
unit=build/tests/test_compare
[ -x "$unit" ] || fail "$unit not built (make $unit)"
mkdir -p "$TMP/units" "$TMP/checks" "$TMP/out"
ln -s "$ROOT/$unit" "$TMP/units/test_compare"
printf '#!/bin/sh\necho "about to crash"\nexit 139\n' >"$TMP/units/test_crash"
chmod +x "$TMP/units/test_crash"
printf '#!/usr/bin/env bash\necho fine\n' >"$TMP/checks/good_one.sh"
printf '#!/usr/bin/env bash\necho working\necho "FAIL: widget: got 3, expected 4" >&2\nexit 1\n' >"$TMP/checks/bad_one.sh"
printf '#!/usr/bin/env bash\nsleep 300 & echo $! >"%s/hung.pid"\nwait\n' "$TMP" >"$TMP/checks/hung_one.sh"

echo "+ scripts/run-tests.sh full (PREE_TEST_UNITS=$TMP/units PREE_TEST_CHECKS=$TMP/checks)"
PREE_TEST_UNITS="$TMP/units" PREE_TEST_CHECKS="$TMP/checks" PREE_TEST_XML="$TMP/out/results.xml" \
  PREE_TEST_TIMEOUT=3 scripts/run-tests.sh full >"$TMP/run.txt" 2>&1 && fail "run-tests.sh exited 0 with a failing check"
sed 's/^/  | /' "$TMP/run.txt"
grep -q "timed out after 3 s" "$TMP/out/test-logs/hung_one.log" || fail "hung_one's log does not say it timed out"
# (a killed child whose parent died may linger as a zombie until something reaps it: dead is enough)
st=$(ps -o stat= -p "$(cat "$TMP/hung.pid")" 2>/dev/null || true)
[ -z "$st" ] || [ "${st:0:1}" = Z ] || fail "hung_one's child outlived the timeout (state $st)"
echo "ok: the hanging check was killed with its child after 3 s"
n=$(python3 -c 'import re,sys; print(len(re.findall(r"cmocka_unit_test\w*\(", open(sys.argv[1]).read())))' tests/unit/test_compare.c)
expect_eq "closing line" "$(tail -1 "$TMP/run.txt")" "$((n + 1)) passed, 3 failed"
grep -q '^slowest checks:' "$TMP/run.txt" || fail "no 'slowest checks:' list"
grep -Eq '^ +[0-9.]+s  (good_one|bad_one)$' "$TMP/run.txt" || fail "the slowest list has no check with its time"
run $V "$TMP/out/results.xml"

python3 - "$TMP/out/results.xml" "$n" "$TMP" <<'PY' || fail "report content (above)"
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot(); n = int(sys.argv[2]); tmp = sys.argv[3]
cases = {(c.get("classname"), c.get("name")): c for c in root.iter("testcase")}
def need(cond, what):
    if not cond: print("FAIL: " + what); sys.exit(1)
    print("ok: " + what)
unit = [k for k in cases if k[0] == "unit.test_compare"]
need(len(unit) == n, "%d testcases from test_compare's cmocka report (one per unit test)" % n)
need(all(cases[k].find("failure") is None for k in unit), "test_compare's tests pass")
need(all(float(cases[k].get("time")) >= 0 for k in unit), "each unit test has its time")
crash = cases.get(("unit.test_crash", "test_crash"))
need(crash is not None and crash.find("failure") is not None, "the crashing binary is one failing testcase")
need("status 139" in crash.find("failure").get("message"), "its message gives the exit status")
bad = cases.get(("checks", "bad_one")); good = cases.get(("checks", "good_one"))
need(good is not None and good.find("failure") is None, "good_one passes")
f = bad.find("failure")
need(f is not None and f.get("message") == "FAIL: widget: got 3, expected 4", "bad_one's message is its FAIL: line")
need("rerun: bash %s/checks/bad_one.sh" % tmp in f.text and "bad_one.log" in f.text, "its text names the log and rerun")
PY

# The validator must reject what a CI server would.
cp "$TMP/out/results.xml" "$TMP/v.xml"
sed 's/<testsuite name="checks"[^>]*>/&<testcase name="x" classname="y" time="1"\/>/' "$TMP/v.xml" >"$TMP/bad1.xml"
sed '0,/ timestamp="[^"]*"/s///' "$TMP/v.xml" >"$TMP/bad2.xml"
printf '<testsuite name="a"/>\n' >"$TMP/bad3.xml"
for b in bad1 bad2 bad3; do
  $V "$TMP/$b.xml" >"$TMP/$b.txt" && fail "the validator accepted $b.xml"
  echo "ok: validator rejects $b.xml: $(head -1 "$TMP/$b.txt")"
done
echo "junit_xml: ok"
