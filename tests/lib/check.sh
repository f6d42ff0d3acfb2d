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

# json FILE KEY: a top-level (or seconds.X) value from a stats file.
json() {
  python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); k=sys.argv[2].split("."); v=d
for p in k: v=v[p]
print(v)' "$1" "$2"
}

expect_eq() {  # expect_eq WHAT ACTUAL EXPECTED
  [ "$2" = "$3" ] || fail "$1: got '$2', expected '$3'"
  echo "ok: $1 = $2"
}
