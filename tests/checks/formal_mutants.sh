#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The formal suite can fail: each line of formal/mutants.txt breaks one rule in a scratch copy of
# rtl/ (a dropped handshake, a lost response, a lost operation, the counters' wrap-around), and
# the named job's task must then FAIL (scripts/formal-run.sh). The same tasks pass on the
# unmutated RTL: checked here, except a quick-level job's prove and cover (formal_quick.sh runs
# those). A job's bmc task (a bounded check from reset, deeper than its prove task's) gives the
# mutants a counterexample from reset rather than an induction failure.
# cost: 110 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
export FPGA_VENV=$(cd "${FPGA_VENV:-build/fpga-venv}" 2>/dev/null && pwd) \
  || fail "no tools venv at ${FPGA_VENV:-build/fpga-venv} (make fpga-deps)"
# FORMAL_MUTANTS: another list (make formal-mutants runs formal/mutants_full.txt, the mutants whose
# jobs take minutes, outside make test).
list=${FORMAL_MUTANTS:-formal/mutants.txt}
# Each line as job, task, file, sed expression, what it breaks (tab-separated).
python3 - "$list" >"$TMP/mutants.tsv" <<'PY' || fail "$list: malformed line (see above)"
import sys
for n, line in enumerate(open(sys.argv[1]), 1):
    line = line.rstrip("\n")
    if not line.strip() or line.startswith("#"):
        continue
    try:
        job, task, f, rest = line.split(" ", 3)
        d = rest[1]
        ends = [i for i, c in enumerate(rest) if c == d and i > 1 and rest[i - 1] != "\\"]
        expr, what = rest[:ends[1] + 1], rest[ends[1] + 1:].strip()
        assert rest[0] == "s" and task in ("prove", "cover", "bmc") and what
    except (ValueError, IndexError, AssertionError):
        sys.exit("%s:%d: expected <job> <task> <rtl file> <sed expression> <what it breaks>" % (sys.argv[1], n))
    print("\t".join((job, task, f, expr, what)))
PY
[ -s "$TMP/mutants.tsv" ] || fail "$list lists no mutant"

# The unmutated RTL passes each task named here.
for pair in $(cut -f1,2 "$TMP/mutants.tsv" | tr '\t' : | sort -u); do
  case ${pair#*:} in prove|cover) grep -q '^# level: quick' "formal/${pair%%:*}/${pair%%:*}.sby" && continue ;; esac
  run scripts/formal-run.sh "$pair"
done

n=0
while IFS=$'\t' read -r job task f expr what; do
  n=$((n + 1)); tree=$TMP/tree$n
  mkdir -p "$tree"; cp -r rtl formal scripts "$tree/"
  sed -i "$expr" "$tree/rtl/$f"
  cmp -s "rtl/$f" "$tree/rtl/$f" && fail "mutant $n ($what): '$expr' changes nothing in rtl/$f"
  if FORMAL_OUT=$TMP/out$n "$tree/scripts/formal-run.sh" "$job:$task" >"$TMP/m$n.log" 2>&1; then
    cat "$TMP/m$n.log"
    fail "mutant $n ($what) passed $job $task (sed -i '$expr' rtl/$f; scripts/formal-run.sh $job:$task)"
  fi
  grep -q " FAIL .*(FAIL)" "$TMP/m$n.log" || { cat "$TMP/m$n.log"; fail "mutant $n ($what): $job $task failed without a counterexample"; }
  echo "ok: mutant $n caught: $what: $(grep " FAIL " "$TMP/m$n.log" | head -1)"
  rm -rf "$tree"
done <"$TMP/mutants.tsv"
echo "ok: $n mutants, each caught"
