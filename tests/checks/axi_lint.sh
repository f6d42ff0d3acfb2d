#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The integration kit's filelist and the AXI4 wrapper: rtl/pree.f names every rtl/*.v once;
# verilator --lint-only -Wall of pree_axi through it (NumPreu 1, 2, 4, 8, 16 and both datapaths, which
# is also pree_top's lint in its paper configuration, see top_lint.sh; the wrapper bench's narrow
# counts; 2, 4 and 8 photons a beat; PipeFast 1 and unit stages; out-of-range parameters refused by
# name); Icarus (-g2005) elaborates pree_axi and pree_reset_sync through it.
# cost: 70 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
listed=$(grep -v '^//' rtl/pree.f | sort)
present=$(ls rtl/*.v | sort)
[ "$listed" = "$present" ] || fail "rtl/pree.f and rtl/*.v differ: $(diff <(echo "$listed") <(echo "$present") | grep '^[<>]' | tr '\n' ' ')"
echo "ok: rtl/pree.f lists the $(echo "$listed" | wc -l) files of rtl/"
for d in 0 1; do
  for p in 1 2 4 8 16; do
    run verilator --lint-only -Wall -Irtl --top-module pree_axi -GNumPreu=$p -GDatapath=$d -f rtl/pree.f
  done
done
# The narrowest running counts the wrapper bench uses (tests/checks/axi_wrap.sh), with one photon
# a beat and with two.
run verilator --lint-only -Wall -Irtl --top-module pree_axi -GNumPreu=2 -GHpAW=6 -GHpBankW=2 \
  -GIdxAW=4 -GPxAW=4 -GPxBankW=2 -GCntW=8 -GPhFifoAW=1 -GCountW=6 -f rtl/pree.f
run verilator --lint-only -Wall -Irtl --top-module pree_axi -GNumPreu=2 -GHpAW=6 -GHpBankW=2 \
  -GIdxAW=4 -GPxAW=4 -GPxBankW=2 -GCntW=8 -GPhFifoAW=1 -GCountW=7 -GPhotonsPerCycle=2 -f rtl/pree.f
# The wide photon intake as the co-simulation builds it (NumPreu / 4 photons a beat), and 8 a beat.
run verilator --lint-only -Wall -Irtl --top-module pree_axi -GNumPreu=8 -GPhotonsPerCycle=2 -f rtl/pree.f
run verilator --lint-only -Wall -Irtl --top-module pree_axi -GNumPreu=16 -GPhotonsPerCycle=4 -GPipeFast=1 -f rtl/pree.f
run verilator --lint-only -Wall -Irtl --top-module pree_axi -GNumPreu=16 -GPhotonsPerCycle=8 -GDatapath=1 -f rtl/pree.f
# The deep PREU pipeline and per-unit stages through the wrapper (pree_top alone at PipeFast 1 and
# its default stages: top_lint.sh).
run verilator --lint-only -Wall -Irtl --top-module pree_axi -GPipeFast=1 -GDivStages=18 -GAddStages=3 -f rtl/pree.f
# A combination out of range stops elaboration with a module named after the problem.
# pree_top's parameters are refused by pree_top (pree_top_*), the wrapper's own by the wrapper.
for bad in "DivStages=1:pree_top_divstages_is_0_or_2_to_31" "PipeFast=2:pree_top_pipefast_is_0_or_1" \
           "HpBankW=10:pree_top_hpbankw_is_1_to_half_of_hpaw" "PhotonsPerCycle=9:pree_axi_photons_per_cycle_is_1_to_8" \
           "RingAW=1:pree_axi_ring_holds_more_than_twice_photons_per_cycle"; do
  if verilator --lint-only -Wall -Irtl --top-module pree_axi -G${bad%%:*} -f rtl/pree.f >"$TMP/bad.log" 2>&1; then
    fail "pree_axi elaborated with ${bad%%:*}"
  fi
  grep -q "${bad#*:}" "$TMP/bad.log" || fail "pree_axi with ${bad%%:*}: no message naming ${bad#*:}: $(head -2 "$TMP/bad.log")"
done
echo "ok: out-of-range parameters stop elaboration with a named module"
run iverilog -g2005 -Wall -Irtl -o "$TMP/axi.vvp" -s pree_axi -c rtl/pree.f
run iverilog -g2005 -Irtl -o "$TMP/rs.vvp" -s pree_reset_sync -c rtl/pree.f
echo "ok: pree_axi lint-clean and elaborated"
