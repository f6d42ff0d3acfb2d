#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# stress-hitpoint.sh: the single-hit-point part of the stress suite (make stress-hitpoint; issue 10,
# docs/numerics.md). Runs build/stress/stress_hitpoint for: the reference self-test; the main run
# (alpha 0.7, r2_0 = 1, constant flux 1, 1e9 accepts, both datapaths), the same with random flux;
# the stable datapath's count through 2^32 (2^32 + 1e6 real updates); sweeps of alpha (0.1 .. 1,
# 1e9 accepts), initial r2 (1e-40 .. 1e30) and flux (0, 1e-40, 1e30) (1e8 accepts); the
# non-finite input table; the stable r2 error split into its two biases (--decompose); N_emitted
# beyond 2^24 and 2^32. Writes OUTDIR/hp-LABEL.txt per run, every checkpoint to OUTDIR/hitpoint.csv,
# the sweep summary OUTDIR/sweeps.md, and the plots (scripts/stress-plots.sh), which the full level
# also copies to docs/images/numerics-*.png.
# Usage: scripts/stress-hitpoint.sh BIN OUTDIR [--quick|--summary]   (--quick: 1e5 accepts a run, to
# test the script in seconds, no copy to docs/images; --summary: only redo sweeps.md and the plots
# from an earlier run's files)
set -euo pipefail
bin=$1; out=$2; quick=${3:-}
cd "$(dirname "$0")/.."
mkdir -p "$out"
csv="$out/hitpoint.csv"
[ "$quick" = --summary ] || rm -f "$csv"
if [ "$quick" = --quick ]; then MAIN=1e5; ALPHA_N=1e5; SWEEP=1e5; COUNT=1e5; COUNT_AT=()
else MAIN=1e9; ALPHA_N=1e9; SWEEP=1e8; COUNT=$((4294967296 + 1000000)); COUNT_AT=(--at 16777216 --at 4294967295 --at 4294967296 --at 4294967297); fi

t0=$(date +%s)
[ "$quick" = --summary ] && [ ! -f "$csv.keep" ] && cp "$csv" "$csv.keep"
hp() {  # hp LABEL ARGS...: one run, its text output kept, its checkpoints appended to the CSV
  local label=$1; shift
  echo "stress-hitpoint: $label: $bin $* --label $label --csv $csv" >&2
  "$bin" "$@" --label "$label" --csv "$csv" > "$out/hp-$label.txt"
  grep -E '^seconds' "$out/hp-$label.txt" | sed "s/^/  $label: /" >&2
}

if [ "$quick" != --summary ]; then
"$bin" --selftest | tee "$out/selftest.txt"
grep -q '^selftest passed' "$out/selftest.txt"
"$bin" --nonfinite > "$out/nonfinite.txt"
"$bin" --ne-table > "$out/ne.txt"
"$bin" --decompose $MAIN > "$out/decompose.txt"

# The main runs: checkpoints ten to a decade for the plots, plus 2^23-ish and 2^24 marks.
hp main --accepts $MAIN --per-decade 10 --at 16777216 --at 30000000
hp main-random --accepts $MAIN --flux-mode random --per-decade 10
# The stable datapath's 64-bit count through 2^32: every update real (no fast path).
hp stable-count --accepts $COUNT --datapaths stable --no-ld "${COUNT_AT[@]}"
for a in 0.1 0.3 0.5 0.7 0.9 1.0; do hp alpha-$a --alpha $a --accepts $ALPHA_N --per-decade 5; done
for r in 1e-40 1e-30 1e-20 1e-10 1 1e10 1e20 1e30; do hp r2-$r --r2 $r --accepts $SWEEP --per-decade 5; done
for f in 0 1e-40 1e30; do hp flux-$f --flux $f --accepts $SWEEP --per-decade 5; done
fi

python3 - "$out" > "$out/sweeps.md" <<'PY'
import csv, glob, os, re, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "hitpoint.csv"))))
def at(label, model, k):
    for r in rows:
        if r["label"] == label and r["model"] == model and int(r["accepts"]) == k:
            return r
    return None
def events(label):
    ev = {}
    for line in open(os.path.join(out, "hp-%s.txt" % label)):
        m = re.match(r"event (\w+)\s+(\w+)\s+first_unchanged=(\S+) last_changed=(\d+)", line)
        if m and m.group(3) == "never": m = None
        if m: ev[(m.group(1), m.group(2))] = (m.group(3), m.group(4))
        m = re.match(r"event stable k final=(\d+) .* w_saturated=(\d) T_saturated=(\d)", line)
        if m: ev[("stable", "sat")] = (m.group(2), m.group(3))
        m = re.match(r"event (\w+)\s+rejected=(\d+)", line)
        if m: ev[(m.group(1), "rej")] = m.group(2)
        m = re.match(r"extreme (\w+)\s+r2 min=(\S+) \(at \d+\) max=(\S+) ", line)
        if m: ev[(m.group(1), "ext")] = "%s .. %s" % (m.group(2), m.group(3))
        m = re.match(r"seconds (\S+)", line)
        if m: ev["sec"] = m.group(1)
    return ev
def e(r, key):
    if r is None: return "-"
    v = float(r[key])
    return "0" if v == 0 else "%+.2e" % v
labels = []
for r in rows:
    if r["label"] not in labels: labels.append(r["label"])
kmax = {l: max(int(r["accepts"]) for r in rows if r["label"] == l) for l in labels}
print("| run | model | accepts | r2 err @1e6 | r2 err @end | N err @end | tau err @end | L err @1e6 | L err @end | r2 word: first unchanged / last changed | N word: first unchanged / last changed | saturated w/T | rejected | r2 err, min .. max over all accepts |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
for l in labels:
    ev = events(l)
    for m in ("paper", "stable"):
        end = at(l, m, kmax[l])
        if end is None: continue
        mid = at(l, m, 1000000)
        word = "r2" if m == "paper" else "w"
        fl = lambda t: "never / every accept" if t is None else "%s / %s" % (format(int(t[0]), ","), format(int(t[1]), ","))
        stop = fl(ev.get((m, word)))
        nstop = fl(ev.get(("paper", "N"))) if m == "paper" else "exact k"
        sat = "/".join("yes" if s == "1" else "no" for s in ev.get(("stable", "sat"), ("-", "-"))) if m == "stable" else "-"
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            l, m, format(kmax[l], ","), e(mid, "err_r2_closed"), e(end, "err_r2_closed"), e(end, "err_n"),
            e(end, "err_tau_ld") if end and end["err_tau_ld"] != "nan" else e(end, "err_tau_double"),
            e(mid, "err_L_double"), e(end, "err_L_double"), stop, nstop, sat, ev.get((m, "rej"), "-"), ev.get((m, "ext"), "-")))
print()
print("Errors: relative, signed; r2 against the closed form, tau against the long-double recurrence (the")
print("stable-count run: against double), L (the radiance word) against smallppm's double with the exact N_emitted;")
print("the min .. max range against the long-double recurrence (stable-count: double) at every accept.")
PY
cat "$out/sweeps.md"
scripts/stress-plots.sh "$out"
if [ -z "$quick" ]; then
  mkdir -p docs/images
  cp "$out"/numerics-*.png docs/images/
  echo "stress-hitpoint: plots copied to docs/images/" >&2
fi
echo "stress-hitpoint: $(( $(date +%s) - t0 )) s; tables in $out" >&2
