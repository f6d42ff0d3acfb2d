#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Co-simulation of cornell3 at 64x48 / 20k photons through the Verilated pree_top with 4, 8 and
# 16 PREUs (paper datapath) and 4 PREUs (stable datapath, alpha 0.7 and 0.5): the final
# hit-point memory and the image must match the fp32 model word for word. The 8- and 16-PREU
# builds take 2 and 4 photons a cycle (the wide intake; the JSON's photons_per_cycle), must
# reach MIN_UTIL_8 / MIN_UTIL_16 update-pass utilization (8: measured 0.984995, 34,981 cycles;
# 16: the cycle model predicts 0.992114, 17,365 cycles, and the RTL adds the cycles of the
# load port's lead; the 4-PREU floor is cosim_schedule.sh's), and the scheduler's cycle model
# must predict their hazard, same-key and bank-conflict counts exactly (its starved count
# differs by the cycles before the first photon).
# cost: 31 (its seconds in a serial run; the runner starts costly checks first)
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
mkdir -p build/cosim
fail=0
MIN_UTIL_8=0.98
MIN_UTIL_16=0.98
for cfg in "4" "8" "16" "4 --datapath stable" "4 --datapath stable --alpha 0.5"; do
  tag=$(echo "$cfg" | tr -d ' -' | tr . _)
  p=${cfg%% *}
  j=build/cosim/check_small_$tag.json
  cmd="build/pree cosim scenes/cornell3 --width 64 --height 48 --photons 20000 --preu $cfg --quiet --no-reference --stats $j"
  if ! $cmd; then echo "FAIL: $cmd"; fail=1; continue; fi
  hp=$(json "$j" hp_words_differing); img=$(json "$j" image_words_differing); pass=$(json "$j" pass)
  echo "--preu $cfg: hp_words_differing $hp, image_words_differing $img, utilization $(json "$j" update.preu_utilization)"
  if [ "$hp" != 0 ] || [ "$img" != 0 ] || [ "$pass" != True ]; then
    echo "FAIL: differing words with --preu $cfg; reproduce: $cmd"; fail=1
  fi
  if [ "$cfg" = 8 ] || [ "$cfg" = 16 ]; then
    min=MIN_UTIL_$p
    if ! python3 - "$j" "$p" "${!min}" <<'EOF'
import sys
sys.path.insert(0, "tests/lib")
from cosim_report import load, utilization_at_least, model_predicts, finish
d = load(sys.argv[1])
p, min_util = int(sys.argv[2]), float(sys.argv[3])
u, s = d["update"], d["schedule"]
bad = []
if d["photons_per_cycle"] != p // 4:
    bad.append("photons_per_cycle %d, expected %d" % (d["photons_per_cycle"], p // 4))
utilization_at_least(d, min_util, bad)
model_predicts(d, bad)
print("  %d cycles, stalls %s; model %d cycles, stalls %s" % (u["cycles"], u["short_cycles_by_cause"],
      s["model_cycles"], s["model_short_cycles_by_cause"]))
finish(bad)
EOF
    then echo "FAIL (--preu $cfg, wide intake); reproduce: $cmd"; fail=1; fi
  fi
done
exit $fail
