#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Run the formal suite (formal/<job>/<job>.sby, docs/formal.md) through the pinned SymbiYosys,
# Yosys and Boolector (the WebAssembly builds that `make fpga-deps` installs).
# Usage: formal-run.sh [quick|full] [job|job:task ...]
#   quick   the jobs whose .sby says "# level: quick" (make test); full: every job (make formal)
#   job     only these jobs (any level), prove and cover; job:task one task of a job (a job may
#           have more tasks, e.g. bmc: a deeper bounded check from reset, for the mutants)
# Prints one line per task: job, task, PASS or FAIL, seconds, depth (prove: the k-induction
# depth, or bmc=N where a job's prove task is only bounded, or the step of a counterexample;
# cover: the last cover's step), and for a failure its
# status (FAIL: a counterexample, UNKNOWN: induction failed, TIMEOUT, ERROR) and the trace (.vcd,
# open in GTKWave). Exits 1 if any task fails.
# Environment: FPGA_VENV the tools' venv (build/fpga-venv), FORMAL_OUT the work folders
# (build/formal: <job>_<task>/ each), FORMAL_TIMEOUT seconds a task may take (1800).
set -u
cd "$(dirname "$0")/.."
root=$PWD
level=full
case "${1:-}" in quick|full) level=$1; shift ;; esac
venv=${FPGA_VENV:-build/fpga-venv}
venv=$(cd "$venv" 2>/dev/null && pwd) || { echo "formal-run: no tools venv at ${FPGA_VENV:-build/fpga-venv} (make fpga-deps)" >&2; exit 2; }
[ -x "$venv/shims/sby" ] || { echo "formal-run: $venv/shims/sby missing (make fpga-deps)" >&2; exit 2; }
export PATH=$venv/shims:$PATH
out=${FORMAL_OUT:-build/formal}
mkdir -p "$out"; out=$(cd "$out" && pwd)
limit=${FORMAL_TIMEOUT:-1800}

# The (job, task) pairs to run.
pairs=()
if [ $# -gt 0 ]; then
  for a in "$@"; do
    job=${a%%:*}
    [ -f "formal/$job/$job.sby" ] || { echo "formal-run: no job $job (formal/$job/$job.sby)" >&2; exit 2; }
    if [ "$a" != "$job" ]; then pairs+=("$job ${a#*:}"); else pairs+=("$job prove" "$job cover"); fi
  done
else
  for sby in formal/*/*.sby; do
    job=$(basename "$sby" .sby)
    [ "$sby" = "formal/$job/$job.sby" ] || continue
    if [ "$level" = quick ] && ! grep -q '^# level: quick' "$sby"; then continue; fi
    pairs+=("$job prove" "$job cover")
  done
fi

fails=0
for p in "${pairs[@]}"; do
  read -r job task <<<"$p"
  dir=$out/${job}_$task
  start=$(date +%s.%N)
  (cd "formal/$job" && timeout -k 10 "$limit" sby -f -d "$dir" "$job.sby" "$task") >"$out/${job}_$task.log" 2>&1
  rc=$?
  secs=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  log=$dir/logfile.txt
  if [ $rc -eq 0 ] && [ -f "$dir/PASS" ]; then
    res=PASS
    if [ "$task" = cover ]; then
      depth="step $(grep -io 'reached cover statement.* step [0-9]*' "$log" | sed 's/.* step //' | sort -n | tail -1)"
    else
      mode=$(sed -n "s/^mode *//p; s/^$task: *mode *//p" "formal/$job/$job.sby" | head -1)
      depth="$([ "$mode" = prove ] && echo k || echo bmc)=$(sed -n "s/^depth *//p; s/^$task: *depth *//p" "formal/$job/$job.sby" | head -1)"
    fi
    echo "$job $task PASS ${secs}s $depth"
  else
    res=FAIL; fails=$((fails + 1))
    step=$(grep -o 'failed assertion .* step [0-9]*' "$log" 2>/dev/null | sed 's/.* step //' | head -1)
    why=$(grep -o 'DONE ([A-Z]*' "$log" 2>/dev/null | sed 's/DONE (//' | tail -1)
    [ $rc -eq 124 ] && why=TIMEOUT
    trace=$(grep -o 'counterexample trace[^:]*: .*\.vcd\|cover trace: .*\.vcd' "$log" 2>/dev/null | sed 's/.*: //' | head -1)
    echo "$job $task FAIL ${secs}s ${step:+step $step }(${why:-ERROR}) log: $log${trace:+ trace: $dir/${trace#*${job}_$task/}}"
    grep -o 'failed assertion .*\|unreached cover statement .*' "$log" 2>/dev/null | head -3 | sed 's/^/    /'
  fi
done
[ $fails -eq 0 ] || { echo "formal-run: $fails task(s) failed (rerun: scripts/formal-run.sh JOB:TASK)"; exit 1; }
