#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Waveforms that open where the action is: a traced co-simulation (cornell3 32x24, 2,000 photons,
# 4 PREUs) has an 8 ns clock in picoseconds (the paper's 125 MHz), and scripts/wave-view.py's
# cycle counts, read from the trace alone, equal the co-simulation's own counters (photons
# streamed, hazard stalls, bank conflicts in stages B and A); the save file starts 4 cycles before
# the first photon, with the primary marker on it and markers A-C on the first stalls listed.
# Usage: tests/checks/wave_view.sh   (needs build/pree-cosim-p4)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
[ -x build/pree-cosim-p4 ] || fail "build/pree-cosim-p4 not built (make build/pree-cosim-p4)"
command -v fst2vcd >/dev/null || fail "fst2vcd missing (Debian gtkwave)"
run "$PREE" cosim scenes/cornell3 --width 32 --height 24 --photons 2000 --quiet --no-reference \
    --trace "$TMP/w.fst" --stats "$TMP/w.json"
run python3 scripts/wave-view.py "$TMP/w.fst" tb/cosim/pree_top.gtkw "$TMP/w.gtkw"
cat "$TMP/w.cycles.txt"
# The clock: rising edges 8000 ps apart, in a 1 ps time unit.
read -r unit e1 e2 < <(fst2vcd "$TMP/w.fst" 2>/dev/null | awk '
  /^\$timescale/ { getline; u = $1 } /^\$var/ && $5 == "clk_i" && !id { id = $4 }
  /^#/ { t = substr($0, 2) } $0 == "1" id && id { e[n++] = t; if (n == 2) { print u, e[0], e[1]; exit } }')
expect_eq "trace time unit" "$unit" "1ps"
expect_eq "clock period (ps)" "$((e2 - e1))" "8000"
count() { sed -n "s/^  $1 .*(\([0-9]*\) cycles in all)$/\1/p" "$TMP/w.cycles.txt"; }
sum() { python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(sum(d[p]["short_cycles_by_cause"][sys.argv[2]] for p in ("update","radiance")))' "$TMP/w.json" "$1"; }
expect_eq "photons accepted in the trace = photon hits streamed" "$(count 'first photon accepted')" "$(json "$TMP/w.json" photon_hits_streamed)"
expect_eq "hazard stall cycles = the counters'" "$(count 'first hazard stall')" "$(sum hazard_in_flight)"
expect_eq "stage B bank conflict cycles = the counters'" "$(count 'first bank conflict (stage B)')" "$(sum bank_conflict_b)"
expect_eq "stage A bank conflict cycles = the counters'" "$(count 'first bank conflict (stage A lanes)')" "$(sum bank_conflict_a)"
# The view: timestart 4 cycles before the first photon, markers at the listed times.
ns() { sed -n "s/^  $1 *cycle [0-9]*, \([0-9]*\) ns.*/\1/p" "$TMP/w.cycles.txt"; }
photon=$(ns 'first photon accepted'); haz=$(ns 'first hazard stall'); bank=$(ns 'first bank conflict (stage B)')
[ -n "$photon" ] && [ "$photon" -gt 0 ] || fail "no first photon after time 0"
expect_eq "view start (ps)" "$(sed -n 's/^\[timestart\] //p' "$TMP/w.gtkw")" "$((photon * 1000 - 32000))"
expect_eq "markers (ps)" "$(sed -n 's/^\*-[0-9.]* \([0-9-]*\) \([0-9-]*\) \([0-9-]*\) .*/\1 \2 \3/p' "$TMP/w.gtkw")" \
  "$((photon * 1000)) $((haz * 1000)) $((bank * 1000))"
grep -qx "\[dumpfile\] \"$TMP/w.fst\"" "$TMP/w.gtkw" || fail "the save file does not name the trace"
echo "wave_view: ok"
