# SPDX-License-Identifier: Apache-2.0
# check.sh: shared helpers for the regression scripts in tests/checks (sourced, not run).
# Every failure prints what failed and the command that reproduces it, then exits 1.
set -u
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
PREE=${PREE:-$ROOT/build/pree}   # override to test another build
TMP=$(mktemp -d "${TMPDIR:-/tmp}/pree-check.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }

# Run a command, echoing it; fail with the command line when it fails.
run() { echo "+ $*"; "$@" || fail "command failed (exit $?): $*"; }

# json FILE KEY: a top-level (or seconds.X) value from a stats file. A missing key or file
# prints "<missing KEY in FILE>" (and a message on stderr), which no expected value equals,
# so that two missing values never compare equal as "" and "".
json() {
  python3 -c 'import json,sys
try:
    v=json.load(open(sys.argv[1]))
    for p in sys.argv[2].split("."): v=v[p]
except (OSError, ValueError, KeyError, TypeError) as e:
    print("json: %s: no %s (%s)" % (sys.argv[1], sys.argv[2], e), file=sys.stderr)
    v="<missing %s in %s>" % (sys.argv[2], sys.argv[1])
print(v)' "$1" "$2"
}

expect_eq() {  # expect_eq WHAT ACTUAL EXPECTED
  [ "$2" = "$3" ] || fail "$1: got '$2', expected '$3'"
  echo "ok: $1 = $2"
}
