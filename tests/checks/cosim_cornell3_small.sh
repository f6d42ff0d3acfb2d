#!/usr/bin/env bash
# Co-simulation of cornell3 at 64x48 / 20k photons through the Verilated pree_top with 4, 8 and
# 16 PREUs (paper datapath) and 4 PREUs (stable datapath, alpha 0.7 and 0.5): the final
# hit-point memory and the image must match the fp32 model word for word.
. "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
mkdir -p build/cosim
fail=0
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
done
exit $fail
