#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# postroute_sdf_run.sh: the timing-annotated runs of a routed netlist (docs/fpga_board.md,
# "Timing-annotated run"; make sim-postroute-sdf, tests/checks/postroute_sdf.sh): Icarus replays
# a recorded UART exchange (tb/postroute/postroute_replay_tb.v, compiled into <vvp>) for <cycles>
# cycles and compares ftdi_rxd with the record:
#   1. without SDF (the netlist's function; zero delays make the period irrelevant): must match;
#   2. with <sdf> at the critical path of nextpnr's <report.json> (its Fmax; or PERIOD_PS): must
#      match, with no SDF warning from vvp;
#   3. with <sdf> at SHORT_PS (default half the critical path): must differ (the delays bite).
# Each run's verdict, and its wall and CPU seconds; exit 1 unless all three go as they must.
#   postroute_sdf_run.sh <vvp> <record prefix: .txd, .rxd> <cycles> <report.json> <sdf>
set -uo pipefail
[ $# = 5 ] || { echo "usage: postroute_sdf_run.sh <vvp> <record prefix> <cycles> <report.json> <sdf>" >&2; exit 2; }
vvp_file=$1 rec=$2 cycles=$3 report=$4 sdf=$5
for f in "$vvp_file" "$rec.txd" "$rec.rxd" "$report" "$sdf"; do
  [ -f "$f" ] || { echo "postroute_sdf_run: $f: no such file" >&2; exit 2; }
done
crit=$(python3 -c "import json, math, sys
f = json.load(open(sys.argv[1])).get('fmax', {})
print(math.ceil(1e6 / min(c['achieved'] for c in f.values())) if f else '')" "$report") || crit=""
[ -n "$crit" ] || { echo "postroute_sdf_run: $report: no Fmax" >&2; exit 2; }
period=${PERIOD_PS:-$crit}
short=${SHORT_PS:-$((crit / 2))}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
replay() {   # <what> <period ps> [plusargs...]: prints the verdict and any SDF warning count
  /usr/bin/time -f "%e %U %S" -o "$log.time" vvp -n "$vvp_file" +txd="$rec.txd" +rxd="$rec.rxd" +cycles="$cycles" \
    +period="$2" "${@:3}" -sdf-warn > "$log" 2>&1
  verdict=$(grep -E '^(PASS|FAIL)' "$log" | tail -1)
  warnings=$(grep -c 'SDF' "$log")
  read -r wall user sys < "$log.time"
  echo "$1: ${verdict:-no verdict (vvp: $(tail -1 "$log"))}; $warnings SDF messages; wall $wall s, CPU $user + $sys s"
  rm -f "$log.time"
}
ok=1
r=$(replay "without SDF" "$period"); echo "$r"
case $r in *": PASS"*) ;; *) ok=0 ;; esac
r=$(replay "with SDF at $period ps (critical path $crit ps)" "$period" +sdf="$sdf"); echo "$r"
case $r in *": PASS"*"; 0 SDF messages"*) ;; *) ok=0 ;; esac
r=$(replay "with SDF at $short ps (must differ)" "$short" +sdf="$sdf"); echo "$r"
case $r in *": FAIL"*) ;; *) ok=0; echo "postroute_sdf_run: at $short ps the annotated netlist matched: the delays do not bite" ;; esac
[ $ok = 1 ]
