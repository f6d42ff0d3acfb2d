#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# The co-simulation host's photon scheduler (host/cosim_sched.c): cornell3 64x48 / 20k
# photons through the Verilated pree_top with 4 PREUs, scheduled (the default), in photon order
# (--no-schedule), and scheduled with the hit points in the eye pass's order (--layout pixel;
# docs/pree_top.md, "Hit-point layout"). All must match the fp32 model word for word (hit points and image). The
# scheduled run must move photons, reach at least MIN_UTIL PREU utilization in update mode
# (measured with the spatial layout, the default: 0.998743 = 275649 operations in 68999 cycles,
# no bank conflict; --layout pixel: 0.998482, 69017 cycles, 20 bank conflicts; the loss is the
# start-up, while the load port builds its lead), and the scheduler's cycle model must predict the RTL's stalls
# exactly: the same hazard, same-key and bank-conflict counts (its starved count differs only by
# the cycles before the first photon and after the last issue). Both scheduled runs must do so, and
# the default spatial layout must have no more bank conflicts than the pixel layout.
set -u
cd "$(dirname "$0")/../.."
pree=${BUILD:-build}/pree
dir=${BUILD:-build}/cosim
mkdir -p "$dir"
MIN_UTIL=0.996
fail=0
base="scenes/cornell3 --width 64 --height 48 --photons 20000 --preu 4 --quiet --no-reference"
for mode in schedule order pixel; do
  j=$dir/check_schedule_$mode.json
  extra=""; [ $mode = order ] && extra="--no-schedule"
  [ $mode = pixel ] && extra="--layout pixel"
  cmd="$pree cosim $base $extra --stats $j"
  if ! $cmd; then echo "FAIL: $cmd"; fail=1; continue; fi
  if ! python3 - "$j" "$mode" "$MIN_UTIL" <<'EOF'
import sys
sys.path.insert(0, "tests/lib")
from cosim_report import load, words_match, utilization_at_least, model_predicts, finish
path, mode, min_util = sys.argv[1], sys.argv[2], float(sys.argv[3])
d = load(path)
u = d["update"]
bad = []
words_match(d, bad)
print("%s: %d operations in %d cycles, utilization %.6f, stalls %s" %
      (mode, u["operations"], u["cycles"], u["preu_utilization"], u["short_cycles_by_cause"]))
want_layout = "pixel" if mode == "pixel" else "spatial"
if d.get("hp_layout") != want_layout:
    bad.append("hp_layout %r, expected %r" % (d.get("hp_layout"), want_layout))
if mode != "order":
    s = d["schedule"]
    print("  photons moved %d of %d; model: %d cycles, stalls %s" %
          (s["photons_moved"], s["photons"], s["model_cycles"], s["model_short_cycles_by_cause"]))
    utilization_at_least(d, min_util, bad)
    if s["photons_moved"] == 0:
        bad.append("no photon moved")
    model_predicts(d, bad)
elif d["schedule"] is not None:
    bad.append("--no-schedule still scheduled")
finish(bad)
EOF
  then echo "FAIL ($mode); reproduce: $cmd"; fail=1; fi
done
# The spatial layout's purpose: fewer bank conflicts than the pixel layout's (0 against 20 measured).
if ! python3 - "$dir/check_schedule_schedule.json" "$dir/check_schedule_pixel.json" <<'EOF'
import json, sys
sp, px = (json.load(open(p))["update"]["short_cycles_by_cause"]["bank_conflict_b"] for p in sys.argv[1:3])
print("bank conflicts: spatial %d, pixel %d" % (sp, px))
sys.exit(0 if sp <= px else 1)
EOF
then echo "FAIL: the spatial layout has more bank conflicts than the pixel layout"; fail=1; fi
# A bad --layout is a usage error (exit 2) that names the value.
msg=$($pree cosim scenes/cornell3 --layout hilbert 2>&1); st=$?
if [ $st -ne 2 ] || ! grep -q "'hilbert' is not spatial or pixel" <<<"$msg"; then
  echo "FAIL: --layout hilbert: exit $st, message: $msg"; fail=1
fi
exit $fail
