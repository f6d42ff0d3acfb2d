#!/usr/bin/env bash
# The deep configuration (PipeFast = 1: 45-stage update, 59-stage radiance pipelines, docs/fpga.md)
# co-simulated: cornell3 64x48 / 20k photons through the Verilated pree_top with 4 PREUs, paper
# datapath, scheduled. The hit-point memory and the image must match the fp32 model word for word
# (the image only when the model adds in the order of ADISO-REC's depth 59), the scheduler's cycle
# model must predict the RTL's hazard, same-key and bank-conflict counts exactly, and the update
# hazard window must be PipeFast 1's (46). Measured (spatial layout, 64 x NumPreu lead): 69,251
# update cycles, utilization 0.99511, hazard stalls 169, bank 6 (pixel layout, 64-photon queue:
# 69,283, 0.99465, 161; PipeFast 0, cosim_schedule.sh: 68,999 cycles, 0.99874, 2).
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
import json, sys
d = json.load(open(sys.argv[1]))
u, s = d["update"], d["schedule"]
bad = []
if d["hp_words_differing"] != 0 or d["image_words_differing"] != 0 or not d["pass"]:
    bad.append("hit-point words differing %d, image words differing %d"
               % (d["hp_words_differing"], d["image_words_differing"]))
if d["pipe_fast"] != 1 or d["update_window"] != 46:
    bad.append("pipe_fast %d, update window %d (expected 1, 46)" % (d["pipe_fast"], d["update_window"]))
if u["preu_utilization"] < float(sys.argv[2]):
    bad.append("utilization %.6f below %s" % (u["preu_utilization"], sys.argv[2]))
for k in ("hazard_in_flight", "same_key_in_lanes", "bank_conflict_b", "bank_conflict_a"):
    if s["model_short_cycles_by_cause"][k] != u["short_cycles_by_cause"][k]:
        bad.append("model %s %d, RTL %d" % (k, s["model_short_cycles_by_cause"][k], u["short_cycles_by_cause"][k]))
print("PipeFast 1: %d update cycles, utilization %.6f, stalls %s" % (u["cycles"], u["preu_utilization"],
      u["short_cycles_by_cause"]))
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
EOF
