#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The deep configuration (PipeFast = 1: 48-stage update, 64-stage radiance pipelines, docs/fpga.md)
# co-simulated: cornell3 64x48 / 20k photons through the Verilated pree_top with 4 PREUs, paper
# datapath, scheduled. The hit-point memory and the image must match the fp32 model word for word
# (the image only when the model adds in the order of ADISO-REC's depth 64), the scheduler's cycle
# model must predict the RTL's hazard, same-key and bank-conflict counts exactly, and the update
# hazard window must be PipeFast 1's (49). Measured (spatial layout, 64 x NumPreu lead; the top's
# registered flow: A's two-offer buffer, B's two-slot queue): 69,323 update cycles, utilization
# 0.99407, hazard stalls 211, bank 6 (PipeFast 0, cosim_schedule.sh: 68,999 cycles, 0.99874, 2).
set -u
cd "$(dirname "$0")/../.."
pree=${BUILD:-build}/pree
dir=${BUILD:-build}/cosim
mkdir -p "$dir"
MIN_UTIL=0.99
j=$dir/check_deep.json
cmd="$pree cosim scenes/cornell3 --width 64 --height 48 --photons 20000 --preu 4 --pipe-fast --quiet --no-reference --stats $j"
if ! $cmd; then echo "FAIL: $cmd"; exit 1; fi
python3 - "$j" "$MIN_UTIL" <<'EOF' || { echo "FAIL; reproduce: $cmd"; exit 1; }
import sys
sys.path.insert(0, "tests/lib")
from cosim_report import load, words_match, utilization_at_least, model_predicts, finish
d = load(sys.argv[1])
u = d["update"]
bad = []
words_match(d, bad)
if d["pipe_fast"] != 1 or d["update_window"] != 49:
    bad.append("pipe_fast %d, update window %d (expected 1, 49)" % (d["pipe_fast"], d["update_window"]))
utilization_at_least(d, float(sys.argv[2]), bad)
model_predicts(d, bad)
print("PipeFast 1: %d update cycles, utilization %.6f, stalls %s" % (u["cycles"], u["preu_utilization"],
      u["short_cycles_by_cause"]))
finish(bad)
EOF
