#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# The AXI4 wrapper against the C model: `pree cosim --axi` (build/pree-cosim-axi-p4: pree_drv on
# the Verilated rtl/pree_axi.v) on cornell3 32x24 / 3000 photons, 4 PREUs:
#   - random back-pressure and gaps on every stream and AXI4-Lite channel (--gap 0.3, random
#     candidate counts and lanes per beat), scheduled order;
#   - no gaps, photon order (--no-schedule);
# each with 0 differing words in the final hit-point memory and the image, and the RTL's operation
# counts equal to those sent ("pass"). The AXI program refuses to run without --axi.
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
[ -x build/pree-cosim-axi-p4 ] || fail "build/pree-cosim-axi-p4 missing (make build/pree-cosim-axi-p4)"
for opts in "--gap 0.3" "--no-schedule"; do
  j="$TMP/axi.json"
  run "$PREE" cosim scenes/cornell3 --width 32 --height 24 --photons 3000 --preu 4 --axi $opts \
    --quiet --no-reference --stats "$j"
  expect_eq "axi ($opts)" "$(json "$j" axi)" True
  expect_eq "hit-point words differing ($opts)" "$(json "$j" hp_words_differing)" 0
  expect_eq "image words differing ($opts)" "$(json "$j" image_words_differing)" 0
  expect_eq "pass ($opts)" "$(json "$j" pass)" True
  echo "   update cycles $(json "$j" update.cycles), utilization $(json "$j" update.preu_utilization)"
done
if build/pree-cosim-axi-p4 scenes/cornell3 --width 16 --height 16 --photons 10 --quiet 2>"$TMP/err"; then
  fail "build/pree-cosim-axi-p4 ran without --axi"
fi
grep -q "give --axi" "$TMP/err" || fail "no usage message without --axi: $(cat "$TMP/err")"
echo "ok: the AXI program refuses to run without --axi"
