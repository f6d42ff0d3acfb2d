#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The AXI4 wrapper with 8 PREUs against the C model: `pree cosim --axi`
# (build/pree-cosim-axi-p8; two photons a beat, PhotonsPerCycle 2, into its pree_top's wide
# intake) on cornell3 32x24 / 3000 photons, with random back-pressure and gaps on every
# stream and AXI4-Lite channel (--gap 0.3) and without: 0 differing words in the final hit-point
# memory and the image, and the RTL's operation counts equal to those sent ("pass").
# `make sim-axi-wide` (outside `make test`: the 8-PREU wrapper model takes about 15 minutes to build).
source "$(dirname "$0")/../../tests/lib/check.sh"
cd "$ROOT"
for p in 8; do
  [ -x build/pree-cosim-axi-p$p ] || fail "build/pree-cosim-axi-p$p missing (make build/pree-cosim-axi-p$p)"
  for opts in "--gap 0.3" "--gap 0"; do
    j="$TMP/axi$p.json"
    run "$PREE" cosim scenes/cornell3 --width 32 --height 24 --photons 3000 --preu $p --axi $opts \
      --quiet --no-reference --stats "$j"
    expect_eq "axi, $p PREUs ($opts)" "$(json "$j" axi)" True
    expect_eq "hit-point words differing, $p PREUs ($opts)" "$(json "$j" hp_words_differing)" 0
    expect_eq "image words differing, $p PREUs ($opts)" "$(json "$j" image_words_differing)" 0
    expect_eq "pass, $p PREUs ($opts)" "$(json "$j" pass)" True
    echo "   $p PREUs ($opts): update cycles $(json "$j" update.cycles), utilization $(json "$j" update.preu_utilization)"
  done
done
