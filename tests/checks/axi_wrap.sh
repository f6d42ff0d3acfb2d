#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The AXI4 wrapper through the wrap-around of its running counts (tb/axi/axi_wrap_tb.v, Icarus):
# two pree_axi with the real pree_top, one with the wide intake (2 photon slots a beat, some left
# empty; beats whose candidates exceed the 16-entry index table) and CountW 7, one with a photon
# a beat and CountW 32, the same 200 photons in batches of 128 (each drained), 932 candidates,
# random back-pressure: no stall, the counts read modulo 2^CountW, the same hit points and pixels
# bit for bit, no X. Then the same bench on a copy of the RTL whose
# wrapper takes a photon-done count of 0 for "nothing retired" (the deadlock this guards
# against) must stall.
# cost: 70 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
tb="tb/axi/axi_wrap_drv.v tb/axi/axi_wrap_tb.v"
run iverilog -g2005 -Irtl -o "$TMP/wrap.vvp" -s axi_wrap_tb -c rtl/pree.f $tb
echo "+ vvp -N $TMP/wrap.vvp"
vvp -N "$TMP/wrap.vvp" >"$TMP/wrap.log" 2>&1 || { tail -5 "$TMP/wrap.log"; fail "axi_wrap_tb failed: vvp -N $TMP/wrap.vvp"; }
grep "axi_wrap_tb: PASS" "$TMP/wrap.log" || fail "axi_wrap_tb: no PASS line: $(tail -3 "$TMP/wrap.log")"
# The mutant: ret_q from photons_done_o's value (0 after the wrap) instead of its moves.
mkdir "$TMP/rtl"
cp rtl/*.v rtl/*.vh "$TMP/rtl/"
old='      if (core_done != done_q) ret_q <= ring_q[last_done];'
new="      ret_q <= (core_done == {CountW{1'b0}}) ? {CountW{1'b0}} : ring_q[last_done];"
grep -qF "$old" rtl/pree_axi.v || fail "rtl/pree_axi.v: the line the mutant replaces is gone (update this check)"
python3 -c 'import sys; p=sys.argv[1]; s=open(p).read(); open(p,"w").write(s.replace(sys.argv[2], sys.argv[3]))' \
  "$TMP/rtl/pree_axi.v" "$old" "$new"
sed "s#^rtl/#$TMP/rtl/#" rtl/pree.f > "$TMP/mut.f"
run iverilog -g2005 -I"$TMP/rtl" -o "$TMP/mut.vvp" -s axi_wrap_tb -c "$TMP/mut.f" $tb
if vvp -N "$TMP/mut.vvp" >"$TMP/mut.log" 2>&1; then
  fail "axi_wrap_tb passed on the mutant wrapper (it cannot see the wrap-around deadlock)"
fi
grep -q "axi_wrap_drv 1: no interrupt" "$TMP/mut.log" || fail "the mutant failed otherwise: $(tail -3 "$TMP/mut.log")"
echo "ok: the mutant stalls: $(grep -m1 FATAL "$TMP/mut.log")"
