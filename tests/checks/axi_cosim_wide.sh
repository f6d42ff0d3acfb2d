#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The AXI4 wrapper's wide photon intake against the C model: `pree cosim --axi` through the quick
# builds of pree_axi (build/axi/quick/pree-cosim-axi-<tag>, g++ -O0; mk/cosim_axi.mk) on cornell3
# 32x24: 8 PREUs with 2 photons a beat (p8), 3000 photons, scheduled, and with random
# back-pressure and gaps on every stream and AXI4-Lite channel (--gap 0.3); 16 PREUs with
# PipeFast 1 and 4 photons a beat (p16f), 1000 photons, scheduled. Each: 0 differing words in the
# final hit-point memory and the image, and the RTL's operation counts equal to those sent
# ("pass"). Without gaps the wrapper must keep pree_top's pace: at most 2% more update cycles
# than the host scheduler's cycle model of pree_top alone predicts for the same stream (p8: 5,253
# against 5,178, pree_top alone's RTL 5,241; one photon a beat needs a cycle a photon hit, 7,859).
# cost: 90 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
scene=(scenes/cornell3 --width 32 --height 24)
for run in "p8:--preu 8 --photons 3000:0" "p8:--preu 8 --photons 3000:0.3" "p16f:--preu 16 --pipe-fast --photons 1000:0"; do
  IFS=: read -r tag opts gap <<<"$run"
  prog=build/axi/quick/pree-cosim-axi-$tag
  [ -x "$prog" ] || fail "$prog missing (make $prog)"
  j="$TMP/$tag-$gap.json"
  run "$prog" "${scene[@]}" $opts --axi --gap "$gap" --quiet --no-reference --stats "$j"
  what="$tag --gap $gap"
  expect_eq "$what: axi" "$(json "$j" axi)" True
  expect_eq "$what: hit-point words differing" "$(json "$j" hp_words_differing)" 0
  expect_eq "$what: image words differing" "$(json "$j" image_words_differing)" 0
  expect_eq "$what: pass" "$(json "$j" pass)" True
  c=$(json "$j" update.cycles); m=$(json "$j" schedule.model_cycles)
  echo "   $what: update cycles $c (pree_top's cycle model $m), utilization $(json "$j" update.preu_utilization)"
  if [ "$gap" = 0 ]; then
    [ $((c * 100)) -le $((m * 102)) ] || fail "$what: $c update cycles, more than 2% above pree_top's $m"
  fi
done
echo "ok: the wide intake through the wrapper, 8 and 16 PREUs (PipeFast 1), 0 differing words, pree_top's pace"
